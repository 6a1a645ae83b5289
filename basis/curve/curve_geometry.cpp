#include "basis/curve/curve_geometry.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <numbers>
#include <string>

#include "core/error.hpp"

namespace iga::basis {

namespace {

// Gauss–Legendre with 5 points on [0, 1], in closed form: nodes (1 ± x_k)/2 with x = 0,
// ±(1/3) sqrt(5 ∓ 2 sqrt(10/7)), weights (on [−1, 1]) 128/225 and (322 ± 13 sqrt(70))/900.
struct Gauss5 {
  Eigen::Matrix<double, 5, 1> x, w;
  Gauss5() {
    const double a = std::sqrt(5.0 - 2.0 * std::sqrt(10.0 / 7.0)) / 3.0;
    const double b = std::sqrt(5.0 + 2.0 * std::sqrt(10.0 / 7.0)) / 3.0;
    const double wa = (322.0 + 13.0 * std::sqrt(70.0)) / 900.0, wb = (322.0 - 13.0 * std::sqrt(70.0)) / 900.0;
    const double s[5] = {-b, -a, 0.0, a, b};
    const double ws[5] = {wb, wa, 128.0 / 225.0, wa, wb};
    for (int k = 0; k < 5; ++k) {
      x(k) = 0.5 * (1.0 + s[k]);
      w(k) = 0.5 * ws[k];
    }
  }
};

// Gauss5 on 8 equal pieces of [0, 1]: nodes t, weights w.
struct CompositeGauss {
  static constexpr int kPieces = 8;
  Eigen::VectorXd t, w;
  CompositeGauss() : t(5 * kPieces), w(5 * kPieces) {
    const Gauss5 g;
    for (int p = 0; p < kPieces; ++p) {
      t.segment<5>(5 * p) = (g.x.array() + p) / kPieces;
      w.segment<5>(5 * p) = g.w / kPieces;
    }
  }
};

std::string element_name(Index e) { return "curve element " + std::to_string(e); }

}  // namespace

CurveGeometry::CurveGeometry(std::shared_ptr<const CurveSpace> space, Eigen::MatrixXd control_points)
    : space_(std::move(space)), control_points_(std::move(control_points)) {
  if (!space_) throw InputError("curve geometry: no space");
  if (control_points_.rows() != space_->num_dofs() || control_points_.cols() != 2) {
    throw InputError("curve geometry: " + std::to_string(control_points_.rows()) + " × " +
                     std::to_string(control_points_.cols()) + " control points for a space with " +
                     std::to_string(space_->num_dofs()) + " dofs (expected n × 2)");
  }
  if (!control_points_.allFinite()) throw InputError("curve geometry: a control point is not finite");
  const Index ne = space_->num_elements();
  if (ne == 0) throw InputError("curve geometry: the space has no elements");
  // End points and the bounding box of a few samples per element.
  Eigen::Matrix2Xd start(2, ne), end(2, ne);
  Eigen::Vector2d lo = Eigen::Vector2d::Constant(std::numeric_limits<double>::infinity()), hi = -lo;
  const Eigen::VectorXd samples = Eigen::VectorXd::LinSpaced(5, 0.0, 1.0);
  CurvePoints pts;
  for (Index e = 0; e < ne; ++e) {
    evaluate(e, samples, pts);
    start.col(e) = pts.x.col(0);
    end.col(e) = pts.x.col(samples.size() - 1);
    lo = lo.cwiseMin(pts.x.rowwise().minCoeff());
    hi = hi.cwiseMax(pts.x.rowwise().maxCoeff());
  }
  diameter_ = (hi - lo).norm();
  const double tol = 1e-9 * diameter_;
  // Match ends to starts through a coarse grid of cell size > tol (neighbouring cells searched).
  const double cell = std::max(tol * 16.0, 1e-300);
  auto key = [&](const Eigen::Vector2d& p) {
    return std::pair<long long, long long>(static_cast<long long>(std::floor((p.x() - lo.x()) / cell)),
                                           static_cast<long long>(std::floor((p.y() - lo.y()) / cell)));
  };
  std::multimap<std::pair<long long, long long>, Index> starts;
  for (Index e = 0; e < ne; ++e) starts.emplace(key(start.col(e)), e);
  next_.assign(static_cast<std::size_t>(ne), -1);
  previous_.assign(static_cast<std::size_t>(ne), -1);
  for (Index e = 0; e < ne; ++e) {
    const auto [kx, ky] = key(end.col(e));
    for (long long dx = -1; dx <= 1; ++dx) {
      for (long long dy = -1; dy <= 1; ++dy) {
        const auto range = starts.equal_range({kx + dx, ky + dy});
        for (auto it = range.first; it != range.second; ++it) {
          const Index f = it->second;
          if ((start.col(f) - end.col(e)).norm() > tol) continue;
          if (next_[static_cast<std::size_t>(e)] >= 0 || previous_[static_cast<std::size_t>(f)] >= 0) {
            throw InputError("curve geometry: the curve branches at the end of " + element_name(e) + " (" +
                             std::to_string(end(0, e)) + ", " + std::to_string(end(1, e)) + ")");
          }
          next_[static_cast<std::size_t>(e)] = f;
          previous_[static_cast<std::size_t>(f)] = e;
        }
      }
    }
  }
  // Loops: open chains from their free starts first (in element order), then closed ones.
  std::vector<char> used(static_cast<std::size_t>(ne), 0);
  auto walk = [&](Index first, bool closed) {
    CurveLoop loop;
    loop.closed = closed;
    for (Index e = first; e >= 0 && !used[static_cast<std::size_t>(e)]; e = next_[static_cast<std::size_t>(e)]) {
      used[static_cast<std::size_t>(e)] = 1;
      loop.elements.push_back(e);
    }
    loops_.push_back(std::move(loop));
  };
  for (Index e = 0; e < ne; ++e) {
    if (previous_[static_cast<std::size_t>(e)] < 0) walk(e, false);
  }
  for (Index e = 0; e < ne; ++e) {
    if (!used[static_cast<std::size_t>(e)]) walk(e, true);
  }
  std::stable_sort(loops_.begin(), loops_.end(), [](const CurveLoop& a, const CurveLoop& b) {
    return a.elements.front() < b.elements.front();
  });
}

void CurveGeometry::evaluate(Index e, const Eigen::VectorXd& t, CurvePoints& out, int derivatives) const {
  thread_local CurveBasisValues values;
  const int d = std::max(1, derivatives);
  space_->evaluate(e, t, d, values);
  const std::span<const Index> dofs = space_->dofs(e);
  const Index nl = static_cast<Index>(dofs.size()), q = t.size();
  thread_local Eigen::Matrix2Xd local;
  local.resize(2, nl);
  for (Index i = 0; i < nl; ++i) local.col(i) = control_points_.row(dofs[static_cast<std::size_t>(i)]).transpose();
  out.x.noalias() = local * values.value;
  out.dx.noalias() = local * values.dt;
  if (d >= 2) out.ddx.noalias() = local * values.dtt;
  out.speed = out.dx.colwise().norm().transpose();
  out.normal.resize(2, q);
  for (Index k = 0; k < q; ++k) {
    const double s = out.speed(k);
    if (!(s > 0.0) || !std::isfinite(s)) {
      throw NumericalError(element_name(e) + ": the curve has no tangent at t = " + std::to_string(t(k)));
    }
    out.normal(0, k) = out.dx(1, k) / s;
    out.normal(1, k) = -out.dx(0, k) / s;
  }
}

Eigen::Vector2d CurveGeometry::point(Index e, double t) const {
  CurvePoints p;
  evaluate(e, Eigen::VectorXd::Constant(1, t), p);
  return p.x.col(0);
}

double CurveGeometry::interior_angle(Index e) const {
  const Index f = next(e);
  if (f < 0) return std::numeric_limits<double>::quiet_NaN();
  CurvePoints a, b;
  evaluate(e, Eigen::VectorXd::Constant(1, 1.0), a);
  evaluate(f, Eigen::VectorXd::Constant(1, 0.0), b);
  const Eigen::Vector2d t1 = a.dx.col(0) / a.speed(0), t2 = b.dx.col(0) / b.speed(0);
  const double turn = std::atan2(t1.x() * t2.y() - t1.y() * t2.x(), t1.dot(t2));
  return std::numbers::pi - turn;
}

bool CurveGeometry::corner_at_end(Index e, double tolerance) const {
  const double a = interior_angle(e);
  return std::isfinite(a) && std::abs(a - std::numbers::pi) > tolerance;
}

double CurveGeometry::length(Index e) const {
  static const CompositeGauss rule;
  const Eigen::VectorXd& t = rule.t;
  const Eigen::VectorXd& w = rule.w;
  CurvePoints pts;
  evaluate(e, t, pts);
  return w.dot(pts.speed);
}

double CurveGeometry::loop_area(std::size_t k) const {
  static const CompositeGauss rule;
  const Eigen::VectorXd& t = rule.t;
  const Eigen::VectorXd& w = rule.w;
  const CurveLoop& loop = loops_.at(k);
  if (!loop.closed) return 0.0;
  // Relative to a point of the loop, so that far-away domains do not lose digits.
  const Eigen::Vector2d origin = point(loop.elements.front(), 0.0);
  double area = 0.0;
  CurvePoints pts;
  for (Index e : loop.elements) {
    evaluate(e, t, pts);
    for (Index q = 0; q < t.size(); ++q) {
      const Eigen::Vector2d x = pts.x.col(q) - origin;
      area += 0.5 * w(q) * (x.x() * pts.dx(1, q) - x.y() * pts.dx(0, q));
    }
  }
  return area;
}

double CurveGeometry::signed_area() const {
  double area = 0.0;
  for (std::size_t k = 0; k < loops_.size(); ++k) area += loop_area(k);
  return area;
}

}  // namespace iga::basis
