#pragma once
// Gaussian (minimal) quadrature rules for univariate spline spaces (thesis §4.2.2; Micchelli–Pinkus:
// a spline space of even dimension m = 2q has a rule with q interior nodes and positive weights that
// integrates every function of the space exactly).
#include <vector>

#include "quadrature/rule.hpp"

namespace iga::quadrature::spline_gauss {

/// The B-splines N_0..N_{m-1} of degree p on the knots t_0 <= ... <= t_{m+p} (Cox–de Boor with half-open
/// intervals [t_j, t_{j+1}); at x = t_{m+p} the last non-empty interval is used). Values in `values`,
/// first derivatives in `derivatives` (if not null). Knots need not be open.
void bspline_values(int degree, const std::vector<double>& knots, double x, std::vector<double>& values,
                    std::vector<double>* derivatives = nullptr);

/// Exact integrals ∫ N_j = (t_{j+p+1} - t_j) / (p + 1), j = 0..m-1.
std::vector<double> bspline_integrals(int degree, const std::vector<double>& knots);

/// The open knot vector of the space of degree-p splines on the break points b_0 < ... < b_K that are
/// C^{c_k} at the inner break point b_k (continuity[k-1] for k = 1..K-1, -1 <= c_k <= p-1): b_0 and b_K
/// repeated p+1 times, b_k repeated p - c_k times.
std::vector<double> open_knots(int degree, const std::vector<double>& breakpoints, const std::vector<int>& continuity);

/// A Gaussian rule for the span of the degree-p B-splines on `knots`.
///
/// Accepted knot vectors: p >= 0, at least p+2 finite non-decreasing knots, every multiplicity <= p+1,
/// t_0 < t_last. The knots need not be open; the rule integrates over the union of the supports
/// [t_0, t_last] (for an open knot vector that is the domain [a, b]). Points and weights are in knot
/// coordinates (weights sum to t_last - t_0), points strictly increasing and strictly inside (t_0, t_last).
///
/// m = number of B-splines. m even: q = m/2 points. m odd: there is no Gaussian rule for the space itself;
/// the rule is the Gaussian rule of the superspace obtained by inserting ONE simple knot at the midpoint of
/// the longest knot interval (among equally long ones the one nearest the centre, so symmetric spaces stay
/// symmetric), q = (m+1)/2 points — the same count as a Gauss–Radau rule, with all nodes interior.
/// Without inner knots (a polynomial space) on an open knot vector the result is Gauss–Legendre with
/// ceil((p+1)/2) points.
///
/// Method: Newton on the 2q moment equations sum_i w_i N_j(x_i) = ∫ N_j (unknowns x_i, w_i), in long
/// double, with a homotopy in the moments: mu(s) = (1-s) mu_0 + s ∫N, where mu_0 are the moments of a
/// start rule with nodes at the midpoints of consecutive Greville-abscissa pairs (these satisfy the
/// Schoenberg–Whitney conditions for Hermite interpolation, so the Jacobian is regular at s = 0) and
/// weights ∫N_{2i} + ∫N_{2i+1}. Steps in s are halved when Newton fails or leaves the feasible set
/// (ordered interior nodes, positive weights). Throws NumericalError if the final residual exceeds
/// 1e-14 · (t_last - t_0) or the rule is not feasible.
Rule1D gaussian_rule(int degree, const std::vector<double>& knots);

/// gaussian_rule(degree, open_knots(degree, breakpoints, continuity)).
Rule1D gaussian_rule(int degree, const std::vector<double>& breakpoints, const std::vector<int>& continuity);

/// max_j |sum_i w_i N_j(x_i) - ∫ N_j| of `rule` for the degree-p B-splines on `knots` (in double).
double moment_residual(const Rule1D& rule, int degree, const std::vector<double>& knots);

}  // namespace iga::quadrature::spline_gauss
