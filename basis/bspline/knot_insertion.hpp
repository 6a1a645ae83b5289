#pragma once
// Knot insertion by the Oslo algorithm (thesis §2.3.1): the refinement matrix between nested spline spaces.
// Its rows are computed here only (oslo_rows): the matrix of two KnotVectors and the Oslo insertion on a
// SplineCurve (spline_curve.hpp) both use them.
#include <Eigen/Sparse>
#include <functional>
#include <span>
#include <string>
#include <vector>

#include "basis/bspline/knot_vector.hpp"

namespace iga::basis::bspline {

/// Receives row j of a refinement matrix: fine coefficient j = sum_{i=0..p} values(i) * coarse coefficient
/// first + i (the other coarse coefficients do not contribute).
using OsloRowSink = std::function<void(Index j, Index first, const Eigen::VectorXd& values)>;

/// The rows j = 0..n_fine-1, in order, of the refinement matrix between knot sequences `coarse` (t) and
/// `fine` (tau) of degree p in the standard convention, clamped or not (knot_vector.hpp). Row j is the blossom
/// (blossom_row on t's knot window) at (tau_{j+1}, ..., tau_{j+p}) of the coarse piece containing
/// [tau_j, tau_{j+1}) (the Oslo algorithm; the last piece for tau_j at the domain end). For tau_j before the
/// domain (unclamped knots, j < p) it is the mirror image: the piece with t_mu < tau_{j+p+1} <= t_{mu+1}, the
/// arguments from tau_{j+p} down. Either way no factor of the recursion extrapolates unless it multiplies an
/// exact zero, so the rows are free of cancellation for any knot spacing. Not checked: fine must contain
/// every coarse knot, with the same degree and domain (refinement_matrix and insert_knots_oslo check).
void oslo_rows(int p, std::span<const double> coarse, std::span<const double> fine, const OsloRowSink& row);

/// The same rows as the matrix R (n_fine × n_coarse): fine coefficients are R * coarse coefficients.
Eigen::SparseMatrix<double> oslo_matrix(int p, std::span<const double> coarse, std::span<const double> fine);

/// The matrix R (n_fine × n_coarse) with N^coarse_i = sum_j R(j, i) N^fine_j, so fine coefficients are
/// R * coarse coefficients. Row j is the blossom of the coarse piece containing [tau_j, tau_{j+1}) at
/// (tau_{j+1}, ..., tau_{j+p}) (oslo_matrix). Throws InputError unless fine has the same degree and contains
/// every knot of coarse (with at least its multiplicity) on the same domain.
Eigen::SparseMatrix<double> refinement_matrix(const KnotVector& coarse, const KnotVector& fine);

/// The knot vector with the midpoint of every non-empty interval inserted once. InputError, naming the interval as
/// `which` + its 0-based index among the non-empty ones, when one is too narrow to halve (too_narrow_to_halve).
KnotVector insert_midpoints(const KnotVector& kv, const std::string& which = "interval");

/// The knot vector with every non-empty interval split into `parts` >= 1 equal parts (parts - 1 knots inserted
/// at equal steps). InputError, naming the interval as `which` + its 0-based index among the non-empty ones, when
/// one is too narrow for the new knots to be distinct in double precision.
KnotVector split_intervals(const KnotVector& kv, int parts, const std::string& which = "interval");

/// The message for a knot interval [a, b] whose midpoint rounds to one of its ends in double precision (`which`:
/// "interval 3", in the user's numbering): halving it would repeat a knot instead.
std::string too_narrow_to_halve(double a, double b, const std::string& which);

}  // namespace iga::basis::bspline
