#pragma once
// Shared by the cap-mask tests (test_polyhedral_star.cpp, test_polyhedral_ngon.cpp): independent Bézier
// evaluation of cap patches, the sector view of split caps, and reading the reference tables (which the
// tests only read, and skip without).
#include "support/paths.hpp"
#include <cmath>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include <Eigen/Dense>
#include <gtest/gtest.h>

#include "basis/polyhedral/mask.hpp"

namespace polyhedral_cap_support {

using Eigen::MatrixXd;
using Eigen::Vector3d;
using iga::basis::polyhedral::ConfigurationMask;

/// Value, ∂u, ∂v of a bi-3 Bézier patch (rows j·4 + i, i along u) at (u, v).
struct Jet {
  Vector3d x, du, dv;
};

inline double bern3(int i, double t) {
  const double c[4] = {1, 3, 3, 1};
  return c[i] * std::pow(t, i) * std::pow(1.0 - t, 3 - i);
}

inline double bern3_d(int i, double t) {  // d/dt B^3_i = 3 (B^2_{i−1} − B^2_i)
  auto b2 = [](int j, double s) {
    const double c[3] = {1, 2, 1};
    return (j < 0 || j > 2) ? 0.0 : c[j] * std::pow(s, j) * std::pow(1.0 - s, 2 - j);
  };
  return 3.0 * (b2(i - 1, t) - b2(i, t));
}

inline Jet bezier3(const MatrixXd& bb, double u, double v) {
  Jet j{Vector3d::Zero(), Vector3d::Zero(), Vector3d::Zero()};
  for (int b = 0; b < 4; ++b)
    for (int a = 0; a < 4; ++a) {
      const Vector3d p = bb.row(b * 4 + a).transpose();
      j.x += bern3(a, u) * bern3(b, v) * p;
      j.du += bern3_d(a, u) * bern3(b, v) * p;
      j.dv += bern3(a, u) * bern3_d(b, v) * p;
    }
  return j;
}

/// A bi-2 patch straight from the uniform biquadratic B-spline basis on its 3 × 3 grid (rows along w).
inline Jet bspline2_jet(const Vector3d (&grid)[3][3], double s, double w) {
  auto n2 = [](int i, double t) {
    return i == 0 ? 0.5 * (1 - t) * (1 - t) : i == 1 ? 0.5 * (-2 * t * t + 2 * t + 1) : 0.5 * t * t;
  };
  auto n2d = [](int i, double t) { return i == 0 ? -(1 - t) : i == 1 ? 1 - 2 * t : t; };
  Jet j{Vector3d::Zero(), Vector3d::Zero(), Vector3d::Zero()};
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) {
      j.x += n2(c, s) * n2(r, w) * grid[r][c];
      j.du += n2d(c, s) * n2(r, w) * grid[r][c];
      j.dv += n2(c, s) * n2d(r, w) * grid[r][c];
    }
  return j;
}

/// Partition of unity (row sums 1) and affine invariance (an affine map of the gathered points maps the BB
/// coefficients alike) of every patch of a mask, to 1e-12, with a random affine map.
inline void expect_affine_invariant(const ConfigurationMask& m, const MatrixXd& points, std::mt19937& rng,
                                    const std::string& label) {
  std::uniform_real_distribution<double> r(-1.0, 1.0);
  Eigen::Matrix3d l;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) l(i, j) = r(rng);
  const Vector3d o(r(rng), r(rng), r(rng));
  const MatrixXd mapped = (points * l.transpose()).rowwise() + o.transpose();
  for (const auto& p : m.patches) {
    EXPECT_LT((p.coefficients.rowwise().sum().array() - 1.0).abs().maxCoeff(), 1e-12) << label;
    const MatrixXd via = ((p.coefficients * points) * l.transpose()).rowwise() + o.transpose();
    EXPECT_LT((p.coefficients * mapped - via).cwiseAbs().maxCoeff(), 1e-12) << label;
  }
}

/// The cap of one net: per patch its 16 BB points.
inline std::vector<MatrixXd> apply(const ConfigurationMask& mask, const MatrixXd& points) {
  std::vector<MatrixXd> out;
  for (const auto& p : mask.patches) out.push_back(p.coefficients * points);
  return out;
}

/// Sector-level jet of a cap: sector k, sector parameters (u, v) ∈ [0, 1]²; a split cap (4n patches) picks
/// sub-patch (α, β) (α = 1 iff u > 1/2, or u = 1/2 with `right`), derivatives scaled to the sector.
inline Jet sector_jet(const std::vector<MatrixXd>& cap, int n, int k, double u, double v, bool right_u = false,
               bool right_v = false) {
  if (static_cast<int>(cap.size()) == n) return bezier3(cap[static_cast<std::size_t>(k)], u, v);
  const int alpha = (u > 0.5 || (u == 0.5 && right_u)) ? 1 : 0;
  const int beta = (v > 0.5 || (v == 0.5 && right_v)) ? 1 : 0;
  Jet j = bezier3(cap[static_cast<std::size_t>(4 * k + 2 * beta + alpha)], 2 * u - alpha, 2 * v - beta);
  j.du *= 2.0;
  j.dv *= 2.0;
  return j;
}

/// Largest distance between the surfaces of two masks over ten random nets (random_net(n, 1000 n + seed),
/// seed 1..10, with member `points`) on a 13 × 13 grid of each of the n sectors, relative to each net's
/// bounding-box diagonal. point(applied patches, k, u, v): the surface point of sector k.
template <class RandomNet, class Point>
double relative_surface_distance(const ConfigurationMask& first, const ConfigurationMask& second, int n,
                                 RandomNet random_net, Point point) {
  double worst = 0.0;
  for (unsigned seed = 1; seed <= 10; ++seed) {
    const auto net = random_net(n, 1000 * static_cast<unsigned>(n) + seed);
    const double diagonal = (net.points.colwise().maxCoeff() - net.points.colwise().minCoeff()).norm();
    const auto a = apply(first, net.points), b = apply(second, net.points);
    double d = 0.0;
    for (int k = 0; k < n; ++k)
      for (int i = 0; i <= 12; ++i)
        for (int j = 0; j <= 12; ++j)
          d = std::max(d, (point(a, k, i / 12.0, j / 12.0) - point(b, k, i / 12.0, j / 12.0)).norm());
    worst = std::max(worst, d / diagonal);
  }
  return worst;
}

inline std::filesystem::path reference_tables() {
  return std::filesystem::path(IGA_SOURCE_DIR) / ".." / "shared" / "reference" / "polyhedral" / "src" / "Patch" / "Table";
}

inline MatrixXd read_table(const std::filesystem::path& file) {
  std::ifstream in(file);
  std::vector<std::vector<double>> rows;
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    std::stringstream ss(line);
    std::string cell;
    std::vector<double> row;
    while (std::getline(ss, cell, ','))
      if (!cell.empty()) row.push_back(std::stod(cell));
    rows.push_back(row);
  }
  MatrixXd m(static_cast<Eigen::Index>(rows.size()),
             rows.empty() ? 0 : static_cast<Eigen::Index>(rows[0].size()));
  for (std::size_t i = 0; i < rows.size(); ++i)
    for (std::size_t j = 0; j < rows[i].size(); ++j)
      m(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(j)) = rows[i][j];
  return m;
}

/// The reference table eopSct<n> in our layout (mask.hpp), rows renormalised to sum 1 (README: the
/// watermark leaves row sums off by up to 4e-9). Facts about the reference layout (public repository
/// paramgupta107/polyhedral_splines, ExtraordinaryPatchConstructor / PatchBuilder, and the tables):
///  - columns: for each outgoing half-edge of v in turn, its end e_k then f_k; v last → our column j + 1,
///    and v → our column 0;
///  - rows: patch-major, 16 per patch, row i·4 + j with i the first (slow) index;
///  - n = 3, 5: reference patch p is our sector (n − p) mod n, i along our u, j along our v;
///  - n ≥ 6: reference patch 4s + a + 2b is sector (s − 1) mod n, sub-patch (α, β) = (1 − a, 1 − b),
///    with i, j running against our u, v (row i·4 + j → our row (3 − j)·4 + (3 − i)).
/// (MappedReferenceMeetsTheBi2Ring confirms the mapping geometrically.)
inline std::vector<MatrixXd> star_reference_in_our_layout(int n) {
  const MatrixXd ref = read_table(reference_tables() / ("eopSct" + std::to_string(n) + ".csv"));
  const int patches = n >= 6 ? 4 * n : n, gathered = 2 * n + 1;
  EXPECT_EQ(ref.rows(), 16 * patches);
  EXPECT_EQ(ref.cols(), gathered);
  std::vector<MatrixXd> out(static_cast<std::size_t>(patches), MatrixXd::Zero(16, gathered));
  for (int rp = 0; rp < patches; ++rp)
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 4; ++j) {
        int patch = 0, row = 0;
        if (n < 6) {
          patch = (n - rp) % n;
          row = j * 4 + i;
        } else {
          const int s = rp / 4, a = rp % 2, b = (rp % 4) / 2;
          patch = 4 * ((s + n - 1) % n) + 2 * (1 - b) + (1 - a);
          row = (3 - j) * 4 + (3 - i);
        }
        const Eigen::RowVectorXd r = ref.row(16 * rp + 4 * i + j);
        MatrixXd& target = out[static_cast<std::size_t>(patch)];
        for (int c = 0; c < gathered; ++c) target(row, c == 2 * n ? 0 : c + 1) = r(c) / r.sum();
      }
  return out;
}

/// The reference table ngonSct<n> in our layout (ngon_cap.hpp), rows renormalised to sum 1 (README: the
/// watermark leaves row sums off by up to 4e-9). Facts about the reference layout (public repository
/// paramgupta107/polyhedral_splines, NGonPatchConstructor / PatchBuilder, and the tables):
///  - columns: for each half-edge c_w → c_{w+1} of F in turn, [d_w, p_w, r_w, c_w] → our n + 3w + 1,
///    n + 3w + 2, n + 3w, w;
///  - rows: patch-major, 16 per patch, row i·4 + j; i runs from B_w's centroid toward A_w's, j toward
///    A_{w−1}'s, i.e. against our v and u: → our row (3 − j)·4 + (3 − i);
///  - n = 3, 5: reference patch w is our patch w;
///  - n ≥ 6: reference patch 4w + a + 2b is our sub-patch 4w + 2(1 − b) + (1 − a).
/// (MappedReferenceMeetsTheBi2Ring confirms the mapping geometrically.)
inline std::vector<MatrixXd> ngon_reference_in_our_layout(int n) {
  const MatrixXd ref = read_table(reference_tables() / ("ngonSct" + std::to_string(n) + ".csv"));
  const int patches = n >= 6 ? 4 * n : n, gathered = 4 * n;
  EXPECT_EQ(ref.rows(), 16 * patches);
  EXPECT_EQ(ref.cols(), gathered);
  auto column = [n](int c) {
    const int w = c / 4, r = c % 4;
    return r == 3 ? w : r == 2 ? n + 3 * w : r == 0 ? n + 3 * w + 1 : n + 3 * w + 2;
  };
  std::vector<MatrixXd> out(static_cast<std::size_t>(patches), MatrixXd::Zero(16, gathered));
  for (int rp = 0; rp < patches; ++rp)
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 4; ++j) {
        const int patch = n < 6 ? rp : 4 * (rp / 4) + 2 * (1 - (rp % 4) / 2) + (1 - rp % 2);
        const int row = (3 - j) * 4 + (3 - i);
        const Eigen::RowVectorXd r = ref.row(16 * rp + 4 * i + j);
        MatrixXd& target = out[static_cast<std::size_t>(patch)];
        for (int c = 0; c < gathered; ++c) target(row, column(c)) = r(c) / r.sum();
      }
  return out;
}

/// The reference table polarSct<n> in our layout, rows renormalised to sum 1 (README: watermark). Facts
/// about the reference layout (public repository paramgupta107/polyhedral_splines, PolarPatchConstructor:
/// gathered [P, first ring counter-clockwise], degree (3, 2); and the tables): columns = ours; patch k =
/// ours; rows patch-major, 12 per patch, row i·3 + j with i radial (i = 0 the pole) → our row j·4 + i.
/// (MappedReferenceMeetsTheRing confirms the mapping geometrically.)
inline std::vector<MatrixXd> polar_reference_in_our_layout(int n) {
  const MatrixXd ref = read_table(reference_tables() / ("polarSct" + std::to_string(n) + ".csv"));
  EXPECT_EQ(ref.rows(), 12 * n);
  EXPECT_EQ(ref.cols(), n + 1);
  std::vector<MatrixXd> out(static_cast<std::size_t>(n), MatrixXd::Zero(12, n + 1));
  for (int k = 0; k < n; ++k)
    for (int i = 0; i <= 3; ++i)
      for (int j = 0; j <= 2; ++j) {
        const Eigen::RowVectorXd r = ref.row(12 * k + 3 * i + j);
        out[static_cast<std::size_t>(k)].row(j * 4 + i) = r / r.sum();
      }
  return out;
}

/// The reference table in our layout, rows renormalised to sum 1 (README: watermark). Facts about the
/// reference layout (public repository paramgupta107/polyhedral_splines, T0/T1/T2PatchConstructor: the
/// vertices in the picture order = our columns; and the tables evaluated on the planar picture nets):
///  - T0: 4 patches of 16 rows, row i·4 + j with i running up (our V) and j right to left (against our
///    U); reference patches 0, 1, 2, 3 = bottom-left, top-left, bottom-right, top-right = our 0, 2, 1, 3;
///    so reference row 16·r + i·4 + j → our patch p(r), row i·4 + (3 − j);
///  - T1: reference patch 2α + β = our patch 4β + α, rows i·4 + j with i up (V), j right (U), as the
///    picture layout of apply (our masks themselves run along (V, U));
///  - T2: reference patch 4β + α = ours, row i·4 + j with i up (V) and j against U → our row i·4 + (3 − j).
/// (ReferenceSatisfiesRecoveredReparameterisation confirms the mapping geometrically.)
inline ConfigurationMask tjunction_reference_mask(const std::string& name) {
  const MatrixXd ref = read_table(reference_tables() / (name + ".csv"));
  const int patches = static_cast<int>(ref.rows()) / 16;
  ConfigurationMask out;
  out.gathered = static_cast<int>(ref.cols());
  out.patches.assign(static_cast<std::size_t>(patches), {3, 3, MatrixXd::Zero(16, ref.cols())});
  for (int r = 0; r < patches; ++r)
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 4; ++j) {
        int patch = 0, row = 0;
        if (name == "T0") {
          const int ours[4] = {0, 2, 1, 3};
          patch = ours[r];
          row = 4 * i + (3 - j);
        } else if (name == "T2") {
          patch = r;
          row = 4 * i + (3 - j);
        } else {
          patch = 4 * (r % 2) + r / 2;
          row = 4 * i + j;
        }
        const Eigen::RowVectorXd v = ref.row(16 * r + 4 * i + j);
        out.patches[static_cast<std::size_t>(patch)].coefficients.row(row) = v / v.sum();
      }
  return out;
}

}  // namespace polyhedral_cap_support
