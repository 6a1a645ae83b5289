#include "basis/polyhedral/tjunction_cap.hpp"

#include <array>
#include <chrono>
#include <mutex>
#include <optional>

namespace iga::basis::polyhedral {
namespace {

constexpr int kT0Gathered = 14;
constexpr int kT1Gathered = 18;
constexpr int kT2Gathered = 20;

/// A bi-2 neighbour from the two rows of its uniform biquadratic B-spline grid nearest the cap (row 0
/// nearest; the third row influences neither the shared boundary nor the cross derivative there and is
/// left out), as BB coefficients (row j·3 + i, i along s) over the gathered vertices.
Eigen::MatrixXd bi2_from_rows(const std::array<std::array<int, 3>, 2>& grid, int gathered) {
  const double t[3][3] = {{0.5, 0.5, 0.0}, {0.0, 1.0, 0.0}, {0.0, 0.5, 0.5}};  // B-spline → Bézier
  Eigen::MatrixXd bb = Eigen::MatrixXd::Zero(9, gathered);
  for (int j = 0; j < 3; ++j)
    for (int i = 0; i < 3; ++i)
      for (int r = 0; r < 2; ++r)
        for (int c = 0; c < 3; ++c) bb(j * 3 + i, grid[static_cast<std::size_t>(r)][static_cast<std::size_t>(c)]) +=
            t[i][c] * t[j][r];
  return bb;
}

CapDerivation derive_t0(Fairness fairness) {
  G1CapSystem system(4, kT0Gathered);
  // neighbours: grid rows (nearest the cap first), s in the direction of the cap's U (bottom, top) or V
  // (left, right); w away from the cap
  const int n11 = system.add_known_patch(2, 2, bi2_from_rows({{{6, 7, 8}, {10, 11, 12}}}, kT0Gathered));
  const int n12 = system.add_known_patch(2, 2, bi2_from_rows({{{7, 8, 9}, {11, 12, 13}}}, kT0Gathered));
  const int n6 = system.add_known_patch(2, 2, bi2_from_rows({{{11, 7, 4}, {10, 6, 3}}}, kT0Gathered));
  const int n3 = system.add_known_patch(2, 2, bi2_from_rows({{{7, 4, 1}, {6, 3, 0}}}, kT0Gathered));
  const int n9 = system.add_known_patch(2, 2, bi2_from_rows({{{12, 8, 4}, {13, 9, 5}}}, kT0Gathered));
  const int n5 = system.add_known_patch(2, 2, bi2_from_rows({{{8, 4, 1}, {9, 5, 2}}}, kT0Gathered));
  const int n1 = system.add_known_patch(2, 2, bi2_from_rows({{{3, 4, 5}, {0, 1, 2}}}, kT0Gathered));

  const EdgeFunction one = [](double) { return 1.0; };
  const EdgeFunction zero = [](double) { return 0.0; };
  const EdgeFunction side_lower = [](double t) { return 1.0 - 0.25 * t; };   // 1 → ¾
  const EdgeFunction side_upper = [](double t) { return 0.75 - 0.25 * t; };  // ¾ → ½
  const auto bubble = [](double c) { return EdgeFunction([c](double t) { return c * t * (1.0 - t); }); };
  const Eigen::Vector2d o(0, 0), ex(1, 0), ey(0, 1);
  auto neighbour = [](int patch, double s0, double ds) { return CapEdge{patch, {s0, 0}, {ds, 0}, {0, 1}}; };
  // bottom (cap edge v = 0, cross +v)
  system.join_g1({0, o, ex, ey}, neighbour(n11, 0, 1), one, bubble(-0.25));
  system.join_g1({1, o, ex, ey}, neighbour(n12, 0, 1), one, bubble(0.25));
  // left (u = 0, cross +u)
  system.join_g1({0, o, ey, ex}, neighbour(n6, 0, 1), side_lower, zero);
  system.join_g1({2, o, ey, ex}, neighbour(n3, 0, 1), side_upper, zero);
  // right (u = 1, cross −u)
  system.join_g1({1, ex, ey, -ex}, neighbour(n9, 0, 1), side_lower, zero);
  system.join_g1({3, ex, ey, -ex}, neighbour(n5, 0, 1), side_upper, zero);
  // top (v = 1, cross −v): the two halves of 1's boundary
  system.join_g1({2, ey, ex, -ey}, neighbour(n1, 0, 0.5), one, bubble(0.5));
  system.join_g1({3, ey, ex, -ey}, neighbour(n1, 0.5, 0.5), one, bubble(-0.5));
  // inside: C1 across U = ½ (1 | 0, 3 | 2) and V = ½ (2 / 0, 3 / 1)
  system.join_g1({1, o, ey, ex}, {0, ex, ey, -ex}, one, zero);
  system.join_g1({3, o, ey, ex}, {2, ex, ey, -ex}, one, zero);
  system.join_g1({2, o, ex, ey}, {0, ey, ex, -ey}, one, zero);
  system.join_g1({3, o, ex, ey}, {1, ey, ex, -ey}, one, zero);
  CapDerivation d = system.solve(Configuration::T0, 0, fairness);
  d.mask.valence = 0;
  return d;
}

CapDerivation derive_t1(Fairness fairness) {
  constexpr int g = kT1Gathered;
  G1CapSystem system(8, g);
  const int n14 = system.add_known_patch(2, 2, bi2_from_rows({{{8, 9, 10}, {13, 14, 15}}}, g));
  const int n15 = system.add_known_patch(2, 2, bi2_from_rows({{{9, 10, 11}, {14, 15, 16}}}, g));
  const int n16 = system.add_known_patch(2, 2, bi2_from_rows({{{10, 11, 12}, {15, 16, 17}}}, g));
  const int n8 = system.add_known_patch(2, 2, bi2_from_rows({{{14, 9, 5}, {13, 8, 4}}}, g));
  const int n4 = system.add_known_patch(2, 2, bi2_from_rows({{{9, 5, 1}, {8, 4, 0}}}, g));
  const int n12 = system.add_known_patch(2, 2, bi2_from_rows({{{16, 11, 6}, {17, 12, 7}}}, g));
  const int n7 = system.add_known_patch(2, 2, bi2_from_rows({{{11, 6, 2}, {12, 7, 3}}}, g));
  const int n1 = system.add_known_patch(2, 2, bi2_from_rows({{{4, 5, 6}, {0, 1, 2}}}, g));
  const int n2 = system.add_known_patch(2, 2, bi2_from_rows({{{5, 6, 7}, {1, 2, 3}}}, g));

  const EdgeFunction one = [](double) { return 1.0; };
  const EdgeFunction zero = [](double) { return 0.0; };
  const auto constant = [](double c) { return EdgeFunction([c](double) { return c; }); };
  const auto linear = [](double c0, double c1) { return EdgeFunction([c0, c1](double t) { return c0 + c1 * t; }); };
  const auto bubble = [](double c) { return EdgeFunction([c](double t) { return c * t * (1.0 - t); }); };
  const Eigen::Vector2d o(0, 0), ex(1, 0), ey(0, 1);
  auto neighbour = [](int patch, double s0, double ds) { return CapEdge{patch, {s0, 0}, {ds, 0}, {0, 1}}; };
  // bottom (v = 0 of patches 0..3): 14, the two halves of 15, 16
  system.join_g1({0, o, ex, ey}, neighbour(n14, 0, 1), one, bubble(-1.0 / 6));
  system.join_g1({1, o, ex, ey}, neighbour(n15, 0, 0.5), one, bubble(1.0 / 6));
  system.join_g1({2, o, ex, ey}, neighbour(n15, 0.5, 0.5), one, bubble(-1.0 / 6));
  system.join_g1({3, o, ex, ey}, neighbour(n16, 0, 1), one, bubble(1.0 / 6));
  // left (u = 0 of patches 0, 4) and right (u = 1 of patches 3, 7)
  system.join_g1({0, o, ey, ex}, neighbour(n8, 0, 1), linear(1.0, -1.0 / 6), zero);
  system.join_g1({4, o, ey, ex}, neighbour(n4, 0, 1), linear(5.0 / 6, -1.0 / 6), zero);
  system.join_g1({3, ex, ey, -ex}, neighbour(n12, 0, 1), linear(1.0, -1.0 / 6), zero);
  system.join_g1({7, ex, ey, -ex}, neighbour(n7, 0, 1), linear(5.0 / 6, -1.0 / 6), zero);
  // top (v = 1 of patches 4..7): 1 split at s = 2/3, 2 split at s = 1/3
  system.join_g1({4, ey, ex, -ey}, neighbour(n1, 0, 2.0 / 3), one, bubble(0.25));
  system.join_g1({5, ey, ex, -ey}, neighbour(n1, 2.0 / 3, 1.0 / 3), one, bubble(-0.25));
  system.join_g1({6, ey, ex, -ey}, neighbour(n2, 0, 1.0 / 3), one, bubble(0.25));
  system.join_g1({7, ey, ex, -ey}, neighbour(n2, 1.0 / 3, 2.0 / 3), one, bubble(-0.25));
  // inside: C1 across the columns (a = ½, 1, 2: the middle columns are half as wide) and the rows
  const double column_a[3] = {0.5, 1.0, 2.0};
  for (int beta = 0; beta < 2; ++beta)
    for (int alpha = 1; alpha < 4; ++alpha)
      system.join_g1({4 * beta + alpha, o, ey, ex}, {4 * beta + alpha - 1, ex, ey, -ex},
                     constant(column_a[alpha - 1]), zero);
  for (int alpha = 0; alpha < 4; ++alpha) system.join_g1({4 + alpha, o, ex, ey}, {alpha, ey, ex, -ey}, one, zero);
  CapDerivation d = system.solve(Configuration::T1, 0, fairness);
  d.mask.valence = 0;
  // The picture shows the T1 net clockwise: swap (u, v) so that every patch is counter-clockwise for a
  // counter-clockwise net (b_ij ↔ b_ji).
  for (PatchMask& p : d.mask.patches) {
    const Eigen::MatrixXd c = p.coefficients;
    for (int j = 0; j < 4; ++j)
      for (int i = 0; i < 4; ++i) p.coefficients.row(i * 4 + j) = c.row(j * 4 + i);
  }
  return d;
}

CapDerivation derive_t2(Fairness fairness) {
  constexpr int g = kT2Gathered;
  G1CapSystem system(16, g);
  const int n16 = system.add_known_patch(2, 2, bi2_from_rows({{{10, 11, 12}, {15, 16, 17}}}, g));
  const int n17 = system.add_known_patch(2, 2, bi2_from_rows({{{11, 12, 13}, {16, 17, 18}}}, g));
  const int n18 = system.add_known_patch(2, 2, bi2_from_rows({{{12, 13, 14}, {17, 18, 19}}}, g));
  const int n10 = system.add_known_patch(2, 2, bi2_from_rows({{{16, 11, 9}, {15, 10, 8}}}, g));
  const int n8 = system.add_known_patch(2, 2, bi2_from_rows({{{11, 9, 5}, {10, 8, 4}}}, g));
  const int n4 = system.add_known_patch(2, 2, bi2_from_rows({{{9, 5, 1}, {8, 4, 0}}}, g));
  const int n14 = system.add_known_patch(2, 2, bi2_from_rows({{{18, 13, 6}, {19, 14, 7}}}, g));
  const int n7 = system.add_known_patch(2, 2, bi2_from_rows({{{13, 6, 2}, {14, 7, 3}}}, g));
  const int n1 = system.add_known_patch(2, 2, bi2_from_rows({{{4, 5, 6}, {0, 1, 2}}}, g));
  const int n2 = system.add_known_patch(2, 2, bi2_from_rows({{{5, 6, 7}, {1, 2, 3}}}, g));

  const EdgeFunction zero = [](double) { return 0.0; };
  const auto constant = [](double c) { return EdgeFunction([c](double) { return c; }); };
  const auto bubble = [](double c) { return EdgeFunction([c](double t) { return c * t * (1.0 - t); }); };
  // a(t) on the k-th quarter of every side: 1 → 8/9 → 5/6 → 7/9 → 2/3, linear on each quarter
  const double a0[4] = {1.0, 8.0 / 9, 5.0 / 6, 7.0 / 9}, a1[4] = {-1.0 / 9, -1.0 / 18, -1.0 / 18, -1.0 / 9};
  const auto side_a = [&](int k) {
    const double c0 = a0[k], c1 = a1[k];
    return EdgeFunction([c0, c1](double t) { return c0 + c1 * t; });
  };
  const Eigen::Vector2d o(0, 0), ex(1, 0), ey(0, 1);
  auto neighbour = [](int patch, double s0, double ds) { return CapEdge{patch, {s0, 0}, {ds, 0}, {0, 1}}; };
  const CapEdge bottom[4] = {neighbour(n16, 0, 1), neighbour(n17, 0, 0.5), neighbour(n17, 0.5, 0.5),
                             neighbour(n18, 0, 1)};
  const CapEdge left[4] = {neighbour(n10, 0, 1), neighbour(n8, 0, 0.5), neighbour(n8, 0.5, 0.5),
                           neighbour(n4, 0, 1)};
  const CapEdge right[4] = {neighbour(n14, 0, 2.0 / 3), neighbour(n14, 2.0 / 3, 1.0 / 3),
                            neighbour(n7, 0, 1.0 / 3), neighbour(n7, 1.0 / 3, 2.0 / 3)};
  const CapEdge top[4] = {neighbour(n1, 0, 2.0 / 3), neighbour(n1, 2.0 / 3, 1.0 / 3), neighbour(n2, 0, 1.0 / 3),
                          neighbour(n2, 1.0 / 3, 2.0 / 3)};
  for (int k = 0; k < 4; ++k) {
    const double sign = k % 2 == 0 ? 1.0 : -1.0;  // bubbles alternate along every side
    system.join_g1({k, o, ex, ey}, bottom[k], side_a(k), bubble(-sign / 9));
    system.join_g1({4 * k, o, ey, ex}, left[k], side_a(k), bubble(-sign / 9));
    system.join_g1({4 * k + 3, ex, ey, -ex}, right[k], side_a(k), bubble(sign / 6));
    system.join_g1({12 + k, ey, ex, -ey}, top[k], side_a(k), bubble(sign / 6));
  }
  // inside: C1 with a = ½, 1, 2 across the column and row boundaries (the middle ones are half as wide)
  const double inner_a[3] = {0.5, 1.0, 2.0};
  for (int r = 0; r < 4; ++r)
    for (int m = 1; m < 4; ++m) {
      system.join_g1({4 * r + m, o, ey, ex}, {4 * r + m - 1, ex, ey, -ex}, constant(inner_a[m - 1]), zero);
      system.join_g1({4 * m + r, o, ex, ey}, {4 * (m - 1) + r, ey, ex, -ey}, constant(inner_a[m - 1]), zero);
    }
  CapDerivation d = system.solve(Configuration::T2, 0, fairness);
  d.mask.valence = 0;
  return d;
}

}  // namespace

CapDerivation derive_t2_cap(Fairness fairness) {
  const auto start = std::chrono::steady_clock::now();
  CapDerivation d = derive_t2(fairness);
  d.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return d;
}

ConfigurationMask t2_mask() {
  static std::mutex mutex;
  static std::optional<ConfigurationMask> cache;
  const std::lock_guard<std::mutex> lock(mutex);
  if (!cache) cache = derive_t2_cap().mask;
  return *cache;
}

CapDerivation derive_t1_cap(Fairness fairness) {
  const auto start = std::chrono::steady_clock::now();
  CapDerivation d = derive_t1(fairness);
  d.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return d;
}

ConfigurationMask t1_mask() {
  static std::mutex mutex;
  static std::optional<ConfigurationMask> cache;
  const std::lock_guard<std::mutex> lock(mutex);
  if (!cache) cache = derive_t1_cap().mask;
  return *cache;
}

CapDerivation derive_t0_cap(Fairness fairness) {
  const auto start = std::chrono::steady_clock::now();
  CapDerivation d = derive_t0(fairness);
  d.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return d;
}

ConfigurationMask t0_mask() {
  static std::mutex mutex;
  static std::optional<ConfigurationMask> cache;
  const std::lock_guard<std::mutex> lock(mutex);
  if (!cache) cache = derive_t0_cap().mask;
  return *cache;
}

}  // namespace iga::basis::polyhedral
