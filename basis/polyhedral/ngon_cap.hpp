#pragma once
// n-gon configuration of the polyhedral bi-3 splines (Peters, Lo, Karčiauskas, "Bi-cubic splines for
// polyhedral control nets"): a face F = (c_0, …, c_{n−1}), n = 3, 5..8, with 4-valent corners, surrounded by
// 2n quads (A_k on the edge c_k c_{k+1}, B_k touching F only at c_k). Gather order: see mask.hpp.
//
// The cap covers F and the quarters of the A_k, B_k at F's corners: sector k is bounded by the boundaries of
// the bi-2 patches of p_k (from the centroid of B_k to the centroid of A_k) and of r_k (from the centroid of
// B_k to the centroid of A_{k−1}), and by the spokes from F's centre to the centroids of A_{k−1} and A_k.
// Patch k (n = 3, 5), or sub-patches 4k + 2β + α (n ≥ 6, see SectorCapSystem):
//   (u, v) = (0, 0) at the centre of F, u toward the centroid of A_{k−1} (edge c_{k−1} c_k), v toward the
//   centroid of A_k (edge c_k c_{k+1}), (1, 1) at the centroid of B_k  (u → v counter-clockwise, as for the
//   star).
//
// Derivation (our own): G1CapSystem with
//  - each outer edge of sector k equal to the whole boundary of the adjacent bi-2 patch (degree-raised to 3),
//    and (4) across it with p = that bi-2 patch (full cross derivative), q = the sector, t = 0 at the
//    centroid of B_k, t = 1 at the centroid of A_k (A_{k−1}), and a_outer, b_outer of
//    star_reparameterisation(n);
//  - (4) on the spokes (t = 0 at F's centre) with a_spoke, b_spoke of star_reparameterisation(n);
//  - n ≥ 6: sectors split 2 × 2, C1 inside;
//  - the remaining freedom fixed by minimising ∫ of the squared third derivatives (closer to the reference
//    surfaces than the thin-plate energy: max distance / bounding-box diagonal 3e-3..1e-2 against
//    3e-3..1.5e-2).
// The reference surfaces (tables ngonSct3..8 of the polyhedral_splines code) satisfy (4) with exactly these
// functions (n = 3, 5: the paper's; n ≥ 6: the same c' as the star caps), which is how they were found.
#include "basis/polyhedral/g1_cap.hpp"
#include "basis/polyhedral/mask.hpp"

namespace iga::basis::polyhedral {

/// Number of bi-3 patches of an n-gon cap: n for n = 3, 5, 4n for n = 6, 7, 8.
int ngon_patch_count(int n);

/// The n-gon cap's extraction operator for n ∈ {3, 5, 6, 7, 8}: ngon_patch_count(n) bi-3 patches over the
/// 4n gathered vertices [c_0, …, c_{n−1}, r_0, d_0, p_0, …] (physical coordinates in, BB coefficients out).
/// Derived once per n and cached (thread-safe). Throws std::invalid_argument for other n.
ConfigurationMask ngon_mask(int n);

/// The uncached derivation with its diagnostics (ranks, null-space dimension, wall time).
CapDerivation derive_ngon_cap(int n, Fairness fairness = Fairness::ThirdDerivatives);

}  // namespace iga::basis::polyhedral
