#pragma once
// Knot insertion by the Oslo algorithm (thesis §2.3.1): the refinement matrix between nested spline spaces.
#include <Eigen/Sparse>
#include <vector>

#include "basis/bspline/knot_vector.hpp"

namespace iga::basis::bspline {

/// The matrix R (n_fine × n_coarse) with N^coarse_i = sum_j R(j, i) N^fine_j, so fine coefficients are
/// R * coarse coefficients. Row j is the blossom of the coarse piece containing [tau_j, tau_{j+1}) at
/// (tau_{j+1}, ..., tau_{j+p}). Throws InputError unless fine has the same degree and contains every knot of
/// coarse (with at least its multiplicity) on the same domain.
Eigen::SparseMatrix<double> refinement_matrix(const KnotVector& coarse, const KnotVector& fine);

/// The knot vector with the midpoint of every non-empty interval inserted once.
KnotVector insert_midpoints(const KnotVector& kv);

}  // namespace iga::basis::bspline
