#pragma once
// Test boundaries for tests/bem, built from SplineCurveSpace and control points (no FEM geometry needed).
#include <complex>
#include <memory>
#include <numbers>
#include <vector>

#include "basis/curve/curve_geometry.hpp"
#include "basis/curve/spline_curve_space.hpp"
#include "fem/function.hpp"

namespace iga::test::bem {

/// Closed polygons (counter-clockwise with the domain on the left; a hole clockwise), one degree-1 open
/// segment per edge: curve element k runs from corners[k] to corners[k+1].
inline basis::CurveGeometry polygons(const std::vector<std::vector<Eigen::Vector2d>>& loops) {
  std::vector<basis::SplineSegment> segments;
  std::vector<Eigen::Vector2d> cps;
  for (const auto& loop : loops) {
    for (std::size_t k = 0; k < loop.size(); ++k) {
      segments.push_back({1, false});
      cps.push_back(loop[k]);
      cps.push_back(loop[(k + 1) % loop.size()]);
    }
  }
  Eigen::MatrixXd c(static_cast<Index>(cps.size()), 2);
  for (std::size_t k = 0; k < cps.size(); ++k) c.row(static_cast<Index>(k)) = cps[k].transpose();
  return basis::CurveGeometry(std::make_shared<basis::SplineCurveSpace>(1, segments), c);
}

inline std::vector<Eigen::Vector2d> square_loop(double lo, double hi, bool clockwise = false) {
  std::vector<Eigen::Vector2d> l{{lo, lo}, {hi, lo}, {hi, hi}, {lo, hi}};
  if (clockwise) std::swap(l[1], l[3]);
  return l;
}

/// The square [lo, hi]²: curve elements 0..3 = bottom, right, top, left.
inline basis::CurveGeometry square(double lo = 0.0, double hi = 1.0) { return polygons({square_loop(lo, hi)}); }

/// [−1, 1]² with the clockwise hole [−0.4, 0.4]² (curve elements 0..3 outer, 4..7 the hole).
inline basis::CurveGeometry square_with_hole() {
  return polygons({square_loop(-1.0, 1.0), square_loop(-0.4, 0.4, true)});
}

/// A smooth closed loop of radius ≈ r around c: the periodic spline of `degree` whose n control points lie on
/// the circle of radius r at the angles of their Greville abscissae (close to, not exactly, a circle). Its
/// normal is C^{degree−2}, so the flux of a harmonic u has a jump in its (degree − 1)-th derivative at the
/// curve's knots: BEM splines of degree p (C^{p−1}) approximate it at the optimal rate only when
/// degree >= p + 1 (a periodic cubic limits p = 3 to the rate 2.5, measured).
inline basis::CurveGeometry smooth_loop(double r = 0.7, Index n = 10, Eigen::Vector2d c = {0.1, -0.05},
                                        int degree = 5) {
  auto space = std::make_shared<basis::SplineCurveSpace>(degree, std::vector<basis::SplineSegment>{{n, true}});
  const Eigen::VectorXd g = space->greville(0);
  Eigen::MatrixXd cps(n, 2);
  for (Index j = 0; j < n; ++j) {
    const double a = 2.0 * std::numbers::pi * g(j) / static_cast<double>(n);
    cps.row(j) << c.x() + r * std::cos(a), c.y() + r * std::sin(a);
  }
  return basis::CurveGeometry(space, cps);
}

/// Re z^k with its gradient (k z^{k−1} = u_x − i u_y).
inline std::shared_ptr<fem::Function> re_power(int k) {
  return fem::make_function(
      [k](const Eigen::Vector3d& x) { return std::pow(std::complex<double>(x.x(), x.y()), k).real(); },
      [k](const Eigen::Vector3d& x) {
        const std::complex<double> d = static_cast<double>(k) * std::pow(std::complex<double>(x.x(), x.y()), k - 1);
        return Eigen::Vector3d(d.real(), -d.imag(), 0.0);
      });
}

/// Im z^k (∇ Im f = (Im f', Re f') for analytic f).
inline std::shared_ptr<fem::Function> im_power(int k) {
  return fem::make_function(
      [k](const Eigen::Vector3d& x) { return std::pow(std::complex<double>(x.x(), x.y()), k).imag(); },
      [k](const Eigen::Vector3d& x) {
        const std::complex<double> d = static_cast<double>(k) * std::pow(std::complex<double>(x.x(), x.y()), k - 1);
        return Eigen::Vector3d(d.imag(), d.real(), 0.0);
      });
}

/// e^x cos y.
inline std::shared_ptr<fem::Function> exp_cos() {
  return fem::make_function([](const Eigen::Vector3d& x) { return std::exp(x.x()) * std::cos(x.y()); },
                            [](const Eigen::Vector3d& x) {
                              return Eigen::Vector3d(std::exp(x.x()) * std::cos(x.y()),
                                                     -std::exp(x.x()) * std::sin(x.y()), 0.0);
                            });
}

}  // namespace iga::test::bem
