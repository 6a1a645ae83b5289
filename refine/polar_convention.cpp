#include "refine/polar_convention.hpp"

#include <cmath>
#include <string>

#include "core/error.hpp"

namespace iga::refine {

using basis::bspline::SplineCurve;

PolarSpline to_polar(const SplineCurve& curve) {
  basis::bspline::validate(curve);
  PolarSpline s;
  s.degree = curve.degree;
  s.knots.assign(curve.knots.begin() + 1, curve.knots.end() - 1);
  s.control_points = curve.control_points;
  return s;
}

SplineCurve to_standard(const PolarSpline& s, double front, double back) {
  const auto k = static_cast<Index>(s.knots.size());
  if (s.degree < 1 || k < s.degree || s.control_points.rows() != k - s.degree + 1) {
    throw InputError("polar B-spline: " + std::to_string(k) + " knots and degree " + std::to_string(s.degree) +
                     " need " + std::to_string(k - s.degree + 1) + " control points, got " +
                     std::to_string(s.control_points.rows()));
  }
  if (std::isnan(front)) front = s.knots.front();
  if (std::isnan(back)) back = s.knots.back();
  if (front > s.knots.front() || back < s.knots.back()) throw InputError("end knots out of order");
  SplineCurve c;
  c.degree = s.degree;
  c.knots.reserve(s.knots.size() + 2);
  c.knots.push_back(front);
  c.knots.insert(c.knots.end(), s.knots.begin(), s.knots.end());
  c.knots.push_back(back);
  c.control_points = s.control_points;
  return c;
}

}  // namespace iga::refine
