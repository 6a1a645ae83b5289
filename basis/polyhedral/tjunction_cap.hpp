#pragma once
// T-configurations of the polyhedral bi-3 splines (Peters, Lo, Karčiauskas, "Bi-cubic splines for polyhedral
// control nets", Section 2 (4)–(6), Section 3 (4)–(6)): T0, T1, T2.
//
// T0: a triangle (s_0, s_1, s_2), s_0 5-valent, s_1, s_2 4-valent, with 7 quads around; 14 gathered
// vertices in the order of the picture in configuration.hpp (numbers below are those positions):
//        0 - 1 - 2
//        |   |   |
//        3 - 4 - 5        The cap covers the union of the dual faces of 4, 7, 8 (a 7-sided region with
//       /   / \   \       corners at the centroids of the faces 0143, 1254, 4598 (≈ middle of the right
//      6 - 7 - 8 - 9      side), 8 9 13 12, 7 8 12 11, 6 7 11 10, 3476 (≈ middle of the left side)),
//      |   |   |   |      as 2 × 2 bi-3 patches over the cap square (U, V) ∈ [0, 1]²:
//     10 -11 -12 - 13     U from the left side (3, 6) to the right side (5, 9), V from the bottom (11, 12)
//                         to the top (1); counter-clockwise when the picture is (U right, V up).
// Patch 2β + α covers [α/2, (α+1)/2] × [β/2, (β+1)/2] (0: bottom-left, 1: bottom-right, 2: top-left, 3:
// top-right), with its own (u, v) ∈ [0, 1]² along (U, V); row j·4 + i of PatchMask::coefficients is b_ij.
// Shared boundaries: bottom-left ↔ bi-2 patch of 11 (bottom) and of 6 (left); bottom-right ↔ 12, 9;
// top-left ↔ 3 (left) and the left half of 1's patch (top); top-right ↔ 5 and the right half of 1's.
//
// Derivation (ours): G1CapSystem (g1_cap.hpp) with the bi-2 neighbours (uniform biquadratic B-spline, as
// regular_mask) known and (4) across every shared boundary, with t the sub-patch edge parameter (in the
// direction of U or V), q the cap patch (cross derivative into it), p the neighbour (cross derivative away
// from the cap; for 1's patch, ∂_t covers half of its edge):
//    bottom:  BL ↔ 11: a = 1, b = −t(1−t)/4;      BR ↔ 12: a = 1, b = t(1−t)/4
//    left:    BL ↔ 6:  a = 1 − t/4, b = 0;        TL ↔ 3:  a = ¾ − t/4, b = 0
//    right:   BR ↔ 9:  a = 1 − t/4, b = 0;        TR ↔ 5:  a = ¾ − t/4, b = 0
//    top:     TL ↔ 1:  a = 1, b = t(1−t)/2;       TR ↔ 1:  a = 1, b = −t(1−t)/2
//    inside the cap: C1 (a = 1, b = 0) across U = ½ and V = ½.
// The paper refers to [25] (Table 1) for these; they were RECOVERED from the reference table T0.csv by
// least-squares fits of cubic a(t), b(t) in (4) along each shared boundary on random 3D nets: every fit
// returned the coefficients above up to ≤ 1e-9 (the tables' watermark), fit residuals ≤ 1.2e-10.
// The remaining freedom is fixed by minimising ∫ of the squared third derivatives.
//
// T1: a pentagon (10, 9, 5, 6, 11) with s_0 = 10 3-valent, 9 quads around; 18 gathered vertices in the
// picture order of configuration.hpp:
//        0 - 1 - 2 - 3       The cap covers the dual faces of 5, 6, 9, 10, 11: corners at the centroids of
//        |   |   |   |       0154, 1265, 2376 (top), 6 7 12 11, 11 12 17 16 (right), 10 11 16 15,
//        4 - 5 - 6 - 7       9 10 15 14 (bottom), 8 9 14 13, 4598 (left); as 4 × 2 bi-3 patches, patch
//       /   /     \   \      4β + α (α = 0..3 along U from left to right, β = 0, 1 along V from bottom to
//      8 - 9 -10- 11 - 12    top). The picture (y up) shows the net clockwise (face order 10, 9, 5, 6, 11),
//      |   |   |   |   |     so each patch's own (u, v) ∈ [0, 1]² runs along (V, U) — counter-clockwise for
//     13 -14 -15- 16 - 17    a counter-clockwise net; rows j·4 + i (b_ij, i along u = V).
// Shared boundaries and (4) (t the sub-patch edge parameter along U or V, conventions as for T0; stated in
// the (U, V) sub-patch coordinates):
//    bottom: 0 ↔ 14: b = −t(1−t)/6;  1 ↔ first half of 15: b = t(1−t)/6;  2 ↔ second half of 15:
//            b = −t(1−t)/6;  3 ↔ 16: b = t(1−t)/6  (a = 1)
//    left:   0 ↔ 8: a = 1 − t/6;  4 ↔ 4: a = 5/6 − t/6;  right: 3 ↔ 12: a = 1 − t/6;  7 ↔ 7: a = 5/6 − t/6
//            (b = 0)
//    top:    4 ↔ 1 on s ∈ [0, ⅔]: b = t(1−t)/4;  5 ↔ 1 on [⅔, 1]: b = −t(1−t)/4;  6 ↔ 2 on [0, ⅓]:
//            b = t(1−t)/4;  7 ↔ 2 on [⅓, 1]: b = −t(1−t)/4  (a = 1)
//    inside: C1 with a = ½, 1, 2 across the column boundaries 1|0, 2|1, 3|2 (the middle columns are
//            half as wide), a = 1 across the row boundary; b = 0.
// Recovered from T1.csv exactly as for T0 (coefficients to ≤ 4e-9, fit residuals ≤ 3.2e-10). Reference
// layout (a fact of the table): reference patch 2α + β is our patch 4β + α, reference row i·4 + j (i along
// V, j along U) is our row j·4 + i.
//
// T2: a hexagon (9, 11, 12, 13, 6, 5) with s_0 = 9 and s_2 = 12 3-valent, 10 quads around; 20 gathered
// vertices in the picture order of configuration.hpp (x = 0, 1, 3, 4 for the top rows, 0..4 for the
// bottom rows; the picture is counter-clockwise):
//      0 - 1 ------ 2 - 3    The cap covers the dual faces of the six hexagon corners, as 4 × 4 bi-3
//      |   |        |   |    patches, patch 4β + α (α along U left → right, β along V bottom → top), each
//      4 - 5 ------ 6 - 7    with its own (u, v) ∈ [0, 1]² along (U, V), rows j·4 + i.
//      |   |        |   |    Shared boundaries, per side the quarters k = 0..3 (bottom, top: along U; left,
//      8 - 9        |   |    right: along V):
//      |   |        |   |      bottom: 16, first / second half of 17, 18
//     10 -11 - 12 - 13 - 14    left:   10, first / second half of 8, 4
//      |   |    |    |   |     right:  14 on s ∈ [0, ⅔] and [⅔, 1], 7 on [0, ⅓] and [⅓, 1]
//     15 -16 - 17 - 18 - 19    top:    1 on [0, ⅔] and [⅔, 1], 2 on [0, ⅓] and [⅓, 1]
// (4) on quarter k of every side: a(t) linear from 1, 8/9, 5/6, 7/9 (k = 0..3) by −1/9, −1/18, −1/18,
// −1/9 (so a runs 1 → ⅔ along the side, continuously); b(t) = ∓t(1−t)/9 on the bottom and left
// (−, +, −, + for k = 0..3) and ±t(1−t)/6 on the right and top (+, −, +, −). Inside: C1 with a = ½, 1, 2
// across the column boundaries 1|0, 2|1, 3|2 and the row boundaries 1/0, 2/1, 3/2; b = 0.
// Recovered from T2.csv as for T0 (coefficients to ≤ 1.4e-8 — cubic fits of 40 boundaries, the larger
// ones on inner edges where the cubic basis is ill-conditioned —, fit residuals ≤ 2.4e-10). Reference
// layout: reference patch p = ours, reference row i·4 + j (i along V, j against U) = our row i·4 + (3 − j).
// The remaining 36-dimensional freedom is fixed by the thin-plate functional here (max distance to the
// reference surfaces / bounding-box diagonal 1.6e-2 on random nets, against 2.2e-2 with third derivatives;
// T0 and T1 are closer with third derivatives: 9.5e-3 / 7.3e-3 against 1.4e-2 / 1.1e-2).
#include "basis/polyhedral/g1_cap.hpp"
#include "basis/polyhedral/mask.hpp"

namespace iga::basis::polyhedral {

/// The T0 cap's extraction operator: 4 bi-3 patches over the 14 gathered vertices (physical coordinates in,
/// BB coefficients out). Derived once and cached (thread-safe).
ConfigurationMask t0_mask();

/// The uncached derivation with its diagnostics (ranks, null-space dimension, wall time).
CapDerivation derive_t0_cap(Fairness fairness = Fairness::ThirdDerivatives);

/// The T1 cap's extraction operator: 8 bi-3 patches over the 18 gathered vertices. Cached (thread-safe).
ConfigurationMask t1_mask();

/// The uncached T1 derivation with its diagnostics.
CapDerivation derive_t1_cap(Fairness fairness = Fairness::ThirdDerivatives);

/// The T2 cap's extraction operator: 16 bi-3 patches over the 20 gathered vertices. Cached (thread-safe).
ConfigurationMask t2_mask();

/// The uncached T2 derivation with its diagnostics (default: the thin-plate functional, see above).
CapDerivation derive_t2_cap(Fairness fairness = Fairness::ThinPlate);

}  // namespace iga::basis::polyhedral
