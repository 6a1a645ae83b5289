#include "basis/bspline/rational_space.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "core/error.hpp"

namespace iga::basis::bspline {

RationalSpace::RationalSpace(std::shared_ptr<const TensorSpace> base, Eigen::VectorXd weights)
    : base_(std::move(base)), weights_(std::move(weights)) {
  if (!base_) throw InputError("NURBS space: no B-spline space");
  if (weights_.size() != base_->num_dofs()) {
    throw InputError("NURBS space: " + std::to_string(weights_.size()) + " weights for " +
                     std::to_string(base_->num_dofs()) + " control points");
  }
  for (Index i = 0; i < weights_.size(); ++i) {
    if (!(std::isfinite(weights_(i)) && weights_(i) > 0.0)) {
      throw InputError("NURBS space: weight " + std::to_string(i) + " is " + std::to_string(weights_(i)) +
                       " (weights must be finite and positive)");
    }
  }
}

// With A_i = w_i N_i and W = Σ A_i (so R_i = A_i / W):
//   R_u  = (A_u − R W_u) / W,
//   R_uu = (A_uu − 2 R_u W_u − R W_uu) / W,   R_uv = (A_uv − R_u W_v − R_v W_u − R W_uv) / W,
// and the same with u and v exchanged (differentiate A = R W).
void RationalSpace::evaluate(Index e, const Eigen::Matrix2Xd& pts, int derivatives, BasisValues& out) const {
  thread_local BasisValues nb;
  thread_local Eigen::VectorXd w;
  base_->evaluate(e, pts, derivatives, nb);
  const std::span<const Index> dofs = base_->dofs(e);
  const auto n = static_cast<Eigen::Index>(dofs.size());
  const Eigen::Index q = pts.cols();
  w.resize(n);
  for (Eigen::Index a = 0; a < n; ++a) w(a) = weights_(dofs[static_cast<std::size_t>(a)]);
  out.resize(n, q, derivatives);
  for (Eigen::Index k = 0; k < q; ++k) {
    const double inv = 1.0 / w.dot(nb.value.col(k));
    out.value.col(k) = inv * w.cwiseProduct(nb.value.col(k));
    if (derivatives < 1) continue;
    const double wu = w.dot(nb.du.col(k)), wv = w.dot(nb.dv.col(k));
    out.du.col(k) = inv * (w.cwiseProduct(nb.du.col(k)) - wu * out.value.col(k));
    out.dv.col(k) = inv * (w.cwiseProduct(nb.dv.col(k)) - wv * out.value.col(k));
    if (derivatives < 2) continue;
    const double wuu = w.dot(nb.duu.col(k)), wuv = w.dot(nb.duv.col(k)), wvv = w.dot(nb.dvv.col(k));
    out.duu.col(k) = inv * (w.cwiseProduct(nb.duu.col(k)) - 2.0 * wu * out.du.col(k) - wuu * out.value.col(k));
    out.dvv.col(k) = inv * (w.cwiseProduct(nb.dvv.col(k)) - 2.0 * wv * out.dv.col(k) - wvv * out.value.col(k));
    out.duv.col(k) = inv * (w.cwiseProduct(nb.duv.col(k)) - wv * out.du.col(k) - wu * out.dv.col(k) -
                            wuv * out.value.col(k));
  }
}

std::optional<RationalForm> RationalSpace::rational_form(Index e) const {
  RationalForm form;
  form.degree = std::max(base_->knots_u().degree(), base_->knots_v().degree());
  const std::span<const Index> dofs = base_->dofs(e);
  form.weights.resize(static_cast<Eigen::Index>(dofs.size()));
  for (std::size_t a = 0; a < dofs.size(); ++a) form.weights(static_cast<Eigen::Index>(a)) = weights_(dofs[a]);
  return form;
}

const RationalSpace* rational_space(const Space& space) { return dynamic_cast<const RationalSpace*>(&space); }

Geometry make_rational_patch(KnotVector u, KnotVector v, Eigen::MatrixXd control_points, Eigen::VectorXd weights) {
  auto base = std::make_shared<const TensorSpace>(std::move(u), std::move(v));
  return Geometry(std::make_shared<const RationalSpace>(std::move(base), std::move(weights)), std::move(control_points));
}

Geometry refine_rational(const Geometry& coarse, std::shared_ptr<const TensorSpace> fine_base,
                         const Eigen::SparseMatrix<double>& r, Eigen::SparseMatrix<double>* prolongation) {
  const RationalSpace* space = rational_space(coarse.space());
  if (!space) throw InputError("NURBS refinement: a '" + coarse.space().name() + "' space has no weights");
  if (r.rows() != fine_base->num_dofs() || r.cols() != space->num_dofs()) {
    throw InputError("NURBS refinement: the refinement matrix does not map the coarse onto the fine space");
  }
  const Eigen::VectorXd& wc = space->weights();
  Eigen::VectorXd wf = r * wc;
  const Eigen::VectorXd inv = wf.cwiseInverse();
  // Homogeneous control points (w P, w) refine linearly; project back.
  Eigen::MatrixXd cp = inv.asDiagonal() * (r * (wc.asDiagonal() * coarse.control_points()));
  *prolongation = inv.asDiagonal() * r * wc.asDiagonal();
  return Geometry(std::make_shared<const RationalSpace>(std::move(fine_base), std::move(wf)), std::move(cp));
}

}  // namespace iga::basis::bspline
