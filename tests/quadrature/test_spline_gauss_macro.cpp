// Strip and macro-element rules (quadrature/spline_gauss/macro_rule.hpp): the thesis's point counts,
// exactness on the patch spaces, and agreement with the per-tile rule on the element.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <functional>
#include <random>
#include <vector>

#include "core/error.hpp"
#include "quadrature/gauss_legendre.hpp"
#include "quadrature/per_tile.hpp"
#include "quadrature/spline_gauss/generator.hpp"
#include "quadrature/spline_gauss/macro_rule.hpp"

using namespace iga::quadrature;
using namespace iga::quadrature::spline_gauss;

namespace {
Eigen::Index patch_points(int r, SpaceDegrees s) { return macro_patch_rule(r, s).size(); }
// Per-tile points on levels 1..r: 3 tiles per level, n × n Gauss each (tiled_rule without its corner square).
Eigen::Index per_tile_points(int n, int r) { return tiled_rule(n, r).size() - n * n; }
}  // namespace

// Thesis lines 8441-8446: r = 3 macro element for subdivision splines (3,2)×(3,2): 4 × 3 = 12 points vs per-tile
// 3 · 3 · (2 × 2) = 36 on the same region (levels 1..3).
TEST(MacroRule, ThesisCountSubdivisionR3) {
  Rule1D s, l;
  macro_patch_rule(3, rule_space(Space::Subdivision), &s, &l);
  EXPECT_EQ(l.size(), 4);
  EXPECT_EQ(s.size(), 3);
  EXPECT_EQ(patch_points(3, rule_space(Space::Subdivision)), 12);
  EXPECT_EQ(per_tile_points(2, 3), 36);
  // the strip (r = 1, Fig. 4.7, lines 8455-8462): 3 × 2
  EXPECT_EQ(patch_points(1, rule_space(Space::Subdivision)), 6);
}

// Thesis lines 8640-8642 (dimensions at 8610-8616): area strip (5,1)×(5,1): 7 · 3 = 21 vs 3 · (3 × 3) = 27 points per level; volume strip
// via the superspace (9,1)×(9,1): 13 · 5 = 65 vs 3 · (5 × 5) = 75 points per level.
TEST(MacroRule, ThesisCountsAreaAndVolumeStrips) {
  EXPECT_EQ(patch_points(1, rule_space(Space::Area)), 21);
  EXPECT_EQ(per_tile_points(3, 1), 27);
  EXPECT_EQ(patch_points(1, rule_space(Space::Volume)), 65);
  EXPECT_EQ(per_tile_points(5, 1), 75);
}

// Thesis lines 8653-8658: Poisson stiffness, r = 2 with the superspace (6,1)×(6,1): 6 · 11 = 66 vs
// 2 · 3 · (4 × 4) = 96. The thesis also states "(4 · 10) + (6 · 7) = 72" for using both (4,1)×(6,2) and
// (6,2)×(4,1); the factors reproduce (short (4,1): 4, long (6,2): 10 [dimension 19, odd: superspace 20];
// short (6,2): 6 [dimension 11 -> 12], long (4,1): 7) but the sum is 82, not 72.
TEST(MacroRule, ThesisCountsPoisson) {
  EXPECT_EQ(patch_points(2, rule_space(Space::Poisson)), 66);
  EXPECT_EQ(per_tile_points(4, 2), 96);
  auto count = [](const std::vector<double>& br, int p, int c) {
    return gaussian_rule(p, br, std::vector<int>(br.size() - 2, c)).size();
  };
  const auto s = short_side_breaks(2), l = long_side_breaks(2);
  EXPECT_EQ(count(s, 4, 1), 4);
  EXPECT_EQ(count(l, 6, 2), 10);
  EXPECT_EQ(count(s, 6, 2), 6);
  EXPECT_EQ(count(l, 4, 1), 7);
  EXPECT_EQ(count(s, 4, 1) * count(l, 6, 2) + count(s, 6, 2) * count(l, 4, 1), 82);
}

// Which r is cheapest per level (thesis line 8610: r = 1 for area and volume; line 8653: r = 2 for Poisson).
TEST(MacroRule, CheapestRPerLevel) {
  for (Space sp : {Space::Subdivision, Space::Area, Space::Volume, Space::Poisson}) {
    double best = 1e9;
    int best_r = 0;
    for (int r = 1; r <= 6; ++r) {
      const double per_level = static_cast<double>(patch_points(r, rule_space(sp))) / r;
      std::printf("%-12s r=%d points/patch=%3ld per level=%6.2f\n", to_string(sp).c_str(), r,
                  static_cast<long>(patch_points(r, rule_space(sp))), per_level);
      if (per_level < best - 1e-12) best = per_level, best_r = r;
    }
    if (sp == Space::Area || sp == Space::Volume) {
      EXPECT_EQ(best_r, 1) << to_string(sp);
    }
    if (sp == Space::Poisson) {
      EXPECT_EQ(best_r, 2);
    }
  }
}

// Every tensor B-spline N_i(u) M_j(v) of the patch space is integrated exactly by the (unfolded) patch rule.
TEST(MacroRule, PatchRuleExactOnPatchSpace) {
  for (Space sp : {Space::Subdivision, Space::Area, Space::Volume, Space::Poisson}) {
    const SpaceDegrees d = rule_space(sp);
    for (int r = 1; r <= 5; ++r) {
      const auto su = short_side_breaks(r), sv = long_side_breaks(r);
      const auto tu = open_knots(d.degree, su, std::vector<int>(su.size() - 2, d.continuity));
      const auto tv = open_knots(d.degree, sv, std::vector<int>(sv.size() - 2, d.continuity));
      const auto iu = bspline_integrals(d.degree, tu), iv = bspline_integrals(d.degree, tv);
      const Rule rule = macro_patch_rule(r, d);
      Eigen::MatrixXd acc = Eigen::MatrixXd::Zero(static_cast<Eigen::Index>(iu.size()), static_cast<Eigen::Index>(iv.size()));
      std::vector<double> bu, bv;
      for (Eigen::Index k = 0; k < rule.size(); ++k) {
        bspline_values(d.degree, tu, rule.points(0, k), bu);
        bspline_values(d.degree, tv, rule.points(1, k), bv);
        for (std::size_t i = 0; i < bu.size(); ++i)
          for (std::size_t j = 0; j < bv.size(); ++j) acc(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(j)) += rule.weights(k) * bu[i] * bv[j];
      }
      double err = 0;
      for (std::size_t i = 0; i < iu.size(); ++i)
        for (std::size_t j = 0; j < iv.size(); ++j)
          err = std::max(err, std::abs(acc(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(j)) - iu[i] * iv[j]));
      EXPECT_LE(err, 1e-15) << to_string(sp) << " r " << r;
      std::printf("%-12s r=%d max B-spline moment error %.2e\n", to_string(sp).c_str(), r, err);
    }
  }
}

TEST(MacroRule, FoldedRuleLayout) {
  for (Space sp : {Space::Subdivision, Space::Area, Space::Volume, Space::Poisson}) {
    for (int r = 1; r <= 4; ++r) {
      for (int levels : {1, 5, 8}) {
        const Rule rule = macro_rule(r, levels, sp);
        const int nc = (rule_space(sp).degree + 2) / 2;
        const int patches = covered_levels(r, levels) / r;
        EXPECT_EQ(rule.size(), patches * macro_patch_rule(r, rule_space(sp)).size() + nc * nc);
        EXPECT_NEAR(rule.weights.sum(), 1.0, 1e-14);
        EXPECT_GE(rule.points.minCoeff(), 0.0);
        EXPECT_LE(rule.points.maxCoeff(), 1.0);
        EXPECT_GT(rule.points.colwise().maxCoeff().minCoeff(), 0.0);
        EXPECT_GT(rule.weights.minCoeff(), 0.0);
      }
    }
  }
  EXPECT_EQ(covered_levels(3, 8), 9);
  EXPECT_EQ(covered_levels(2, 8), 8);
}

// On the element: four elements around a valence-4 vertex form [-1,1]² (element k maps (u,v) to R^k (u,v), R the
// rotation by 90°, which matches Stam's edge sharing). A global F that is a polynomial of the target degree on
// every tile and C^c across tile edges is integrated by the sum of the folded per-element macro rules exactly,
// as by the per-tile rule and as the exact integral.
namespace {
using Fn = std::function<double(double, double)>;
double sum_over_elements(const Rule& rule, const Fn& f) {
  double s = 0;
  for (int k = 0; k < 4; ++k) {
    for (Eigen::Index i = 0; i < rule.size(); ++i) {
      double x = rule.points(0, i), y = rule.points(1, i);
      for (int j = 0; j < k; ++j) {
        const double t = x;
        x = -y;
        y = t;
      }
      s += rule.weights(i) * f(x, y);
    }
  }
  return s;
}
}  // namespace

TEST(MacroRule, ElementSumMatchesPerTileAndExact) {
  std::mt19937 gen(3);
  std::uniform_real_distribution<double> coef(-1.0, 1.0);
  double worst_global = 0, worst_bump = 0;
  for (Space sp : {Space::Subdivision, Space::Area, Space::Volume, Space::Poisson}) {
    const SpaceDegrees d = rule_space(sp);
    const int nc = (d.degree + 2) / 2;
    for (int r = 1; r <= 4; ++r) {
      const int levels = 6;
      const Rule macro = macro_rule(r, levels, sp);
      const Rule tiles = tiled_rule(nc, covered_levels(r, levels));
      // (a) a global tensor spline of the space on the breaks {-1, -1/2, 0, 1/2, 1} in x and y.
      const auto t = open_knots(d.degree, {-1, -0.5, 0, 0.5, 1}, {d.continuity, d.continuity, d.continuity});
      const auto ints = bspline_integrals(d.degree, t);
      const auto n = static_cast<Eigen::Index>(ints.size());
      Eigen::MatrixXd c(n, n);
      for (Eigen::Index i = 0; i < n; ++i)
        for (Eigen::Index j = 0; j < n; ++j) c(i, j) = coef(gen);
      double exact = 0;
      for (Eigen::Index i = 0; i < n; ++i)
        for (Eigen::Index j = 0; j < n; ++j) exact += c(i, j) * ints[static_cast<std::size_t>(i)] * ints[static_cast<std::size_t>(j)];
      const Fn f = [&](double x, double y) {
        std::vector<double> bx, by;
        bspline_values(d.degree, t, x, bx);
        bspline_values(d.degree, t, y, by);
        const Eigen::Map<Eigen::VectorXd> vx(bx.data(), n), vy(by.data(), n);
        return vx.dot(c * vy);
      };
      const double m = sum_over_elements(macro, f), p = sum_over_elements(tiles, f);
      worst_global = std::max({worst_global, std::abs(m - exact), std::abs(m - p)});
      EXPECT_NEAR(m, exact, 1e-14) << to_string(sp) << " r " << r;
      EXPECT_NEAR(m, p, 1e-14) << to_string(sp) << " r " << r;
      // (b) for C^1 spaces of degree >= 5: bumps (x-a)_+^2 (b-x)_+^2 (y+h)_+^2 (h-y)_+^2 (1 + x - y/2) with
      // a = 2^-l, b = 2^(2-l), h = 2^(1-l): per tile a polynomial, C^1 across every tile edge, on levels l >= 2.
      if (d.continuity == 1 && d.degree >= 5) {
        for (int l = 2; l <= covered_levels(r, levels); ++l) {
          const double a = std::ldexp(1.0, -l), b = std::ldexp(1.0, 2 - l), h = std::ldexp(1.0, 1 - l);
          auto pos = [](double z) { return z > 0 ? z : 0.0; };
          const Fn g = [&](double x, double y) {
            return std::pow(pos(x - a) * pos(b - x), 2) * std::pow(pos(y + h) * pos(h - y), 2) * (1 + x - 0.5 * y);
          };
          // exact: separable pieces, 8-point Gauss on [a, min(b,1)] × [-h, h] (degree <= 5 per variable)
          const Rule1D gl = gauss_legendre(8);
          const double xb = std::min(b, 1.0);
          double ex = 0;
          for (Eigen::Index i = 0; i < gl.size(); ++i)
            for (Eigen::Index j = 0; j < gl.size(); ++j)
              ex += gl.weights(i) * gl.weights(j) * (xb - a) * 2 * h *
                    g(a + (xb - a) * gl.points(i), -h + 2 * h * gl.points(j));
          const double gm = sum_over_elements(macro, g), gp = sum_over_elements(tiles, g);
          // relative to the integral (the bumps are as small as 2^(-10 l))
          const double scale = std::abs(ex);
          worst_bump = std::max({worst_bump, std::abs(gm - ex) / scale, std::abs(gm - gp) / scale});
          EXPECT_LE(std::abs(gm - ex), 1e-13 * scale) << to_string(sp) << " r " << r << " l " << l;
          EXPECT_LE(std::abs(gm - gp), 1e-13 * scale) << to_string(sp) << " r " << r << " l " << l;
        }
      }
    }
  }
  std::printf("global splines: max abs error %.2e; bumps: max rel error %.2e\n", worst_global, worst_bump);
}

TEST(MacroRule, ProviderDispatchAndNames) {
  const MacroPatch mp(2);
  EXPECT_EQ(mp.name(), "macro:2");
  EXPECT_EQ(MacroPatch(3, 6).name(), "macro:3:6");
  const iga::basis::ElementKind irregular{iga::basis::Shape::Quad, iga::basis::Family::Irregular, 5, false, iga::basis::Scheme::CatmullClark};
  const iga::basis::ElementKind regular{};
  const iga::basis::ElementKind tri{iga::basis::Shape::Triangle, iga::basis::Family::Regular, 6};
  EXPECT_EQ(mp.rule(irregular).size(), 4 * 66 + 16);
  EXPECT_EQ(mp.rule(regular).size(), 16);
  EXPECT_EQ(mp.rule(tri).size(), 16);
  EXPECT_EQ(mp.edge_rule().size(), 4);
  const auto p = make_macro_patch(1, 3);
  EXPECT_EQ(p->name(), "macro:1:3");
  EXPECT_THROW(MacroPatch(0), iga::InputError);
  EXPECT_THROW(MacroPatch(2, 0), iga::InputError);
}
