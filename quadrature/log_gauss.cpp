#include "quadrature/log_gauss.hpp"

#include <Eigen/Eigenvalues>
#include <cmath>
#include <vector>

#include "core/error.hpp"

namespace iga::quadrature {

Rule1D log_gauss_rule(int n) {
  if (n < 1 || n > 40) throw InputError("logarithmic Gauss rule: n must be 1..40, got " + std::to_string(n));
  const int m = 2 * n;
  // Monic shifted Legendre recurrence p_{k+1} = (x − a_k) p_k − b_k p_{k−1} on [0, 1].
  std::vector<double> a(static_cast<std::size_t>(m), 0.5), b(static_cast<std::size_t>(m), 0.0);
  for (int k = 1; k < m; ++k) b[static_cast<std::size_t>(k)] = 0.25 * k * k / (4.0 * k * k - 1.0);
  // Modified moments ν_k = ∫ p_k (−ln x): the Legendre integral over the leading coefficient C(2k, k).
  std::vector<double> nu(static_cast<std::size_t>(m));
  double binom = 1.0;  // C(2k, k)
  for (int k = 0; k < m; ++k) {
    if (k > 0) binom *= (2.0 * k) * (2.0 * k - 1.0) / (static_cast<double>(k) * k);
    nu[static_cast<std::size_t>(k)] = k == 0 ? 1.0 : (k % 2 ? -1.0 : 1.0) / (static_cast<double>(k) * (k + 1) * binom);
  }
  // Modified Chebyshev algorithm (Gautschi, Orthogonal Polynomials, Algorithm 2.1).
  Eigen::VectorXd alpha(n), beta(n);
  std::vector<double> prev(static_cast<std::size_t>(m), 0.0), cur(nu), next(static_cast<std::size_t>(m), 0.0);
  alpha(0) = a[0] + nu[1] / nu[0];
  beta(0) = nu[0];
  for (int k = 1; k < n; ++k) {
    for (int l = k; l < m - k; ++l) {
      const auto L = static_cast<std::size_t>(l);
      next[L] = cur[L + 1] - (alpha(k - 1) - a[L]) * cur[L] - beta(k - 1) * prev[L] + b[L] * cur[L - 1];
    }
    alpha(k) = a[static_cast<std::size_t>(k)] + next[static_cast<std::size_t>(k + 1)] / next[static_cast<std::size_t>(k)] -
               cur[static_cast<std::size_t>(k)] / cur[static_cast<std::size_t>(k - 1)];
    beta(k) = next[static_cast<std::size_t>(k)] / cur[static_cast<std::size_t>(k - 1)];
    prev.swap(cur);
    cur.swap(next);
  }
  // Golub–Welsch.
  Eigen::MatrixXd jacobi = Eigen::MatrixXd::Zero(n, n);
  for (int k = 0; k < n; ++k) {
    jacobi(k, k) = alpha(k);
    if (k + 1 < n) jacobi(k, k + 1) = jacobi(k + 1, k) = std::sqrt(beta(k + 1));
  }
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(jacobi);
  Rule1D r;
  r.points = eig.eigenvalues();
  r.weights = beta(0) * eig.eigenvectors().row(0).transpose().array().square();
  return r;
}

}  // namespace iga::quadrature
