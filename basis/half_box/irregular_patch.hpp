#pragma once
// Exact evaluation of a half-box patch with an extraordinary face (EF) at corner (0,0) (thesis (3.40)):
// on tile k of layer l, S = H111^T(t_k(2^(l−1) x)) X^k Ā A^(l−1) N, with cached matrix powers (A is
// defective for n >= 4, so no eigendecomposition is used).
#include <Eigen/Core>

#include "basis/basis_values.hpp"

namespace iga::basis::half_box {

/// The patch_size(valence) blending functions of an EF patch (rows in patch_net.hpp order) at uv (2 × q
/// points of the reference triangle {u, v >= 0, u + v <= 1}, EF corner at (0,0)), derivatives with respect to
/// (u, v) up to `derivatives` (0, 1, 2). The layer of a point is l = 1 − e for u + v = m 2^e, m in [1/2, 1),
/// (l = 1 for u + v = 1); on it the derivatives carry 2^(l−1) and 4^(l−1). At (0,0) exactly the values are the
/// limit stencil and the first derivatives the tangent stencils of subdivision_structure.hpp (limits along
/// 2^-m (1/3, 1/3); the parametric derivatives themselves have no limit at the EF for n != 6, but every
/// limit spans the tangent plane, so du × dv is normal). Second derivatives grow like 1/(u + v) towards the
/// EF (the eigenfunctions of 1/2 are not linear); derivatives = 2 at (0,0) throws NumericalError.
/// Below u + v = 2^-64 the limit values and tangent stencils are used (differences below 1e-18), and
/// derivatives = 2 throws NumericalError as at (0,0).
/// valence 6 reproduces evaluate_regular (13-point order). Throws InputError for derivatives outside 0..2 or a
/// point outside the triangle (tolerance 1e-12), UnsupportedError for valences without a structure.
/// Resizes `out`; no allocation when `out` already has the sizes.
void evaluate_irregular(int valence, const Eigen::Matrix2Xd& uv, int derivatives, BasisValues& out);

/// The patch of any valence: evaluate_regular for 6, evaluate_irregular otherwise.
void evaluate_patch(int valence, const Eigen::Matrix2Xd& uv, int derivatives, BasisValues& out);

}  // namespace iga::basis::half_box
