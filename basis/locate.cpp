#include "basis/locate.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <limits>
#include <sstream>
#include <vector>

#include "core/error.hpp"

namespace iga::basis {

namespace {

constexpr int kSamples = 9;

Eigen::Vector2d clamp_to(Shape shape, Eigen::Vector2d uv) {
  uv = uv.cwiseMax(0.0).cwiseMin(1.0);
  if (shape == Shape::Triangle && uv.sum() > 1.0) {
    const double excess = 0.5 * (uv.sum() - 1.0);  // back onto the hypotenuse along its normal
    uv = (uv.array() - excess).cwiseMax(0.0).matrix();
    if (uv.sum() > 1.0) uv /= uv.sum();
  }
  return uv;
}

Eigen::Matrix2Xd sample_points(Shape shape) {
  std::vector<Eigen::Vector2d> pts;
  for (int j = 0; j < kSamples; ++j) {
    for (int i = 0; i < kSamples; ++i) {
      const Eigen::Vector2d uv(double(i) / (kSamples - 1), double(j) / (kSamples - 1));
      if (shape == Shape::Triangle && uv.sum() > 1.0 + 1e-12) continue;
      pts.push_back(uv);
    }
  }
  Eigen::Matrix2Xd out(2, static_cast<Index>(pts.size()));
  for (std::size_t k = 0; k < pts.size(); ++k) out.col(static_cast<Index>(k)) = pts[k];
  return out;
}

// Gauss–Newton for min |x(uv) − p| on element e from uv, kept in the reference domain.
LocatedPoint refine_on(const Geometry& g, Index e, Eigen::Vector2d uv, const Eigen::Vector3d& p) {
  const Shape shape = g.space().kind(e).shape;
  BasisValues bv;
  GeometryValues gv;
  Eigen::Matrix2Xd at(2, 1);
  LocatedPoint best;
  best.element = e;
  best.distance = std::numeric_limits<double>::infinity();
  for (int it = 0; it < 40; ++it) {
    at.col(0) = uv;
    g.space().evaluate(e, at, 1, bv);
    g.evaluate(e, bv, gv, false, 1);
    const Eigen::Vector3d r = gv.x.col(0) - p;
    if (r.norm() < best.distance) {
      best.distance = r.norm();
      best.uv = uv;
      best.x = gv.x.col(0);
    } else if (it > 0) {
      break;
    }
    Eigen::Matrix<double, 3, 2> j;
    j << gv.xu.col(0), gv.xv.col(0);
    const Eigen::Matrix2d n = j.transpose() * j;
    if (!(std::abs(n.determinant()) > 1e-14 * n.squaredNorm())) break;
    const Eigen::Vector2d next = clamp_to(shape, uv - n.ldlt().solve(j.transpose() * r));
    if ((next - uv).norm() < 1e-15) break;
    uv = next;
  }
  return best;
}

}  // namespace

LocatedPoint nearest_point(const Geometry& geometry, const Eigen::Vector3d& point) {
  const Space& space = geometry.space();
  struct Candidate {
    double distance;
    Index element;
    Eigen::Vector2d uv;
  };
  std::vector<Candidate> best;
  BasisValues bv;
  GeometryValues gv;
  const Eigen::Matrix2Xd quad = sample_points(Shape::Quad), tri = sample_points(Shape::Triangle);
  for (Index e = 0; e < space.num_elements(); ++e) {
    const Eigen::Matrix2Xd& pts = space.kind(e).shape == Shape::Triangle ? tri : quad;
    space.evaluate(e, pts, 0, bv);
    const Eigen::MatrixXd x = geometry.element_points(e).transpose() * bv.value;  // dim × q
    Candidate c{std::numeric_limits<double>::infinity(), e, Eigen::Vector2d::Zero()};
    for (Index k = 0; k < pts.cols(); ++k) {
      Eigen::Vector3d xk = Eigen::Vector3d::Zero();
      xk.head(x.rows()) = x.col(k);
      const double d = (xk - point).norm();
      if (d < c.distance) c = {d, e, pts.col(k)};
    }
    best.push_back(c);
  }
  if (best.empty()) throw InputError("nearest point: the geometry has no elements");
  const std::size_t keep = std::min<std::size_t>(4, best.size());
  std::partial_sort(best.begin(), best.begin() + static_cast<std::ptrdiff_t>(keep), best.end(),
                    [](const Candidate& a, const Candidate& b) { return a.distance < b.distance; });
  LocatedPoint out;
  out.distance = std::numeric_limits<double>::infinity();
  for (std::size_t k = 0; k < keep; ++k) {
    const LocatedPoint r = refine_on(geometry, best[k].element, best[k].uv, point);
    if (r.distance < out.distance) out = r;
  }
  return out;
}

LocatedPoint locate_point(const Geometry& geometry, const Eigen::Vector3d& point, const std::string& what,
                          double tolerance, double allowance) {
  const LocatedPoint r = nearest_point(geometry, point);
  const Eigen::MatrixXd& p = geometry.control_points();
  const double extent = (p.colwise().maxCoeff() - p.colwise().minCoeff()).norm();
  const double allowed = std::max(tolerance * extent, allowance);
  if (!(r.distance <= allowed)) {
    std::ostringstream msg;
    msg << what << ": (" << point(0) << ", " << point(1) << ", " << point(2)
        << ") is not on the surface: the nearest point of the geometry is (" << r.x(0) << ", " << r.x(1) << ", "
        << r.x(2) << ") at distance " << r.distance << ", more than the " << allowed << " allowed";
    throw InputError(msg.str());
  }
  return r;
}

}  // namespace iga::basis
