#pragma once
// Internal to refine/: the constant-memory variant (§5) of the refine-and-smooth algorithm as a blocked
// sweep. Final positions are processed in blocks of B; each block runs the refine stage on B + 2·levels
// positions and every smoothing level in place (P^λ_i stored where P^{λ-2}_i was, one saved point), so the
// working memory is O(B + d) whatever the length of the curve. The index sets Y ⊂ Z are never stored: a
// generator merges the knots with the new ones into a window of O(B + d) entries, and the refined knot vector
// is written straight to the output. Blocks run on the OpenMP threads in chunks.
#include <Eigen/Core>
#include <vector>

#include "core/types.hpp"

namespace iga::refine::detail {

/// NumericalError for a zero knot span in an affine combination (out of line: the cold path).
[[noreturn, gnu::noinline, gnu::cold]] void zero_span();
/// num / den for an affine weight; 0/0 (all the knots involved coincide, so both points carry the same
/// arguments) is 0.
[[gnu::always_inline]] inline double ratio(double num, double den) {
  if (den > 0.0) [[likely]] return num / den;
  if (num == 0.0) return 0.0;
  zero_span();
}

/// The new knots of one run, at most one in each knot interval [t_j, t_{j+1}] of the paper's knot vector.
struct NewKnots {
  /// Either one entry per interval j = 0..k-2 (NaN: no knot) ...
  const double* per_interval = nullptr;
  /// ... or sorted values (per_interval null), value x going to the first non-empty interval j in
  /// [first, last] with t_j <= x < t_{j+1} (x <= t_{j+1} for j = last): the standard convention's rule.
  const double* sorted = nullptr;
  Index count = 0;
  Index first = 0, last = -1;
};

/// Throws InputError if the new knot x of interval j (t_j <= x <= t_{j+1} assumed) would get a multiplicity
/// above the degree d.
void check_new_knot(const double* t, Index k, Index j, double x, int d);

/// Runs the §5 variant on the paper-convention spline (d, t[0..k-1], cp with k - d + 1 rows). Writes the
/// surviving control points to `out` (resized) and the refined knots after the truncation of §7 to
/// out_knots[offset..] (resized to offset + count + offset); adds the affine combinations to `count`.
/// Returns false, writing nothing, if `sorted` knots do not each have an interval of their own (two in one
/// interval: the caller needs another pass). InputError for a knot of too high multiplicity.
bool refine_smooth_stream(int d, const double* t, Index k, const Eigen::MatrixXd& cp, const NewKnots& knots,
                          long long& count, Eigen::MatrixXd& out, std::vector<double>& out_knots,
                          std::size_t offset);

}  // namespace iga::refine::detail
