#pragma once
// Star configuration of the polyhedral bi-3 splines (Peters, Lo, Karčiauskas, "Bi-cubic splines for
// polyhedral control nets"): a vertex v of valence n = 3, 5..8 surrounded by n quads.  The cap covers the
// quarters of those quads at v (sector k: from v to the midpoints of v e_k and v e_{k+1} and the centroid of
// the quad (v, e_k, f_k, e_{k+1})); it joins the surrounding bi-2 spline (degree-raised to 3) G1 and its
// patches join each other G1.  Gather order and patch layout: see mask.hpp.
//
// Derivation (our own, not the reference masks): BB coefficients of the cap are the unknowns of
// G1CapSystem (g1_cap.hpp) with
//  - the cap boundary equal to the adjacent half of each bi-2 boundary curve, and (4) across it with
//      a(t) = (1 − c(1−t))/(1 − c),  b(t) = c(1−t)t/(1 − c),  c = cos(2π/n),
//    t = 0 at the quad centroid, t = 1 at the edge midpoint, p the quarter of the bi-2 patch of e_k
//    (cross derivative half the full patch's), q the cap patch (the paper's transition map);
//  - (4) with a = 1, b(t) = 2c(1−t) on the spokes v e_k (t = 0 at v) between neighbouring sectors;
//  - n ≥ 6: each sector split 2 × 2 (C1 inside the sector); the reparameterisations are not in the paper:
//    those of star_reparameterisation, recovered from the reference surfaces (star_cap.cpp), applied on
//    each half of every spoke and outer half-edge;
//  - the remaining freedom (n = 3, 5: centre point and tangent plane) fixed by minimising ∫ of the squared
//    third derivatives (closer to the reference surfaces than the thin-plate energy: max distance / bounding-
//    box diagonal 2e-3..6e-3 against 3e-3..8e-3 on random one-rings).
#include "basis/polyhedral/g1_cap.hpp"
#include "basis/polyhedral/mask.hpp"

namespace iga::basis::polyhedral {

/// The reparameterisations of (4) used by the star cap, on the sector level: t ∈ [0, 1] along a whole outer
/// half-edge (t = 0 at the quad centroid, t = 1 at the edge midpoint; p = the quarter of the bi-2 patch,
/// q = the cap sector) or along a whole spoke (t = 0 at v, t = 1 at the edge midpoint; p, q the two
/// sectors). With c' = c_outer:
///   a_outer(t) = (1 − c'(1−t))/(1 − c'),  b_outer(t) = c'(1−t)t/(1 − c'),  a_spoke = 1,
///   b_spoke piecewise linear through (0, 2c), (1/2, c'), (1, 0)  (= 2c(1−t) for n = 3, 5 where c' = c).
struct StarReparameterisation {
  double c = 0.0;        ///< cos(2π/n)
  double c_outer = 0.0;  ///< c' (n = 3, 5: c; n ≥ 6: recovered from the reference surfaces)
  EdgeFunction a_outer, b_outer, a_spoke, b_spoke;
};
/// Throws std::invalid_argument unless n ∈ {3, 5, 6, 7, 8}.
StarReparameterisation star_reparameterisation(int n);

/// Number of bi-3 patches of a star cap of valence n: n for n = 3, 5, 4n for n = 6, 7, 8.
int star_patch_count(int n);

/// The star cap's extraction operator for valence n ∈ {3, 5, 6, 7, 8}: star_patch_count(n) bi-3 patches
/// over the 2n + 1 gathered vertices [v, e_0, f_0, …] (physical coordinates in, BB coefficients out).
/// Derived once per valence and cached (thread-safe). Throws std::invalid_argument for other n.
ConfigurationMask star_mask(int n);

/// The uncached derivation with its diagnostics (ranks, null-space dimension, wall time).
CapDerivation derive_star_cap(int n, Fairness fairness = Fairness::ThirdDerivatives);

}  // namespace iga::basis::polyhedral
