#include "basis/catmull_clark/ev_enrichment.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "core/error.hpp"

namespace iga::basis::catmull_clark {
namespace {

Eigen::Vector3d padded(const Eigen::MatrixXd& points, Index row) {
  Eigen::Vector3d p = Eigen::Vector3d::Zero();
  p.head(points.cols()) = points.row(row).transpose();
  return p;
}

// Distance from p to the axis-aligned box of the control points of `dofs` (the convex-hull property of the
// non-negative partition of unity puts the element's image inside it).
double box_distance(const Eigen::MatrixXd& points, std::span<const Index> dofs, const Eigen::Vector3d& p) {
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(1e300), hi = Eigen::Vector3d::Constant(-1e300);
  for (Index d : dofs) {
    const Eigen::Vector3d x = padded(points, d);
    lo = lo.cwiseMin(x);
    hi = hi.cwiseMax(x);
  }
  const Eigen::Vector3d gap = (lo - p).cwiseMax(p - hi).cwiseMax(0.0);
  return gap.norm();
}

// Value, physical gradient and Hessian of f_k = χ(|d|²/ρ²) q_k(Fᵀ d / ρ) at d = x − x_v, k = 0, 1, 2.
struct EnrichmentJet {
  double value[3];
  Eigen::Vector3d gradient[3];
  Eigen::Matrix3d hessian[3];
};

// False where the cutoff is zero (|d| >= ρ): all three functions and their derivatives vanish.
bool enrichment_jet(const EnrichmentCentre& c, const Eigen::Vector3d& d, bool second, EnrichmentJet& jet) {
  const double r2 = c.radius * c.radius;
  const double t = d.squaredNorm() / r2;
  if (t >= 1.0) return false;
  const double s = 1.0 - t;
  // χ(t) = (1 − t)⁸: C⁷ at t = 1. (With (1 − t)⁴, C³, Gauss rules converge so slowly across the circle
  // |x − x_v| = ρ that the linear patch test on square_evs.obj stalled at 8e-8 (tiles:4:12, 3 refinements);
  // with the 8th power: 1.4e-10.)
  const double s2 = s * s, s4 = s2 * s2, s6 = s4 * s2;
  const double chi = s4 * s4, chi_t = -8.0 * s6 * s, chi_tt = 56.0 * s6;
  const Eigen::Vector2d xi = c.frame.transpose() * d / c.radius;
  const double q[3] = {xi(0) * xi(0), xi(0) * xi(1), xi(1) * xi(1)};
  const Eigen::Vector2d dq[3] = {{2.0 * xi(0), 0.0}, {xi(1), xi(0)}, {0.0, 2.0 * xi(1)}};
  const Eigen::Vector3d g_chi = chi_t * 2.0 / r2 * d;
  Eigen::Matrix3d h_chi = Eigen::Matrix3d::Zero();
  if (second) h_chi = chi_tt * 4.0 / (r2 * r2) * d * d.transpose() + chi_t * 2.0 / r2 * Eigen::Matrix3d::Identity();
  for (int k = 0; k < 3; ++k) {
    const Eigen::Vector3d g_q = c.frame * dq[k] / c.radius;
    jet.value[k] = chi * q[k];
    jet.gradient[k] = q[k] * g_chi + chi * g_q;
    if (second) {
      Eigen::Matrix2d hq = Eigen::Matrix2d::Zero();
      if (k == 0) hq(0, 0) = 2.0;
      if (k == 1) hq(0, 1) = hq(1, 0) = 1.0;
      if (k == 2) hq(1, 1) = 2.0;
      jet.hessian[k] = q[k] * h_chi + g_chi * g_q.transpose() + g_q * g_chi.transpose() +
                       chi * c.frame * hq * c.frame.transpose() / r2;
    }
  }
  return true;
}

}  // namespace

bool enrichment_option(const std::string& word) {
  if (word.empty() || word == "none") return false;
  if (word == "quadratic") return true;
  throw InputError("--cc-enrich '" + word + "': expected none or quadratic");
}

EnrichedSpace::EnrichedSpace(std::shared_ptr<const Space> base, Eigen::MatrixXd base_points,
                             std::vector<EnrichmentCentre> centres)
    : base_(std::move(base)), base_points_(std::move(base_points)), centres_(std::move(centres)) {
  if (base_points_.rows() != base_->num_dofs() || (base_points_.cols() != 2 && base_points_.cols() != 3)) {
    throw InputError("enrichment: control points must be num_dofs × 2 or × 3");
  }
  for (const EnrichmentCentre& c : centres_) {
    if (!(c.radius > 0.0) || !std::isfinite(c.radius)) throw InputError("enrichment: a centre's radius must be positive");
  }
  slot_.assign(static_cast<std::size_t>(base_->num_elements()), -1);
  max_local_dofs_ = base_->max_local_dofs();
  for (Index e = 0; e < base_->num_elements(); ++e) {
    const std::span<const Index> d = base_->dofs(e);
    std::vector<int> near;
    for (std::size_t j = 0; j < centres_.size(); ++j) {
      if (box_distance(base_points_, d, centres_[j].point) < centres_[j].radius) near.push_back(static_cast<int>(j));
    }
    if (near.empty()) continue;
    slot_[static_cast<std::size_t>(e)] = static_cast<int>(local_.size());
    std::vector<Index> all(d.begin(), d.end());
    for (int j : near) {
      for (int k = 0; k < 3; ++k) all.push_back(base_->num_dofs() + 3 * j + k);
    }
    max_local_dofs_ = std::max(max_local_dofs_, static_cast<Index>(all.size()));
    local_.push_back(std::move(all));
    local_centres_.push_back(std::move(near));
  }
}

Index EnrichedSpace::num_enriched_elements() const { return static_cast<Index>(local_.size()); }

std::span<const Index> EnrichedSpace::dofs(Index e) const {
  const int s = slot_[static_cast<std::size_t>(e)];
  if (s < 0) return base_->dofs(e);
  return local_[static_cast<std::size_t>(s)];
}

std::optional<int> EnrichedSpace::polynomial_degree(Index e) const {
  if (slot_[static_cast<std::size_t>(e)] >= 0) return std::nullopt;
  return base_->polynomial_degree(e);
}

std::optional<SubdivisionElement> EnrichedSpace::subdivision_element(Index e) const {
  std::optional<SubdivisionElement> se = base_->subdivision_element(e);
  const int s = slot_[static_cast<std::size_t>(e)];
  if (!se || s < 0) return se;
  const Index extra = 3 * static_cast<Index>(local_centres_[static_cast<std::size_t>(s)].size());
  auto pad = [extra](Eigen::MatrixXd& m) {
    const Index c = m.cols();
    m.conservativeResize(Eigen::NoChange, c + extra);
    m.rightCols(extra).setZero();
  };
  pad(se->to_points);
  for (PatchTile& t : se->explicit_tiles) pad(t.points);
  return se;
}

void EnrichedSpace::evaluate(Index e, const Eigen::Matrix2Xd& pts, int derivatives, BasisValues& out) const {
  const int s = slot_[static_cast<std::size_t>(e)];
  if (s < 0) {
    base_->evaluate(e, pts, derivatives, out);
    return;
  }
  thread_local BasisValues b;
  thread_local Eigen::MatrixXd xl;
  thread_local Eigen::Matrix3Xd x, xu, xv, xuu, xuv, xvv;
  base_->evaluate(e, pts, derivatives, b);
  const std::span<const Index> d = base_->dofs(e);
  const Index nb = static_cast<Index>(d.size()), q = pts.cols();
  const std::vector<int>& near = local_centres_[static_cast<std::size_t>(s)];
  out.resize(nb + 3 * static_cast<Index>(near.size()), q, derivatives);
  BasisValues::for_each_block(b, out, derivatives, [nb](const Eigen::MatrixXd& from, Eigen::MatrixXd& to) {
    to.topRows(nb) = from;
  });
  xl.setZero(nb, 3);
  for (Index i = 0; i < nb; ++i) xl.row(i).head(base_points_.cols()) = base_points_.row(d[static_cast<std::size_t>(i)]);
  x.noalias() = xl.transpose() * b.value;
  if (derivatives >= 1) {
    xu.noalias() = xl.transpose() * b.du;
    xv.noalias() = xl.transpose() * b.dv;
  }
  if (derivatives >= 2) {
    xuu.noalias() = xl.transpose() * b.duu;
    xuv.noalias() = xl.transpose() * b.duv;
    xvv.noalias() = xl.transpose() * b.dvv;
  }
  EnrichmentJet jet;
  for (Index p = 0; p < q; ++p) {
    for (std::size_t r = 0; r < near.size(); ++r) {
      const Index row = nb + 3 * static_cast<Index>(r);
      const EnrichmentCentre& c = centres_[static_cast<std::size_t>(near[r])];
      if (!enrichment_jet(c, x.col(p) - c.point, derivatives >= 2, jet)) {
        for (int k = 0; k < 3; ++k) {
          out.value(row + k, p) = 0.0;
          if (derivatives >= 1) out.du(row + k, p) = out.dv(row + k, p) = 0.0;
          if (derivatives >= 2) out.duu(row + k, p) = out.duv(row + k, p) = out.dvv(row + k, p) = 0.0;
        }
        continue;
      }
      for (int k = 0; k < 3; ++k) {
        out.value(row + k, p) = jet.value[k];
        if (derivatives >= 1) {
          out.du(row + k, p) = jet.gradient[k].dot(xu.col(p));
          out.dv(row + k, p) = jet.gradient[k].dot(xv.col(p));
        }
        if (derivatives >= 2) {
          const Eigen::Matrix3d& h = jet.hessian[k];
          out.duu(row + k, p) = xu.col(p).dot(h * xu.col(p)) + jet.gradient[k].dot(xuu.col(p));
          out.duv(row + k, p) = xu.col(p).dot(h * xv.col(p)) + jet.gradient[k].dot(xuv.col(p));
          out.dvv(row + k, p) = xv.col(p).dot(h * xv.col(p)) + jet.gradient[k].dot(xvv.col(p));
        }
      }
    }
  }
}

namespace {

// The smallest distance from x to the domain's boundary, sampled at 9 points per boundary edge (+inf for a
// closed surface).
double boundary_distance(const Geometry& g, const Eigen::Vector3d& x) {
  const Space& space = g.space();
  double best = std::numeric_limits<double>::infinity();
  Eigen::Matrix2Xd pts(2, 9);
  GeometryValues gv;
  BasisValues bv;
  for (const BoundaryEdge& b : space.boundary_edges()) {
    for (int k = 0; k < 9; ++k) pts.col(k) = side_point(space.kind(b.element).shape, b.side, k / 8.0);
    space.evaluate(b.element, pts, 1, bv);
    g.evaluate(b.element, bv, gv, false);
    for (int k = 0; k < 9; ++k) best = std::min(best, (gv.x.col(k) - x).norm());
  }
  return best;
}

Eigen::Matrix<double, 3, 2> tangent_frame(const Eigen::Vector3d& normal) {
  const Eigen::Vector3d n = normal.normalized();
  Eigen::Index axis = 0;
  n.cwiseAbs().minCoeff(&axis);
  Eigen::Vector3d t1 = Eigen::Vector3d::Unit(axis) - n(axis) * n;
  t1.normalize();
  Eigen::Matrix<double, 3, 2> f;
  f.col(0) = t1;
  f.col(1) = n.cross(t1);
  return f;
}

}  // namespace

std::vector<EnrichmentCentre> extraordinary_centres(const Geometry& g) {
  const Space& space = g.space();
  if (dynamic_cast<const EnrichedSpace*>(&space)) throw InputError("enrichment: the geometry is enriched already");
  const Eigen::MatrixXd& cp = g.control_points();
  const double scale = (cp.colwise().maxCoeff() - cp.colwise().minCoeff()).norm();
  std::vector<EnrichmentCentre> centres;
  std::vector<Eigen::Vector3d> normals;
  Eigen::Matrix2Xd corners(2, 5);
  corners << 0, 1, 1, 0, 1e-4, 0, 0, 1, 1, 1e-4;
  GeometryValues gv;
  BasisValues bv;
  for (Index e = 0; e < space.num_elements(); ++e) {
    const ElementKind k = space.kind(e);
    if (k.family != Family::Irregular || k.shape != Shape::Quad) continue;
    // Interior valence 3 keeps full order without enrichment (L2 4.00, H1 2.79: test_cc_ev_rates), and there
    // the enrichment is nearly in the space: the stiffness is so close to singular that 4-point tile rules'
    // errors (1e-8 relative) cost the Galerkin solution a factor 8 in H1 (measured at level 4).
    if (!k.boundary && k.valence == 3) continue;
    space.evaluate(e, corners, 1, bv);
    g.evaluate(e, bv, gv, false);
    const Eigen::Vector3d x0 = gv.x.col(0);
    double ring = 0.0;
    for (int c = 1; c < 4; ++c) ring = std::max(ring, (gv.x.col(c) - x0).norm());
    std::size_t j = 0;
    while (j < centres.size() && (centres[j].point - x0).norm() > 1e-9 * scale) ++j;
    if (j == centres.size()) {
      centres.push_back({x0, 0.0, Eigen::Matrix<double, 3, 2>::Identity(), k.valence, k.boundary});
      normals.emplace_back(Eigen::Vector3d::Zero());
    }
    centres[j].radius = std::max(centres[j].radius, ring);
    normals[j] += gv.normal.col(4);
  }
  for (std::size_t j = 0; j < centres.size(); ++j) {
    EnrichmentCentre& c = centres[j];
    if (g.dim() == 3) c.frame = tangent_frame(normals[j]);
    // Interior EVs: the disc stays inside the domain, so the functions vanish on the boundary (Dirichlet
    // traces and boundary terms do not see them).
    if (!c.boundary) c.radius = std::min(c.radius, 0.99 * boundary_distance(g, c.point));
    if (!(c.radius > 1e-12 * scale)) {
      throw NumericalError("enrichment: the extraordinary vertex at (" + std::to_string(c.point(0)) + ", " +
                           std::to_string(c.point(1)) + ") has no room inside the domain for its enrichment disc");
    }
  }
  return centres;
}

Geometry enriched_geometry(const Geometry& base, std::vector<EnrichmentCentre> centres) {
  const Index m = 3 * static_cast<Index>(centres.size());
  auto space = std::make_shared<const EnrichedSpace>(base.space_ptr(), base.control_points(), std::move(centres));
  Eigen::MatrixXd cp = Eigen::MatrixXd::Zero(base.control_points().rows() + m, base.control_points().cols());
  cp.topRows(base.control_points().rows()) = base.control_points();
  return Geometry(std::move(space), std::move(cp));
}

}  // namespace iga::basis::catmull_clark
