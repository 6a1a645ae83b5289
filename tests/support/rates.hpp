#pragma once
// Convergence rates for tests: the least-squares slope of log(error) against log(h) for h = 2^-k.
#include <cmath>
#include <vector>

namespace iga::test {

/// errors[k] at mesh size h_k = h_0 2^-k; returns the fitted p in error ~ C h^p.
/// The least-squares slope of log(y) against log(x).
inline double loglog_slope(const std::vector<double>& x, const std::vector<double>& y) {
  const int n = static_cast<int>(y.size());
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  for (int k = 0; k < n; ++k) {
    const double a = std::log(x[static_cast<std::size_t>(k)]), b = std::log(y[static_cast<std::size_t>(k)]);
    sx += a;
    sy += b;
    sxx += a * a;
    sxy += a * b;
  }
  return (n * sxy - sx * sy) / (n * sxx - sx * sx);
}

inline double fitted_rate(const std::vector<double>& errors) {
  std::vector<double> h(errors.size());
  for (std::size_t k = 0; k < h.size(); ++k) h[k] = std::pow(0.5, static_cast<double>(k));
  return loglog_slope(h, errors);
}

/// The rate in the number of dofs (adaptive refinement): error ~ C dofs^-r; returns r.
inline double fitted_rate_in_dofs(const std::vector<double>& dofs, const std::vector<double>& errors) {
  return -loglog_slope(dofs, errors);
}

}  // namespace iga::test
