#pragma once
// Exact integrals of Catmull–Clark subdivision splines over an element at an interior extraordinary vertex
// (thesis §4.2.1, (4.28)–(4.34); Appendix C): on tile Ω_{k,l} (area 4^-l) the functions are
// φ = M44(t_{k,l}(u,v))^T X^k Ā A^(l-1), first derivatives carry 2^l, so every integral is a per-tile constant
// (exact B-spline integrals) summed over the three tiles and then over the levels by a geometric series.
#include <Eigen/Core>
#include <array>
#include <vector>

#include "quadrature/exact/series.hpp"
#include "quadrature/exact/tile_integrals.hpp"

namespace iga::quadrature::exact {

/// Integrals over [0,1]^2 of the 2n+8 Stam functions φ_m of valence n (stam.hpp ordering).
struct IrregularIntegrals {
  Eigen::VectorXd phi;      ///< ∫ φ_m                     (series s = 1/4)
  Eigen::MatrixXd phi_phi;  ///< ∫ φ_a φ_b                  (s = 1/4)
  Eigen::MatrixXd d[2][2];  ///< d[i][j](a, b) = ∫ ∂_i φ_a ∂_j φ_b, i, j in {0: u, 1: v}  (s = 1, deflated)
};

/// Cached per valence (thread-safe; computed on first use). InputError unless 3 <= n <= 16.
const IrregularIntegrals& irregular_integrals(int n);

/// Second-derivative products, [d][e](a, b) = ∫ ∂²_d φ_a ∂²_e φ_b with d, e in {0: uu, 1: uv, 2: vv}.
/// Per level the factor is 4^-l · 4^l · 4^l = 4^l: the series has s = 4 and converges iff 4 λ² < 1 for every
/// eigenvalue λ whose eigenfunction has non-zero second derivatives (the constant mode, and for n = 4 the
/// linear modes, are deflated exactly). An eigenfunction ψ(u/2, v/2) = λ ψ(u, v) behaves like r^α with
/// α = -log2 λ, its second derivatives like r^(α-2), square integrable in 2D iff α > 1, i.e. λ < 1/2.
/// n = 3: λ = (4.5 + √17/2)/16 ≈ 0.410, 4λ² ≈ 0.67 < 1: the second derivatives are unbounded at the EV
/// (growing like (4λ)^l ≈ 1.64^l per level) but square integrable, and the series converges (slowly:
/// 0.67^j). n = 4: polynomial. n >= 5: λ > 1/2, the integrals are infinite: UnsupportedError with the reason.
std::array<std::array<Eigen::MatrixXd, 3>, 3> second_derivative_products(int n);

/// Triple products T[a](b, c) = ∫ F_a G_b H_c of the 2n+8 Stam functions, each factor -1 (value), 0 (d/du) or
/// 1 (d/dv) (Appendix C: the third-order tensor series). Per level the factor is s = 4^-l 2^(l·#derivatives),
/// i.e. s = 2^#d / 4 per step; the constant mode is deflated in each derivative factor, so the series
/// converges when s λ_i λ_j λ_k < 1 over the remaining triples: value×du×dv: max is 1·λ1² < 1 (λ1 the
/// subdominant eigenvalue); three derivatives: 2 λ1³ < 1 (λ1 <= 0.65 for n <= 16). InputError for bad factors.
Tensor3 triple(int n, Factor da, Factor db, Factor dc);

}  // namespace iga::quadrature::exact
