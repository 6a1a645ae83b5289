#include "basis/polyhedral/star_cap.hpp"

#include <chrono>
#include <cmath>
#include <map>
#include <mutex>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

namespace iga::basis::polyhedral {
namespace {

void check_valence(int n) {
  if (n != 3 && (n < 5 || n > 8))
    throw std::invalid_argument("star cap: valence " + std::to_string(n) + " is not in {3, 5, 6, 7, 8}");
}

int index_e(int k, int n) { return 1 + 2 * (((k % n) + n) % n); }
int index_f(int k, int n) { return 2 + 2 * (((k % n) + n) % n); }

/// The bi-2 patch of the 4-valent neighbour e_k as BB coefficients (3 × 3, row j·3 + i) over the gathered
/// vertices. Parameters: s (i) from the centroid of quad k−1 to the centroid of quad k, w (j) away from v.
/// Uniform biquadratic B-spline control grid (rows along w):
///   w-row 0: e_{k−1}  v    e_{k+1}
///   w-row 1: f_{k−1}  e_k  f_k
///   w-row 2: (outside the one-ring; it influences neither the boundary w = 0 nor ∂_w there, so it is
///            left out — its coefficients are zero here, which leaves every constraint of the cap intact).
Eigen::MatrixXd neighbour_bi2(int k, int n) {
  const int grid[2][3] = {{index_e(k - 1, n), 0, index_e(k + 1, n)},
                          {index_f(k - 1, n), index_e(k, n), index_f(k, n)}};
  // B-spline to Bézier of one uniform quadratic segment: (P0+P1)/2, P1, (P1+P2)/2
  const double t[3][3] = {{0.5, 0.5, 0.0}, {0.0, 1.0, 0.0}, {0.0, 0.5, 0.5}};
  Eigen::MatrixXd bb = Eigen::MatrixXd::Zero(9, 2 * n + 1);
  for (int j = 0; j < 3; ++j)
    for (int i = 0; i < 3; ++i)
      for (int r = 0; r < 2; ++r)
        for (int c = 0; c < 3; ++c) bb(j * 3 + i, grid[r][c]) += t[i][c] * t[j][r];
  return bb;
}

/// The constraints of one star cap (sector k of the cap = quad (v, e_k, f_k, e_{k+1})).
CapDerivation derive(int n, const StarReparameterisation& r, Fairness fairness) {
  SectorCapSystem system(n, n >= 6, 2 * n + 1);
  std::vector<int> bi2;
  for (int k = 0; k < n; ++k) bi2.push_back(system.add_known_patch(2, 2, neighbour_bi2(k, n)));
  for (int k = 0; k < n; ++k) {
    // outer boundary toward e_k (sector edge u = 1): s = 1 − t/2 on the bi-2 patch of e_k
    system.join({k, {1, 1}, {0, -1}, {-1, 0}},
                {bi2[static_cast<std::size_t>(k)], {1, 0}, {-0.5, 0}, {0, 0.5}}, false, r.a_outer, r.b_outer);
    // outer boundary toward e_{k+1} (sector edge v = 1): s = t/2 on the bi-2 patch of e_{k+1}
    system.join({k, {1, 1}, {-1, 0}, {0, -1}},
                {bi2[static_cast<std::size_t>((k + 1) % n)], {0, 0}, {0.5, 0}, {0, 0.5}}, false, r.a_outer,
                r.b_outer);
    // spoke v e_k between sector k (edge v = 0) and sector k − 1 (edge u = 0)
    system.join({k, {0, 0}, {1, 0}, {0, 1}}, {(k + n - 1) % n, {0, 0}, {0, 1}, {1, 0}}, true, r.a_spoke,
                r.b_spoke);
  }
  return system.solve(Configuration::Star, n, fairness);
}

double star_outer_c(int n) {
  check_valence(n);
  // n = 3, 5: the paper's c = cos(2π/n). n ≥ 6: recovered from the reference surfaces (tables eopSct6..8 of
  // the polyhedral_splines code evaluated on random 3D one-rings): along every outer half-edge and spoke
  // their patches satisfy (4) with the functions of star_reparameterisation for exactly this c' (least-
  // squares fit of a, b as cubics in t: a linear, b quadratic/piecewise linear, residual ≤ 5e-10, the size
  // of the tables' watermark perturbations). No closed form was identified; c' ≠ cos(2π/n).
  switch (n) {
    case 6:
      return 0.432242987;
    case 7:
      return 0.466624530;
    case 8:
      return 0.486776405;
    default:
      return std::cos(2.0 * std::numbers::pi / n);
  }
}

}  // namespace

StarReparameterisation star_reparameterisation(int n) {
  StarReparameterisation r;
  r.c = std::cos(2.0 * std::numbers::pi / n);
  r.c_outer = star_outer_c(n);
  const double c = r.c, co = r.c_outer;
  r.a_outer = [co](double t) { return (1.0 - co * (1.0 - t)) / (1.0 - co); };
  r.b_outer = [co](double t) { return co * (1.0 - t) * t / (1.0 - co); };
  r.a_spoke = [](double) { return 1.0; };
  // piecewise linear through (0, 2c), (1/2, c'), (1, 0); = 2c(1 − t) when c' = c
  r.b_spoke = [c, co](double t) {
    return t <= 0.5 ? 2.0 * c + (co - 2.0 * c) * 2.0 * t : 2.0 * co * (1.0 - t);
  };
  return r;
}

int star_patch_count(int n) {
  check_valence(n);
  return n >= 6 ? 4 * n : n;
}

CapDerivation derive_star_cap(int n, Fairness fairness) {
  check_valence(n);
  const auto start = std::chrono::steady_clock::now();
  CapDerivation d = derive(n, star_reparameterisation(n), fairness);
  d.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return d;
}

ConfigurationMask star_mask(int n) {
  check_valence(n);
  static std::mutex mutex;
  static std::map<int, ConfigurationMask> cache;
  const std::lock_guard<std::mutex> lock(mutex);
  auto it = cache.find(n);
  if (it == cache.end()) it = cache.emplace(n, derive_star_cap(n).mask).first;
  return it->second;
}

}  // namespace iga::basis::polyhedral
