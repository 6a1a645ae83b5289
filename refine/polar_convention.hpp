#pragma once
// The two conventions for B-spline knot vectors. Standard (basis::bspline::SplineCurve): m knots, m - d - 1
// control points.
// Paper (Cashman, Dodgson, Sabin; polar form): k knots, k - d + 1 control points, control point q labelled
// by the d consecutive knots t_q, ..., t_{q+d-1} (its blossom arguments), domain [t_{d-1}, t_{k-d}].
// The paper's knots are the standard ones without the first and the last (which do not affect the curve).
#include <Eigen/Core>
#include <vector>

#include "basis/bspline/spline_curve.hpp"

namespace iga::refine {

struct PolarSpline {
  int degree = 0;
  std::vector<double> knots;       ///< k knots
  Eigen::MatrixXd control_points;  ///< k - degree + 1 rows
};

/// Drops the first and the last knot. InputError if the curve is invalid (validate()).
PolarSpline to_polar(const basis::bspline::SplineCurve& curve);
/// Adds one knot at each end: `front` (<= the first knot) and `back` (>= the last knot); NaN repeats the end
/// knot. InputError if the counts do not match or the end knots are out of order.
basis::bspline::SplineCurve to_standard(const PolarSpline& spline, double front, double back);

}  // namespace iga::refine
