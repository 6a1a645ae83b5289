#pragma once
// The symmetric, non-uniform refine-and-smooth subdivision algorithm for B-splines of any degree d >= 1
// (Cashman, Dodgson, Sabin): zero or one new knot per knot interval, a refine stage (copies for even d, one
// affine combination per new knot for odd d) followed by (d-1)/2 or d/2 smoothing stages, each point formed
// by one of the actions (a) copy, (b)/(c) one new knot, (d) two new knots (factorised about a pivot, (6)-(8)),
// with the end conditions of §7 by boundary markers. Index sets: Z indexes the refined knot sequence u,
// Y ⊂ Z the original knots; the polar arguments of P^λ_i are u_j, j ∈ cen^d_i(Y ∪ cen^λ_i(Z)).
#include <Eigen/Sparse>
#include <vector>

#include "basis/bspline/spline_curve.hpp"
#include "basis/geometry.hpp"
#include "refine/polar_convention.hpp"
#include "refine/uniform.hpp"

namespace iga::refine {

enum class RefineSmoothVariant {
  levels,           ///< §3: each level P^λ computed from a separate copy of P^{λ-2}
  constant_memory,  ///< §5: P^λ_i stored in the same place for every λ (in place, one saved point), in blocks
                    ///< of 1024 positions with O(block + d) working memory, on the OpenMP threads
};

struct RefineSmoothResult {
  PolarSpline spline;              ///< the refined B-spline, truncated as in §7 (paper convention)
  long long affine_combinations = 0;  ///< two-point affine combinations evaluated (copies are free)
};

/// Paper convention. new_knots has one entry per knot interval [t_j, t_{j+1}], j = 0..k-2: NaN for none,
/// otherwise a value in [t_j, t_{j+1}]. InputError for a misplaced knot, a multiplicity above d it would
/// create, or an inconsistent spline.
RefineSmoothResult refine_smooth(const PolarSpline& spline, const std::vector<double>& new_knots,
                                 RefineSmoothVariant variant = RefineSmoothVariant::levels);

/// Standard convention: inserts the knots xs (inside the domain, any order). Each pass inserts at most one
/// knot per non-empty interval (the one containing it); further knots in the same interval take further
/// passes. The end knots are kept. `count` (optional) accumulates the affine combinations. With the §5
/// variant and sorted xs, one knot per interval, the single pass reads xs directly (no per-interval array).
basis::bspline::SplineCurve refine_smooth(const basis::bspline::SplineCurve& curve, const std::vector<double>& xs,
                                          RefineSmoothVariant variant = RefineSmoothVariant::levels,
                                          long long* count = nullptr);

/// The refinement matrix (fine × coarse) of a knot vector (standard convention, any degree) for the knots xs,
/// computed by the algorithm applied to the unit coordinate vectors; fine knots returned in `fine_knots`.
Eigen::SparseMatrix<double> refine_smooth_matrix(int degree, const std::vector<double>& knots,
                                                 const std::vector<double>& xs, std::vector<double>& fine_knots);

/// Tensor-product B-spline geometry: halves the chosen non-empty intervals (0-based, in order; empty = all) in
/// each direction. Returns the refined geometry (the same map) and the prolongation (kron(R_v, R_u)).
/// UnsupportedError unless the space is a basis::bspline::TensorSpace.
Refinement refine_smooth_tensor(const basis::Geometry& geometry, const std::vector<Index>& intervals_u = {},
                                const std::vector<Index>& intervals_v = {});

}  // namespace iga::refine
