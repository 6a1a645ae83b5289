// T0, T1 and T2 caps of the polyhedral bi-3 splines (basis/polyhedral/tjunction_cap.hpp).
//
// Checked on random 3D nets (the T0 / T1 / T2 pictures of configuration.hpp, jittered) against quantities computed
// here, independently of the derivation: the cap's patches with their own Bernstein formula, the seven bi-2
// (T0), nine (T1) or ten (T2) neighbours straight from the uniform biquadratic B-spline basis on their full 3 × 3 grids (the row away
// from the cap random, not gathered), and (4) of Peters–Lo–Karčiauskas with the reparameterisations
// recovered from the reference table (ReferenceSatisfiesRecoveredReparameterisation checks the recovery).
//
// The reference tables T0.csv, T1.csv, T2.csv (../shared/reference/polyhedral, non-commercial licence) are only
// read at test time; the tests that need them skip when they are absent.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iostream>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include <Eigen/Dense>

#include "basis/polyhedral/tjunction_cap.hpp"

#include "basis/polyhedral_cap_support.hpp"

namespace {

using polyhedral_cap_support::read_table;
using polyhedral_cap_support::reference_tables;
using polyhedral_cap_support::tjunction_reference_mask;

using Eigen::MatrixXd;
using Eigen::Vector2d;
using Eigen::Vector3d;
using iga::basis::polyhedral::ConfigurationMask;

/// One bi-2 neighbour: its B-spline grid rows (row 0 nearest the cap; row 2 outside the configuration,
/// random), s along the cap's U (bottom, top) or V (left, right).
struct Neighbour {
  int vertex;
  std::array<std::array<int, 3>, 2> rows;
};

/// A shared boundary: cap patch q's edge (origin + t·along, cross into q), the other side (neighbour index
/// or cap patch), and the reparameterisation of (4) (tjunction_cap.hpp).
struct Join {
  int q;
  Vector2d qo, qa, qc;
  bool p_is_cap;
  int p;
  Vector2d po, pa, pc;
  std::function<double(double)> a, b;
};

/// One T-configuration as the tests see it: picture positions of the gathered vertices, neighbours, joins.
struct Config {
  std::string name;
  std::vector<Vector2d> picture;
  std::vector<Neighbour> neighbours;
  std::vector<Join> joins;
};

std::function<double(double)> constant(double c) {
  return [c](double) { return c; };
}
std::function<double(double)> linear(double c0, double c1) {
  return [c0, c1](double t) { return c0 + c1 * t; };
}
std::function<double(double)> bubble(double c) {
  return [c](double t) { return c * t * (1 - t); };
}

const Config& t0() {
  static const Config c = [] {
    const Vector2d o(0, 0), ex(1, 0), ey(0, 1);
    Config k;
    k.name = "T0";
    k.picture = {{-1, 1},   {0, 1},    {1, 1},     {-1, 0},    {0, 0},    {1, 0},    {-1.5, -1},
                 {-0.5, -1}, {0.5, -1}, {1.5, -1}, {-1.5, -2}, {-0.5, -2}, {0.5, -2}, {1.5, -2}};
    k.neighbours = {{11, {{{6, 7, 8}, {10, 11, 12}}}}, {12, {{{7, 8, 9}, {11, 12, 13}}}},
                    {6, {{{11, 7, 4}, {10, 6, 3}}}},   {3, {{{7, 4, 1}, {6, 3, 0}}}},
                    {9, {{{12, 8, 4}, {13, 9, 5}}}},   {5, {{{8, 4, 1}, {9, 5, 2}}}},
                    {1, {{{3, 4, 5}, {0, 1, 2}}}}};
    k.joins = {{0, o, ex, ey, false, 0, o, ex, ey, constant(1), bubble(-0.25)},
               {1, o, ex, ey, false, 1, o, ex, ey, constant(1), bubble(0.25)},
               {0, o, ey, ex, false, 2, o, ex, ey, linear(1, -0.25), constant(0)},
               {2, o, ey, ex, false, 3, o, ex, ey, linear(0.75, -0.25), constant(0)},
               {1, ex, ey, -ex, false, 4, o, ex, ey, linear(1, -0.25), constant(0)},
               {3, ex, ey, -ex, false, 5, o, ex, ey, linear(0.75, -0.25), constant(0)},
               {2, ey, ex, -ey, false, 6, o, 0.5 * ex, ey, constant(1), bubble(0.5)},
               {3, ey, ex, -ey, false, 6, 0.5 * ex, 0.5 * ex, ey, constant(1), bubble(-0.5)},
               {1, o, ey, ex, true, 0, ex, ey, -ex, constant(1), constant(0)},
               {3, o, ey, ex, true, 2, ex, ey, -ex, constant(1), constant(0)},
               {2, o, ex, ey, true, 0, ey, ex, -ey, constant(1), constant(0)},
               {3, o, ex, ey, true, 1, ey, ex, -ey, constant(1), constant(0)}};
    return k;
  }();
  return c;
}

const Config& t1() {
  static const Config c = [] {
    const Vector2d o(0, 0), ex(1, 0), ey(0, 1);
    Config k;
    k.name = "T1";
    for (int i = 0; i < 4; ++i) k.picture.push_back({i - 1.5, 3});
    for (int i = 0; i < 4; ++i) k.picture.push_back({i - 1.5, 2});
    for (int i = 0; i < 5; ++i) k.picture.push_back({i - 2.0, 1});
    for (int i = 0; i < 5; ++i) k.picture.push_back({i - 2.0, 0});
    k.neighbours = {{14, {{{8, 9, 10}, {13, 14, 15}}}},  {15, {{{9, 10, 11}, {14, 15, 16}}}},
                    {16, {{{10, 11, 12}, {15, 16, 17}}}}, {8, {{{14, 9, 5}, {13, 8, 4}}}},
                    {4, {{{9, 5, 1}, {8, 4, 0}}}},        {12, {{{16, 11, 6}, {17, 12, 7}}}},
                    {7, {{{11, 6, 2}, {12, 7, 3}}}},      {1, {{{4, 5, 6}, {0, 1, 2}}}},
                    {2, {{{5, 6, 7}, {1, 2, 3}}}}};
    k.joins = {{0, o, ex, ey, false, 0, o, ex, ey, constant(1), bubble(-1.0 / 6)},
               {1, o, ex, ey, false, 1, o, 0.5 * ex, ey, constant(1), bubble(1.0 / 6)},
               {2, o, ex, ey, false, 1, 0.5 * ex, 0.5 * ex, ey, constant(1), bubble(-1.0 / 6)},
               {3, o, ex, ey, false, 2, o, ex, ey, constant(1), bubble(1.0 / 6)},
               {0, o, ey, ex, false, 3, o, ex, ey, linear(1, -1.0 / 6), constant(0)},
               {4, o, ey, ex, false, 4, o, ex, ey, linear(5.0 / 6, -1.0 / 6), constant(0)},
               {3, ex, ey, -ex, false, 5, o, ex, ey, linear(1, -1.0 / 6), constant(0)},
               {7, ex, ey, -ex, false, 6, o, ex, ey, linear(5.0 / 6, -1.0 / 6), constant(0)},
               {4, ey, ex, -ey, false, 7, o, 2.0 / 3 * ex, ey, constant(1), bubble(0.25)},
               {5, ey, ex, -ey, false, 7, 2.0 / 3 * ex, 1.0 / 3 * ex, ey, constant(1), bubble(-0.25)},
               {6, ey, ex, -ey, false, 8, o, 1.0 / 3 * ex, ey, constant(1), bubble(0.25)},
               {7, ey, ex, -ey, false, 8, 1.0 / 3 * ex, 2.0 / 3 * ex, ey, constant(1), bubble(-0.25)}};
    const double column_a[3] = {0.5, 1.0, 2.0};
    for (int beta = 0; beta < 2; ++beta)
      for (int alpha = 1; alpha < 4; ++alpha)
        k.joins.push_back({4 * beta + alpha, o, ey, ex, true, 4 * beta + alpha - 1, ex, ey, -ex,
                           constant(column_a[alpha - 1]), constant(0)});
    for (int alpha = 0; alpha < 4; ++alpha)
      k.joins.push_back({4 + alpha, o, ex, ey, true, alpha, ey, ex, -ey, constant(1), constant(0)});
    return k;
  }();
  return c;
}

const Config& t2() {
  static const Config c = [] {
    const Vector2d o(0, 0), ex(1, 0), ey(0, 1);
    Config k;
    k.name = "T2";
    k.picture = {{0, 4}, {1, 4}, {3, 4}, {4, 4}, {0, 3}, {1, 3}, {3, 3}, {4, 3}, {0, 2}, {1, 2},
                 {0, 1}, {1, 1}, {2, 1}, {3, 1}, {4, 1}, {0, 0}, {1, 0}, {2, 0}, {3, 0}, {4, 0}};
    k.neighbours = {{16, {{{10, 11, 12}, {15, 16, 17}}}}, {17, {{{11, 12, 13}, {16, 17, 18}}}},
                    {18, {{{12, 13, 14}, {17, 18, 19}}}}, {10, {{{16, 11, 9}, {15, 10, 8}}}},
                    {8, {{{11, 9, 5}, {10, 8, 4}}}},      {4, {{{9, 5, 1}, {8, 4, 0}}}},
                    {14, {{{18, 13, 6}, {19, 14, 7}}}},   {7, {{{13, 6, 2}, {14, 7, 3}}}},
                    {1, {{{4, 5, 6}, {0, 1, 2}}}},        {2, {{{5, 6, 7}, {1, 2, 3}}}}};
    // per side: (neighbour, s0, ds) of the quarters k = 0..3
    struct Piece {
      int n;
      double s0, ds;
    };
    const Piece bottom[4] = {{0, 0, 1}, {1, 0, 0.5}, {1, 0.5, 0.5}, {2, 0, 1}};
    const Piece left[4] = {{3, 0, 1}, {4, 0, 0.5}, {4, 0.5, 0.5}, {5, 0, 1}};
    const Piece right[4] = {{6, 0, 2.0 / 3}, {6, 2.0 / 3, 1.0 / 3}, {7, 0, 1.0 / 3}, {7, 1.0 / 3, 2.0 / 3}};
    const Piece top[4] = {{8, 0, 2.0 / 3}, {8, 2.0 / 3, 1.0 / 3}, {9, 0, 1.0 / 3}, {9, 1.0 / 3, 2.0 / 3}};
    const double a0[4] = {1.0, 8.0 / 9, 5.0 / 6, 7.0 / 9}, a1[4] = {-1.0 / 9, -1.0 / 18, -1.0 / 18, -1.0 / 9};
    for (int q = 0; q < 4; ++q) {
      const double sign = q % 2 == 0 ? 1.0 : -1.0;
      const auto a = linear(a0[q], a1[q]);
      k.joins.push_back({q, o, ex, ey, false, bottom[q].n, bottom[q].s0 * ex, bottom[q].ds * ex, ey, a,
                         bubble(-sign / 9)});
      k.joins.push_back({4 * q, o, ey, ex, false, left[q].n, left[q].s0 * ex, left[q].ds * ex, ey, a,
                         bubble(-sign / 9)});
      k.joins.push_back({4 * q + 3, ex, ey, -ex, false, right[q].n, right[q].s0 * ex, right[q].ds * ex, ey, a,
                         bubble(sign / 6)});
      k.joins.push_back({12 + q, ey, ex, -ey, false, top[q].n, top[q].s0 * ex, top[q].ds * ex, ey, a,
                         bubble(sign / 6)});
    }
    const double inner_a[3] = {0.5, 1.0, 2.0};
    for (int r = 0; r < 4; ++r)
      for (int m = 1; m < 4; ++m) {
        k.joins.push_back({4 * r + m, o, ey, ex, true, 4 * r + m - 1, ex, ey, -ex, constant(inner_a[m - 1]),
                           constant(0)});
        k.joins.push_back({4 * m + r, o, ex, ey, true, 4 * (m - 1) + r, ey, ex, -ey, constant(inner_a[m - 1]),
                           constant(0)});
      }
    return k;
  }();
  return c;
}

struct Net {
  MatrixXd points;                                 ///< gathered × 3
  std::vector<std::array<Vector3d, 3>> outer;      ///< row 2 of each neighbour's grid
};

Net random_net(const Config& c, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> r(-1.0, 1.0);
  Net net;
  const auto m = static_cast<Eigen::Index>(c.picture.size());
  net.points.resize(m, 3);
  for (Eigen::Index i = 0; i < m; ++i)
    net.points.row(i) = Vector3d(c.picture[static_cast<std::size_t>(i)].x() + 0.2 * r(rng),
                                 c.picture[static_cast<std::size_t>(i)].y() + 0.2 * r(rng), 0.5 * r(rng));
  net.outer.resize(c.neighbours.size());
  for (auto& o : net.outer)
    for (auto& p : o) p = Vector3d(3 * r(rng), 3 * r(rng), 0.5 * r(rng));
  return net;
}

// ---- independent evaluation -------------------------------------------------------------------------

using polyhedral_cap_support::bspline2_jet;
using polyhedral_cap_support::Jet;
using polyhedral_cap_support::expect_affine_invariant;

Vector3d along(const Jet& j, const Vector2d& d) { return d(0) * j.du + d(1) * j.dv; }

Jet bezier3(const MatrixXd& bb, const Vector2d& x) { return polyhedral_cap_support::bezier3(bb, x(0), x(1)); }

/// Neighbour k (index into cfg.neighbours) at (s, w) from the uniform biquadratic B-spline basis.
Jet bi2_jet(const Config& cfg, const Net& net, int k, const Vector2d& x) {
  const Neighbour& nb = cfg.neighbours[static_cast<std::size_t>(k)];
  Vector3d grid[3][3];
  for (int r = 0; r < 2; ++r)
    for (int c = 0; c < 3; ++c)
      grid[r][c] = net.points.row(nb.rows[static_cast<std::size_t>(r)][static_cast<std::size_t>(c)]).transpose();
  for (int c = 0; c < 3; ++c) grid[2][c] = net.outer[static_cast<std::size_t>(k)][static_cast<std::size_t>(c)];
  return bspline2_jet(grid, x(0), x(1));
}

struct Residuals {
  double c0 = 0, g1 = 0;
};

Residuals residuals(const Config& cfg, const std::vector<MatrixXd>& cap, const Net& net) {
  Residuals res;
  for (const Join& j : cfg.joins)
    for (int m = 0; m < 17; ++m) {
      const double t = (m + 0.37) / 17;
      const Jet q = bezier3(cap[static_cast<std::size_t>(j.q)], j.qo + t * j.qa);
      const Jet p = j.p_is_cap ? bezier3(cap[static_cast<std::size_t>(j.p)], j.po + t * j.pa)
                               : bi2_jet(cfg, net, j.p, j.po + t * j.pa);
      res.c0 = std::max(res.c0, (q.x - p.x).norm());
      const Vector3d g1 = along(q, j.qc) + j.a(t) * along(p, j.pc) - j.b(t) * along(p, j.pa);
      res.g1 = std::max(res.g1, g1.norm());
    }
  return res;
}

/// The cap's BB points in the picture's (U, V) sub-patch layout (row j·4 + i, i along U). T1 patches run
/// along (V, U) (tjunction_cap.hpp: its picture is clockwise), so `transposed` swaps them back.
std::vector<MatrixXd> apply(const ConfigurationMask& mask, const MatrixXd& points, bool transposed = false) {
  std::vector<MatrixXd> out;
  for (const auto& p : mask.patches) {
    MatrixXd x = p.coefficients * points;
    if (transposed) {
      const MatrixXd c = x;
      for (int j = 0; j < 4; ++j)
        for (int i = 0; i < 4; ++i) x.row(i * 4 + j) = c.row(j * 4 + i);
    }
    out.push_back(x);
  }
  return out;
}

// ---- tests ----------------------------------------------------------------------------------------------

struct Case {
  const Config* config;
  ConfigurationMask (*mask)();
  iga::basis::polyhedral::CapDerivation (*derive)(iga::basis::polyhedral::Fairness);
  iga::basis::polyhedral::Configuration type;
  int patches, gathered, null_dimension;
  bool transposed;  ///< patches run along (V, U) of the picture
};

std::vector<Case> cases() {
  using namespace iga::basis::polyhedral;
  return {{&t0(), &t0_mask, &derive_t0_cap, Configuration::T0, 4, 14, 4, false},
          {&t1(), &t1_mask, &derive_t1_cap, Configuration::T1, 8, 18, 12, true},
          {&t2(), &t2_mask, &derive_t2_cap, Configuration::T2, 16, 20, 36, false}};
}

TEST(PolyhedralTJunction, Shapes) {
  for (const Case& c : cases()) {
    const ConfigurationMask m = c.mask();
    EXPECT_EQ(m.configuration, c.type);
    EXPECT_EQ(m.gathered, c.gathered);
    ASSERT_EQ(static_cast<int>(m.patches.size()), c.patches);
    for (const auto& p : m.patches) {
      EXPECT_EQ(p.degree_u, 3);
      EXPECT_EQ(p.degree_v, 3);
      EXPECT_EQ(p.coefficients.rows(), 16);
      EXPECT_EQ(p.coefficients.cols(), c.gathered);
    }
  }
}

TEST(PolyhedralTJunction, ConstraintsConsistentAndNullSpace) {
  for (const Case& c : cases()) {
    const auto d = c.derive(iga::basis::polyhedral::Fairness::ThirdDerivatives);
    EXPECT_EQ(d.rank, d.rank_augmented) << c.config->name;
    EXPECT_LT(d.constraint_residual, 1e-10) << c.config->name;
    EXPECT_EQ(d.null_dimension, c.null_dimension) << c.config->name;
    std::cout << "[" << c.config->name << "] unknowns " << d.unknowns << ", equations " << d.equations
              << ", rank " << d.rank << ", null space " << d.null_dimension << ", derivation " << d.seconds
              << " s\n";
  }
}

TEST(PolyhedralTJunction, G1AcrossEveryBoundaryOnRandomNets) {
  for (const Case& c : cases()) {
    const ConfigurationMask m = c.mask();
    for (unsigned seed = 1; seed <= 5; ++seed) {
      const Net net = random_net(*c.config, 100 + seed);
      const Residuals r = residuals(*c.config, apply(m, net.points, c.transposed), net);
      EXPECT_LT(r.c0, 1e-12) << c.config->name << ", seed " << seed;
      EXPECT_LT(r.g1, 1e-10) << c.config->name << ", seed " << seed;
    }
  }
}

TEST(PolyhedralTJunction, PartitionOfUnityAndLinearPrecision) {
  std::mt19937 rng(5);
  for (const Case& c : cases()) {
    const ConfigurationMask m = c.mask();
    const Net net = random_net(*c.config, 77);
    expect_affine_invariant(m, net.points, rng, c.config->name);
  }
}

// ---- comparison with the reference tables -----------------------------------------------------------




bool have_reference() { return std::filesystem::exists(reference_tables() / "T0.csv"); }

TEST(PolyhedralTJunction, ReferenceSatisfiesRecoveredReparameterisation) {
  // The reparameterisations of tjunction_cap.hpp are facts about the reference surfaces: they satisfy C0
  // and (4) with them up to the tables' watermark (~1e-10 entrywise).
  if (!have_reference()) GTEST_SKIP() << "reference tables not present";
  for (const Case& c : cases()) {
    const ConfigurationMask ref = tjunction_reference_mask(c.config->name);
    ASSERT_EQ(static_cast<int>(ref.patches.size()), c.patches);
    ASSERT_EQ(ref.gathered, c.gathered);
    for (unsigned seed = 1; seed <= 3; ++seed) {
      const Net net = random_net(*c.config, 31 + seed);
      const Residuals r = residuals(*c.config, apply(ref, net.points), net);
      EXPECT_LT(r.c0, 1e-8) << c.config->name << ", seed " << seed;
      EXPECT_LT(r.g1, 1e-7) << c.config->name << ", seed " << seed;
    }
  }
}

TEST(PolyhedralTJunction, CloseToTheReferenceSurfaces) {
  if (!have_reference()) GTEST_SKIP() << "reference tables not present";
  for (const Case& c : cases()) {
    const ConfigurationMask ours = c.mask(), ref = tjunction_reference_mask(c.config->name);
    double worst = 0.0;
    for (unsigned seed = 1; seed <= 10; ++seed) {
      const Net net = random_net(*c.config, 1000 + seed);
      const double diagonal = (net.points.colwise().maxCoeff() - net.points.colwise().minCoeff()).norm();
      const auto a = apply(ours, net.points, c.transposed), b = apply(ref, net.points);
      double d = 0.0;
      for (std::size_t k = 0; k < a.size(); ++k)
        for (int i = 0; i <= 12; ++i)
          for (int j = 0; j <= 12; ++j) {
            const Vector2d x(i / 12.0, j / 12.0);
            d = std::max(d, (bezier3(a[k], x).x - bezier3(b[k], x).x).norm());
          }
      worst = std::max(worst, d / diagonal);
    }
    std::cout << "[" << c.config->name << "] max distance to the reference surface / bounding-box diagonal "
              << "(10 random nets): " << worst << "\n";
    EXPECT_LT(worst, 2e-2) << c.config->name;
  }
}

}  // namespace
