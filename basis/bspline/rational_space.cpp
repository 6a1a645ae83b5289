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
  base_->evaluate(e, pts, derivatives, nb);
  from_reference(e, nb, derivatives, out);
}

namespace {
// The quotient rule point by point: W = Σ w_i N_i and its derivatives as dot products of contiguous columns, then
// R = w∘N / W, R_u = (w∘N_u − W_u R) / W, R_uu = (w∘N_uu − 2 W_u R_u − W_uu R) / W, R_uv = (w∘N_uv − W_v R_u −
// W_u R_v − W_uv R) / W. N is the number of functions at compile time (bicubic: 16, unrolled) or Eigen::Dynamic.
template <int N>
void quotient_rule(const Eigen::VectorXd& weights, const BasisValues& nb, int derivatives, BasisValues& out) {
  using Column = Eigen::Matrix<double, N, 1>;
  const Eigen::Index n = weights.size();
  const Eigen::Map<const Column> w(weights.data(), n);
  auto in = [&](const Eigen::MatrixXd& block, Eigen::Index k) { return Eigen::Map<const Column>(&block(0, k), n); };
  auto to = [&](Eigen::MatrixXd& block, Eigen::Index k) { return Eigen::Map<Column>(&block(0, k), n); };
  for (Eigen::Index k = 0; k < nb.value.cols(); ++k) {
    const double inv = 1.0 / w.dot(in(nb.value, k));
    auto r = to(out.value, k);
    r = inv * w.cwiseProduct(in(nb.value, k));
    if (derivatives < 1) continue;
    const double wu = w.dot(in(nb.du, k)), wv = w.dot(in(nb.dv, k));
    auto ru = to(out.du, k), rv = to(out.dv, k);
    ru = inv * (w.cwiseProduct(in(nb.du, k)) - wu * r);
    rv = inv * (w.cwiseProduct(in(nb.dv, k)) - wv * r);
    if (derivatives < 2) continue;
    const double wuu = w.dot(in(nb.duu, k)), wuv = w.dot(in(nb.duv, k)), wvv = w.dot(in(nb.dvv, k));
    to(out.duu, k) = inv * (w.cwiseProduct(in(nb.duu, k)) - 2.0 * wu * ru - wuu * r);
    to(out.dvv, k) = inv * (w.cwiseProduct(in(nb.dvv, k)) - 2.0 * wv * rv - wvv * r);
    to(out.duv, k) = inv * (w.cwiseProduct(in(nb.duv, k)) - wv * ru - wu * rv - wuv * r);
  }
}
}  // namespace

void RationalSpace::from_reference(Index e, const BasisValues& nb, int derivatives, BasisValues& out) const {
  thread_local Eigen::VectorXd w;
  const std::span<const Index> dofs = base_->dofs(e);
  const auto n = static_cast<Eigen::Index>(dofs.size());
  w.resize(n);
  for (Eigen::Index a = 0; a < n; ++a) w(a) = weights_(dofs[static_cast<std::size_t>(a)]);
  out.resize(n, nb.value.cols(), derivatives);
  if (n == 16) {
    quotient_rule<16>(w, nb, derivatives, out);
  } else {
    quotient_rule<Eigen::Dynamic>(w, nb, derivatives, out);
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
