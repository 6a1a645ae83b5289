#pragma once
// Open (clamped) knot vectors and the B-splines on them, evaluated by the Cox–de Boor recursion
// (thesis §2.1.2). This is the reference path; elements are evaluated by Bézier extraction (extraction.hpp).
// The recursion, the spans and the blossoms work on any knot sequence (clamped or not) or on one interval's
// knot window: the one univariate model, also of SplineCurve (spline_curve.hpp) and the THB levels.
#include <Eigen/Core>
#include <span>
#include <vector>

#include "core/types.hpp"

namespace iga::basis::bspline {

/// Knots t_0 <= ... <= t_{m-1} of a degree-p spline space with n = m - p - 1 B-splines N_0..N_{n-1}.
/// Invariants (checked, InputError otherwise): p >= 1; finite, non-decreasing knots; the first p+1 and the
/// last p+1 knots equal (open/clamped); interior multiplicity <= p (the space is at least C^0);
/// a non-empty domain [t_p, t_n].
class KnotVector {
 public:
  KnotVector() = default;
  KnotVector(int degree, std::vector<double> knots);
  /// Open knot vector on [a, b] with `intervals` equal intervals.
  static KnotVector uniform(int degree, Index intervals, double a = 0.0, double b = 1.0);

  int degree() const { return degree_; }
  const std::vector<double>& knots() const { return knots_; }
  double operator[](Index i) const { return knots_[static_cast<std::size_t>(i)]; }
  Index size() const { return static_cast<Index>(knots_.size()); }
  Index num_basis() const { return size() - degree_ - 1; }
  double front() const { return knots_[static_cast<std::size_t>(degree_)]; }
  double back() const { return knots_[static_cast<std::size_t>(num_basis())]; }

  /// Distinct knots of the domain: the element boundaries.
  std::vector<double> breakpoints() const;
  /// For each non-empty interval [t_mu, t_{mu+1}) of the domain, in order, its index mu.
  const std::vector<Index>& interval_spans() const { return spans_; }
  Index num_intervals() const { return static_cast<Index>(spans_.size()); }
  /// The mu with t_mu <= x < t_{mu+1} and t_mu < t_{mu+1}, clamped to the domain (x = back() gives the last
  /// interval).
  Index span(double x) const;

 private:
  int degree_ = 0;
  std::vector<double> knots_;
  std::vector<Index> spans_;
};

/// The functions below take knot sequences t_0 <= ... <= t_{m-1} of degree p in the standard convention
/// (n = m - p - 1 B-splines, domain [t_p, t_n]), clamped or not, as plain sequences or as the knot window of
/// one interval, w[k] = t_{span-p+k}, k = 0..2p+1 (the p+1 B-splines of one interval depend on no other
/// knots). They do not check the knots: KnotVector and SplineCurve (spline_curve.hpp) do.
///
/// For each non-empty interval [t_mu, t_{mu+1}) of the domain, in order, its index mu.
std::vector<Index> domain_intervals(int p, std::span<const double> knots);
/// The mu with t_mu <= x < t_{mu+1} and t_mu < t_{mu+1}, clamped to the domain: x <= t_p gives the first
/// non-empty interval, x >= t_n the last. The domain must not be empty.
Index find_span(int p, std::span<const double> knots, double x);

/// Values (row 0) and derivatives up to order `derivatives` (rows 1..) of the p+1 B-splines
/// N_{span-p}, ..., N_span at x, by the Cox–de Boor recursion and the derivative formula
/// D N_{i,q} = q (N_{i,q-1}/(t_{i+q}-t_i) - N_{i+1,q-1}/(t_{i+q+1}-t_{i+1})). Derivatives are with respect to
/// the knot parameter x.
Eigen::MatrixXd basis_functions(const KnotVector& kv, Index span, double x, int derivatives);
/// The same from the knot window w of the interval.
Eigen::MatrixXd basis_functions(const double* window, int p, double x, int derivatives);

/// The blossom row: coefficients c_0..c_p with f(args_1, ..., args_p) = sum_i c_i P_{span-p+i} for the
/// polynomial piece of a spline on [t_span, t_{span+1}) (the Oslo / discrete B-spline recursion, a product
/// of B-spline matrices R_1(args_1) ... R_p(args_p)). With all args equal to x it gives the B-spline values
/// at x. Used for Bézier extraction and knot insertion.
Eigen::VectorXd blossom_row(const KnotVector& kv, Index span, const double* args);
/// The same from the knot window w of the interval alone: for knot vectors that are never stored whole
/// (basis/thb) or not clamped (SplineCurve).
Eigen::VectorXd blossom_row(const double* window, int p, const double* args);

}  // namespace iga::basis::bspline
