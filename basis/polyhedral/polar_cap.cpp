#include "basis/polyhedral/polar_cap.hpp"

#include <array>
#include <chrono>
#include <cmath>
#include <map>
#include <mutex>
#include <numbers>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include <Eigen/Dense>

namespace iga::basis::polyhedral {
namespace {

constexpr int kDegreeU = 3;  // radial
constexpr int kDegreeV = 2;  // circular
constexpr int kCoefficients = (kDegreeU + 1) * (kDegreeV + 1);
/// Relative singular-value threshold of the rank decisions (as g1_cap.cpp).

void check_valence(int n) {
  if (n < 3 || n > 8) throw std::invalid_argument("polar cap: valence " + std::to_string(n) + " is not in 3..8");
}

int wrap(int k, int n) { return ((k % n) + n) % n; }

/// The linear system over [12n unknown BB coefficients | n + 1 gathered vertices]; each row states
/// row · (x, g) = 0.
class PolarSystem {
 public:
  explicit PolarSystem(int n) : n_(n), unknowns_(kCoefficients * n) {}

  int unknowns() const { return unknowns_; }
  Eigen::RowVectorXd row() const { return Eigen::RowVectorXd::Zero(unknowns_ + n_ + 1); }
  /// Column of b_ij of patch k.
  int b(int k, int i, int j) const { return kCoefficients * wrap(k, n_) + j * (kDegreeU + 1) + i; }
  /// Column of a gathered vertex: P (−1) or q_m.
  int pole() const { return unknowns_; }
  int q(int m) const { return unknowns_ + 1 + wrap(m, n_); }
  void add(const Eigen::RowVectorXd& r) {
    const double norm = r.norm();
    if (norm > 0.0) rows_.push_back(r / norm);
  }
  const std::vector<Eigen::RowVectorXd>& rows() const { return rows_; }

 private:
  int n_, unknowns_;
  std::vector<Eigen::RowVectorXd> rows_;
};

/// BB coefficient j (circular) of BB row w (w = 0: the shared boundary, w = 1: the next row) of the bi-2
/// patch of q_k, as a row over the gathered columns. Its uniform biquadratic B-spline grid: row 0 = P, P, P
/// (the collapsed fan triangles), row 1 = q_{k−1}, q_k, q_{k+1} (row 2, outside the configuration, affects
/// neither the boundary nor ∂_w there). B-spline → Bézier per direction: ((c0+c1)/2, c1, (c1+c2)/2).
void add_ring(PolarSystem& s, Eigen::RowVectorXd& r, int k, int w, int j, double factor) {
  const double t[3][3] = {{0.5, 0.5, 0.0}, {0.0, 1.0, 0.0}, {0.0, 0.5, 0.5}};
  const double tw[2][2] = {{0.5, 0.5}, {0.0, 1.0}};  // BB rows 0, 1 from B-spline rows 0, 1
  for (int c = 0; c < 3; ++c) {
    r(s.pole()) += factor * tw[w][0] * t[j][c];
    r(s.q(k - 1 + c)) += factor * tw[w][1] * t[j][c];
  }
}

PolarSystem constraints(int n) {
  PolarSystem s(n);
  for (int k = 0; k < n; ++k) {
    for (int j = 0; j <= kDegreeV; ++j) {
      // C0 to the bi-2 patch of q_k: b_3j = its BB coefficient (w = 0, j)
      Eigen::RowVectorXd r = s.row();
      r(s.b(k, 3, j)) = 1.0;
      add_ring(s, r, k, 0, j, -1.0);
      s.add(r);
      // C1: ∂_u p_k(1, ·) = ½ ∂_w r_k(·, 0), i.e. 3 (b_3j − b_2j) = ½ · 2 (BB_1j − BB_0j)
      r = s.row();
      r(s.b(k, 3, j)) = 3.0;
      r(s.b(k, 2, j)) = -3.0;
      add_ring(s, r, k, 1, j, -1.0);
      add_ring(s, r, k, 0, j, 1.0);
      s.add(r);
    }
    for (int i = 0; i <= kDegreeU; ++i) {
      // C1 to patch k + 1 along the spoke P q_{k+1} direction (v = 1 of k, v = 0 of k + 1)
      Eigen::RowVectorXd r = s.row();
      r(s.b(k, i, 2)) = 1.0;
      r(s.b(k + 1, i, 0)) = -1.0;
      s.add(r);
      r = s.row();
      r(s.b(k, i, 2)) += 1.0;
      r(s.b(k, i, 1)) -= 1.0;
      r(s.b(k + 1, i, 1)) -= 1.0;
      r(s.b(k + 1, i, 0)) += 1.0;
      s.add(r);
    }
    // collapse: b_0j of every patch = b_00 of patch 0 (the pole X)
    for (int j = 0; j <= kDegreeV; ++j) {
      if (k == 0 && j == 0) continue;
      Eigen::RowVectorXd r = s.row();
      r(s.b(k, 0, j)) = 1.0;
      r(s.b(0, 0, 0)) = -1.0;
      s.add(r);
    }
  }
  // removable singularity: c_k = b_11 of patch k is X + U cos θ_k + V sin θ_k (θ_k = 2πk/n)
  Eigen::RowVectorXd mean = s.row();
  for (int k = 0; k < n; ++k) mean(s.b(k, 1, 1)) = 1.0;
  mean(s.b(0, 0, 0)) = -static_cast<double>(n);
  s.add(mean);
  for (int m = 2; 2 * m <= n; ++m) {
    Eigen::RowVectorXd rc = s.row(), rs = s.row();
    for (int k = 0; k < n; ++k) {
      const double angle = 2.0 * std::numbers::pi * m * k / n;
      rc(s.b(k, 1, 1)) = std::cos(angle);
      rs(s.b(k, 1, 1)) = std::sin(angle);
    }
    s.add(rc);
    if (2 * m != n) s.add(rs);  // for 2m = n the sine mode vanishes identically
  }
  return s;
}

}  // namespace

CapDerivation derive_polar_cap(int n, Fairness fairness) {
  check_valence(n);
  const auto start = std::chrono::steady_clock::now();
  CapDerivation d = solve_cap_constraints(constraints(n).rows(), n, kDegreeU, kDegreeV, n + 1, fairness,
                                          "polar cap, n = " + std::to_string(n));
  d.mask.configuration = Configuration::Polar;
  d.mask.valence = n;
  d.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return d;
}

ConfigurationMask polar_mask(int n) {
  check_valence(n);
  static std::mutex mutex;
  static std::map<int, ConfigurationMask> cache;
  const std::lock_guard<std::mutex> lock(mutex);
  auto it = cache.find(n);
  if (it == cache.end()) it = cache.emplace(n, derive_polar_cap(n).mask).first;
  return it->second;
}

}  // namespace iga::basis::polyhedral
