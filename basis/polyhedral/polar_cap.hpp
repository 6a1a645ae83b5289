#pragma once
// Polar configuration of the polyhedral bi-3 splines (Peters, Lo, Karčiauskas, "Bi-cubic splines for
// polyhedral control nets", Section 3 (7)): a pole P of valence n ∈ 3..8 surrounded by n triangles
// (P, q_k, q_{k+1}) and a ring of quads. Gather order [P, q_0, …, q_{n−1}] (configuration.hpp). Output: n
// patches of degree (3, 2) (radial, circular) whose BB coefficients b_0j collapse into the pole; they are
// surrounded by the ring of n bi-2 patches of the ring vertices q_k (Regular configurations with the fan
// triangles read as quads collapsed onto P, configuration.hpp).
//
// Patch orientation (ours): patch k is centred on the spoke P q_k and spans, around the pole, the same
// range as the bi-2 patch of q_k (from the direction of triangle k−1 to that of triangle k):
//   u (degree 3, BB index i) radial: u = 0 is the pole (the collapsed edge: b_0j = pole for j = 0..2),
//     u = 1 the boundary shared with the bi-2 patch of q_k;
//   v (degree 2, BB index j) circular, counter-clockwise: v = 0 toward q_{k−1} (shared with patch k − 1),
//     v = 1 toward q_{k+1} (shared with patch k + 1).
// Row j·4 + i of PatchMask::coefficients is b_ij (mask.hpp layout, degree_u = 3, degree_v = 2).
//
// Derivation (ours): the 12n BB coefficients are the unknowns of a constrained least-squares system
//  - C0 and C1 to the bi-2 patch r_k of q_k (s along v, w away from P): p_k(1, s) = r_k(s, 0) and
//    ∂_u p_k(1, s) = ½ ∂_w r_k(s, 0), i.e. (4) with a = ½, b = 0 ("polar configurations join C1", paper
//    Section 3; the factor ½ is recovered from the reference tables polarSct3..8, where it holds exactly);
//  - C1 between neighbouring polar patches (a = 1, b = 0): p_k(u, 1) = p_{k+1}(u, 0), ∂_v p_k(u, 1) =
//    ∂_v p_{k+1}(u, 0);
//  - the collapse b_0j of every patch = one pole point X;
//  - the removable singularity at the pole ([26] of the paper): with the C1 joins the first ring b_1j is a
//    periodic C1 quadratic spline around the pole with control points c_k = b_11 of patch k; it must be an
//    affine image of the regular n-gon centred at X: c_k = X + U cos(2πk/n) + V sin(2πk/n) (so the
//    tangent plane at the pole is spanned by U, V and the surface is C1 in polar coordinates). Linearly:
//    Σ_k c_k = n X and Σ_k c_k cos(2πmk/n) = Σ_k c_k sin(2πmk/n) = 0 for 2 ≤ m ≤ n/2;
//  - all these are coefficient identities (the joined boundaries have the same degree on both sides);
//    rank A = rank [A | B] is checked; the null space has dimension 3 (X, U, V), fixed by minimising
//    ∫ |∂uuu|² + 3|∂uuv|² + 3|∂uvv|² over the n patches in their parameter domains.
// The reference surfaces (tables polarSct3..8) satisfy every constraint above with X = ¾P + ¼·mean(q) and
// c_k = X + (1/(3n)) Σ_m cos(2π(m−k)/n) q_m, which is exactly the minimiser of the third-derivative
// functional: our masks agree with the tables entrywise to their watermark (≤ 7e-10), so the distance of
// the surfaces is ~1e-10 of the bounding-box diagonal (tests/basis/test_polyhedral_polar.cpp). The
// thin-plate functional gives a different first ring (entries off by up to 2e-2).
#include "basis/polyhedral/g1_cap.hpp"
#include "basis/polyhedral/mask.hpp"

namespace iga::basis::polyhedral {

/// The polar cap's extraction operator for n ∈ 3..8: n patches of degree (3, 2) over the n + 1 gathered
/// vertices [P, q_0, …, q_{n−1}] (physical coordinates in, BB coefficients out). Derived once per n and
/// cached (thread-safe). Throws std::invalid_argument for other n.
ConfigurationMask polar_mask(int n);

/// The uncached derivation with its diagnostics (ranks, null-space dimension, wall time).
/// Fairness::ThinPlate uses ∫ |∂uu|² + 2|∂uv|² + |∂vv|² instead.
CapDerivation derive_polar_cap(int n, Fairness fairness = Fairness::ThirdDerivatives);

}  // namespace iga::basis::polyhedral
