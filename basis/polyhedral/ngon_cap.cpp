#include "basis/polyhedral/ngon_cap.hpp"

#include <chrono>
#include <map>
#include <mutex>
#include <stdexcept>
#include <string>
#include <vector>

#include "basis/polyhedral/star_cap.hpp"

namespace iga::basis::polyhedral {
namespace {

void check_valence(int n) {
  if (n != 3 && (n < 5 || n > 8))
    throw std::invalid_argument("n-gon cap: n = " + std::to_string(n) + " is not in {3, 5, 6, 7, 8}");
}

int wrap(int k, int n) { return ((k % n) + n) % n; }
int index_c(int k, int n) { return wrap(k, n); }
int index_r(int k, int n) { return n + 3 * wrap(k, n); }
int index_d(int k, int n) { return n + 3 * wrap(k, n) + 1; }
int index_p(int k, int n) { return n + 3 * wrap(k, n) + 2; }

/// A bi-2 patch from the two rows of its uniform biquadratic B-spline grid nearest F (w-row 0, w-row 1; the
/// third row influences neither the boundary w = 0 nor ∂_w there and is left out), as BB coefficients
/// (row j·3 + i, i along s) over the 4n gathered vertices.
Eigen::MatrixXd bi2_from_rows(const int (&grid)[2][3], int n) {
  const double t[3][3] = {{0.5, 0.5, 0.0}, {0.0, 1.0, 0.0}, {0.0, 0.5, 0.5}};  // B-spline → Bézier
  Eigen::MatrixXd bb = Eigen::MatrixXd::Zero(9, 4 * n);
  for (int j = 0; j < 3; ++j)
    for (int i = 0; i < 3; ++i)
      for (int r = 0; r < 2; ++r)
        for (int c = 0; c < 3; ++c) bb(j * 3 + i, grid[r][c]) += t[i][c] * t[j][r];
  return bb;
}

/// Bi-2 patch of p_k: s from the centroid of B_k (s = 0) to that of A_k (s = 1), w away from F.
Eigen::MatrixXd bi2_of_p(int k, int n) {
  const int grid[2][3] = {{index_r(k, n), index_c(k, n), index_c(k + 1, n)},
                          {index_d(k, n), index_p(k, n), index_r(k + 1, n)}};
  return bi2_from_rows(grid, n);
}

/// Bi-2 patch of r_k: s from the centroid of B_k (s = 0) to that of A_{k−1} (s = 1), w away from F.
Eigen::MatrixXd bi2_of_r(int k, int n) {
  const int grid[2][3] = {{index_p(k, n), index_c(k, n), index_c(k - 1, n)},
                          {index_d(k, n), index_r(k, n), index_p(k - 1, n)}};
  return bi2_from_rows(grid, n);
}

CapDerivation derive(int n, Fairness fairness) {
  const StarReparameterisation r = star_reparameterisation(n);
  SectorCapSystem system(n, n >= 6, 4 * n);
  std::vector<int> bi2_p, bi2_r;
  for (int k = 0; k < n; ++k) {
    bi2_p.push_back(system.add_known_patch(2, 2, bi2_of_p(k, n)));
    bi2_r.push_back(system.add_known_patch(2, 2, bi2_of_r(k, n)));
  }
  for (int k = 0; k < n; ++k) {
    const auto kk = static_cast<std::size_t>(k);
    // outer edge v = 1 (from B_k's centroid at u = 1 to A_k's at u = 0) ↔ bi-2 of p_k
    system.join({k, {1, 1}, {-1, 0}, {0, -1}}, {bi2_p[kk], {0, 0}, {1, 0}, {0, 1}}, false, r.a_outer,
                r.b_outer);
    // outer edge u = 1 (from B_k's centroid at v = 1 to A_{k−1}'s at v = 0) ↔ bi-2 of r_k
    system.join({k, {1, 1}, {0, -1}, {-1, 0}}, {bi2_r[kk], {0, 0}, {1, 0}, {0, 1}}, false, r.a_outer,
                r.b_outer);
    // spoke toward A_{k−1}: sector k (edge v = 0) ↔ sector k − 1 (edge u = 0)
    system.join({k, {0, 0}, {1, 0}, {0, 1}}, {wrap(k - 1, n), {0, 0}, {0, 1}, {1, 0}}, true, r.a_spoke,
                r.b_spoke);
  }
  return system.solve(Configuration::NGon, n, fairness);
}

}  // namespace

int ngon_patch_count(int n) {
  check_valence(n);
  return n >= 6 ? 4 * n : n;
}

CapDerivation derive_ngon_cap(int n, Fairness fairness) {
  check_valence(n);
  const auto start = std::chrono::steady_clock::now();
  CapDerivation d = derive(n, fairness);
  d.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return d;
}

ConfigurationMask ngon_mask(int n) {
  check_valence(n);
  static std::mutex mutex;
  static std::map<int, ConfigurationMask> cache;
  const std::lock_guard<std::mutex> lock(mutex);
  auto it = cache.find(n);
  if (it == cache.end()) it = cache.emplace(n, derive_ngon_cap(n).mask).first;
  return it->second;
}

}  // namespace iga::basis::polyhedral
