#pragma once
// Bézier extraction (thesis §4.2, "IgA, Bézier extraction"): on each non-empty knot interval the p+1
// non-zero B-splines are combinations of the Bernstein polynomials of that interval, N = C B.
#include <Eigen/Core>
#include <vector>

#include "basis/bspline/knot_vector.hpp"

namespace iga::basis::bspline {

/// The extraction operator of interval [a, b) = [t_mu, t_{mu+1}): C(i, j) is the coefficient of the
/// Bernstein polynomial B_j^p((x-a)/(b-a)) in N_{mu-p+i}. Computed from blossoms: C(i, j) is B-spline i's
/// share of the blossom at (a^(p-j), b^j), i.e. of the j-th Bézier control point of the piece.
Eigen::MatrixXd extraction_operator(const KnotVector& kv, Index mu);
/// The same from the interval's knot window w[k] = t_{mu-p+k}, k = 0..2p+1 (blossom_row on a window).
Eigen::MatrixXd extraction_operator(const double* window, int p);

/// Extraction operators of every interval, in the order of kv.interval_spans().
std::vector<Eigen::MatrixXd> extraction_operators(const KnotVector& kv);

}  // namespace iga::basis::bspline
