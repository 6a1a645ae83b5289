#include "quadrature/gauss_legendre.hpp"

#include <cmath>
#include <numbers>

#include "core/error.hpp"

namespace iga::quadrature {

Rule1D gauss_legendre(int n) {
  if (n < 1) throw InputError("gauss_legendre: need at least one point, got " + std::to_string(n));
  Rule1D r;
  r.points.resize(n);
  r.weights.resize(n);
  using Real = long double;
  const Real pi = std::numbers::pi_v<long double>;
  for (int k = 0; k < (n + 1) / 2; ++k) {
    Real x = std::cos(pi * (static_cast<Real>(k) + 0.75L) / (static_cast<Real>(n) + 0.5L));
    Real dp = 0;
    for (int it = 0; it < 100; ++it) {
      // P_n(x) and P_n'(x) by (j+1) P_{j+1} = (2j+1) x P_j - j P_{j-1}.
      Real p0 = 1, p1 = x;
      if (n == 1) p1 = x;
      for (int j = 1; j < n; ++j) {
        const Real p2 = ((2 * j + 1) * x * p1 - j * p0) / (j + 1);
        p0 = p1;
        p1 = p2;
      }
      // p1 = P_n, p0 = P_{n-1}; P_n' = n (x P_n - P_{n-1}) / (x^2 - 1).
      dp = static_cast<Real>(n) * (x * p1 - p0) / (x * x - 1);
      const Real dx = p1 / dp;
      x -= dx;
      if (std::fabs(dx) <= 1e-19L * (1 + std::fabs(x))) {
        // One more evaluation for the derivative at the converged node.
        p0 = 1;
        p1 = x;
        for (int j = 1; j < n; ++j) {
          const Real p2 = ((2 * j + 1) * x * p1 - j * p0) / (j + 1);
          p0 = p1;
          p1 = p2;
        }
        dp = static_cast<Real>(n) * (x * p1 - p0) / (x * x - 1);
        break;
      }
    }
    const Real w = 2 / ((1 - x * x) * dp * dp);
    // x is the k-th largest node on [-1, 1]; map to [0, 1] symmetrically.
    r.points(n - 1 - k) = static_cast<double>((1 + x) / 2);
    r.points(k) = static_cast<double>((1 - x) / 2);
    r.weights(n - 1 - k) = static_cast<double>(w / 2);
    r.weights(k) = static_cast<double>(w / 2);
  }
  return r;
}

}  // namespace iga::quadrature
