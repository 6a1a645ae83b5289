#pragma once
// Exact integrals over the unit square of products of the 16 tensor-product uniform cubic B-splines
// N_a(s) N_b(t) (row a + 4b, the order of bicubic_values and of Stam's picking matrices) and of their first
// parametric derivatives: the per-tile constants of the subdivision series.
#include <Eigen/Core>

#include "quadrature/exact/series.hpp"

namespace iga::quadrature::exact {

/// Which factor: -1 the value, 0 the derivative d/du (first coordinate), 1 d/dv.
using Factor = int;

/// 16-vector: ∫ F_i over [0,1]^2 for factor f.
Eigen::VectorXd tile_integral(Factor f);
/// 16 × 16: G(i, j) = ∫ F_i G_j (exact: 6-point Gauss per direction, degree 11).
Eigen::MatrixXd tile_gram(Factor f, Factor g);
/// 16 × 16 for second derivatives: d in {0: uu, 1: uv, 2: vv}.
Eigen::MatrixXd tile_gram2(int d, int e);
/// 16 × 16 × 16: T(i, j, k) = ∫ F_i G_j H_k.
Tensor3 tile_triple(Factor f, Factor g, Factor h);

}  // namespace iga::quadrature::exact
