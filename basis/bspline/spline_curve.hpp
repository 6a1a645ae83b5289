#pragma once
// B-spline curves with control points of any dimension on knots that need not be clamped, and knot insertion
// on them (thesis §2.3.1): Boehm's single-knot insertion and the Oslo algorithm (the rows of
// knot_insertion.hpp). The same univariate model as KnotVector (knot_vector.hpp): curve points and blossoms
// are basis_functions and blossom_row on a knot window. These are the references for the refine-and-smooth
// algorithm (refine/refine_smooth.hpp).
#include <Eigen/Core>
#include <vector>

#include "core/types.hpp"

namespace iga::basis::bspline {

/// A B-spline curve in the standard convention: knots t_0 <= ... <= t_{m-1}, n = m - degree - 1 control
/// points (rows of control_points, any number of columns), domain [t_degree, t_n]. The knots need not be
/// clamped.
struct SplineCurve {
  int degree = 0;
  std::vector<double> knots;
  Eigen::MatrixXd control_points;

  Index num_control_points() const { return static_cast<Index>(control_points.rows()); }
  double domain_begin() const { return knots[static_cast<std::size_t>(degree)]; }
  double domain_end() const { return knots[knots.size() - static_cast<std::size_t>(degree) - 1]; }
};

/// Throws InputError (one line naming the problem) unless: degree >= 1; finite, non-decreasing knots; no knot
/// of multiplicity above degree + 1; control-point rows = knots - degree - 1 >= 1; finite coordinates; a
/// non-empty domain.
void validate(const SplineCurve& curve);

/// The indices mu (t_mu < t_{mu+1}) of the non-empty knot intervals inside the domain, in order
/// (domain_intervals of the knots).
std::vector<Index> domain_intervals(const SplineCurve& curve);

/// Midpoints of the chosen non-empty domain intervals (0-based positions in domain_intervals(); empty = all).
/// InputError for an index out of range or not strictly increasing.
std::vector<double> interval_midpoints(const SplineCurve& curve, const std::vector<Index>& intervals);

/// Knot insertion (every function below, and refine_smooth on a SplineCurve) first checks the curve with
/// validate(), that each knot to insert lies in the domain and that no knot gets a multiplicity above
/// degree + 1 (refine_smooth: above degree, the algorithm's limit): InputError otherwise.
///
/// Boehm: inserts x (inside the domain) once. The interval used is the non-empty one containing x.
SplineCurve insert_knot_boehm(const SplineCurve& curve, double x);
/// Boehm applied knot by knot.
SplineCurve insert_knots_boehm(const SplineCurve& curve, const std::vector<double>& xs);
/// Oslo: all knots xs at once; every new control point is the blossom of a coarse piece at its knots
/// (oslo_rows, knot_insertion.hpp).
SplineCurve insert_knots_oslo(const SplineCurve& curve, const std::vector<double>& xs);

/// The blossom (polar form) of the polynomial piece on the non-empty interval [t_mu, t_{mu+1}] at
/// args[0..degree-1] (blossom_row on the piece's knot window).
Eigen::RowVectorXd blossom(const SplineCurve& curve, Index mu, const double* args);

/// Curve point at x (in the domain; outside it, the first or last piece extended) by the Cox–de Boor
/// recursion (basis_functions on the knot window of the interval containing x).
Eigen::VectorXd evaluate(const SplineCurve& curve, double x);

}  // namespace iga::basis::bspline
