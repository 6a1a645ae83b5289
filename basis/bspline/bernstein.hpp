#pragma once
// Bernstein polynomials B_i^p(t) = C(p,i) t^i (1-t)^(p-i) on [0,1], batched over points.
#include <Eigen/Core>

namespace iga::basis::bspline {

/// Rows i = 0..p, columns = points t. d1, d2 (first and second derivatives) are filled when
/// derivatives >= 1, 2; they may be null otherwise. Computed by the degree recursion
/// B_i^k = (1-t) B_i^{k-1} + t B_{i-1}^{k-1}, with D B_i^p = p (B_{i-1}^{p-1} - B_i^{p-1}).
void bernstein(int p, const Eigen::Ref<const Eigen::RowVectorXd>& t, int derivatives, Eigen::MatrixXd& values,
               Eigen::MatrixXd* d1, Eigen::MatrixXd* d2);

}  // namespace iga::basis::bspline
