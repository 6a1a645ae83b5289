#pragma once
// Convergence rates for tests: the least-squares slope of log(error) against log(h) for h = 2^-k.
#include <cmath>
#include <vector>

namespace iga::test {

/// errors[k] at mesh size h_k = h_0 2^-k; returns the fitted p in error ~ C h^p.
inline double fitted_rate(const std::vector<double>& errors) {
  const int n = static_cast<int>(errors.size());
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  for (int k = 0; k < n; ++k) {
    const double x = -k * std::log(2.0), y = std::log(errors[static_cast<std::size_t>(k)]);
    sx += x;
    sy += y;
    sxx += x * x;
    sxy += x * y;
  }
  return (n * sxy - sx * sy) / (n * sxx - sx * sx);
}

}  // namespace iga::test
