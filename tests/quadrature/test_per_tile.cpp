// Per-tile rules for irregular elements: tile layout, exactness per tile, the specification parser.
#include <gtest/gtest.h>

#include <cmath>

#include "core/error.hpp"
#include "quadrature/per_tile.hpp"
#include "quadrature/rule_provider.hpp"

using namespace iga::quadrature;

TEST(PerTile, PointCountsWeightsAndNoPointAtTheVertex) {
  for (int p = 1; p <= 4; ++p) {
    for (int levels = 1; levels <= 12; ++levels) {
      const Rule r = tiled_rule(p, levels);
      EXPECT_EQ(r.size(), (3 * levels + 1) * p * p);
      EXPECT_NEAR(r.weights.sum(), 1.0, 1e-14);  // a sum of up to 592 rounded weights
      EXPECT_GT(r.points.colwise().maxCoeff().minCoeff(), 0.0);  // max(u, v) > 0 at every point
      EXPECT_GE(r.points.minCoeff(), 0.0);
      EXPECT_LE(r.points.maxCoeff(), 1.0);
    }
  }
}

// Each tile carries a p × p Gauss rule: monomials u^a v^b with a, b <= 2p-1 are integrated exactly,
// ∫∫ u^a v^b = 1/((a+1)(b+1)).
TEST(PerTile, ExactForTensorPolynomials) {
  const int p = 3;
  const Rule r = tiled_rule(p, 6);
  for (int a = 0; a <= 2 * p - 1; ++a) {
    for (int b = 0; b <= 2 * p - 1; ++b) {
      double s = 0;
      for (Eigen::Index k = 0; k < r.size(); ++k) s += r.weights(k) * std::pow(r.points(0, k), a) * std::pow(r.points(1, k), b);
      EXPECT_NEAR(s, 1.0 / ((a + 1) * (b + 1)), 1e-15);
    }
  }
}

// A function that is a different polynomial on each level, f = (u+v)^2 · 4^(l-1) with l the tile level
// (l = floor(-log2(max(u,v))) + 1), is not integrated exactly by one Gauss rule over the element but is by the
// tiled rule on levels 1..L, up to the corner square (where f = (u+v)^2 4^L with the same rule is exact too).
// Exact value: sum over levels of 4^(l-1) ∫_{level l} (u+v)^2, from ∫_{[0,s]^2} (u+v)^2 = 7 s^4 / 6.
TEST(PerTile, ExactForLevelwisePolynomials) {
  const int levels = 5;
  const Rule r = tiled_rule(2, levels);
  auto level_of = [&](double u, double v) {
    const int l = static_cast<int>(std::floor(-std::log2(std::max(u, v)))) + 1;
    return std::min(l, levels + 1);
  };
  double s = 0;
  for (Eigen::Index k = 0; k < r.size(); ++k) {
    const double u = r.points(0, k), v = r.points(1, k);
    s += r.weights(k) * (u + v) * (u + v) * std::pow(4.0, level_of(u, v) - 1);
  }
  double exact = 0;
  for (int l = 1; l <= levels; ++l) {
    const double outer = std::ldexp(1.0, 1 - l), inner = std::ldexp(1.0, -l);
    exact += std::pow(4.0, l - 1) * 7.0 / 6.0 * (std::pow(outer, 4) - std::pow(inner, 4));
  }
  exact += std::pow(4.0, levels) * 7.0 / 6.0 * std::pow(std::ldexp(1.0, -levels), 4);
  EXPECT_NEAR(s, exact, 1e-14);
}

TEST(PerTile, ProviderDispatchesOnKind) {
  const PerTile t(3, 4);
  EXPECT_EQ(t.name(), "tiles:3:4");
  iga::basis::ElementKind irregular{iga::basis::Shape::Quad, iga::basis::Family::Irregular, 5, false, iga::basis::Scheme::CatmullClark};
  EXPECT_EQ(t.rule(irregular).size(), 13 * 9);
  EXPECT_EQ(t.rule(iga::basis::ElementKind{}).size(), 9);
  auto p = make_rule_provider("tiles:2:7", 4);
  EXPECT_EQ(p->name(), "tiles:2:7");
  EXPECT_THROW(make_rule_provider("tiles:2", 4), iga::InputError);
  EXPECT_THROW(make_rule_provider("tiles:2:x", 4), iga::InputError);
  EXPECT_THROW(make_rule_provider("tiles:2:0", 4), iga::InputError);
  EXPECT_THROW(make_rule_provider("gauss:2:3", 4), iga::InputError);
}

// The tiled triangle rule (half-box elements, EF at (0,0)): point count, area 1/2, points inside, and
// monomials of total degree <= 2p - 2 exact: ∫_T u^a v^b = a! b! / (a + b + 2)!.
TEST(PerTileTriangle, CountsAreaAndMonomials) {
  for (int p = 1; p <= 4; ++p) {
    for (int levels = 1; levels <= 12; ++levels) {
      const Rule r = tiled_triangle_rule(p, levels);
      EXPECT_EQ(r.size(), (3 * levels + 1) * p * p);
      EXPECT_NEAR(r.weights.sum(), 0.5, 1e-15);
      EXPECT_GT((r.points.row(0) + r.points.row(1)).minCoeff(), 0.0);  // never at the EF corner
      EXPECT_GE(r.points.minCoeff(), 0.0);
      EXPECT_LE((r.points.row(0) + r.points.row(1)).maxCoeff(), 1.0 + 1e-15);
    }
  }
  const int p = 4;
  const Rule r = tiled_triangle_rule(p, 7);
  for (int a = 0; a <= 2 * p - 2; ++a) {
    for (int b = 0; a + b <= 2 * p - 2; ++b) {
      double s = 0.0;
      for (Eigen::Index k = 0; k < r.size(); ++k) s += r.weights(k) * std::pow(r.points(0, k), a) * std::pow(r.points(1, k), b);
      const double exact = std::tgamma(a + 1.0) * std::tgamma(b + 1.0) / std::tgamma(a + b + 3.0);
      EXPECT_NEAR(s, exact, 1e-15) << a << " " << b;
    }
  }
}

// Exact on functions that are polynomial on each layer only: f = l · u² with l = floor(-log2(u + v)) + 1 the
// layer (L + 1 on the corner triangle): ∫ = Σ_l l ∫_{layer l} u² + (L + 1) ∫_{corner} u², ∫_{u+v <= c} u² = c⁴/12.
TEST(PerTileTriangle, ExactForLayerwisePolynomials) {
  const int levels = 6;
  const Rule r = tiled_triangle_rule(3, levels);
  double s = 0.0;
  for (Eigen::Index k = 0; k < r.size(); ++k) {
    const double u = r.points(0, k), sum = r.points(0, k) + r.points(1, k);
    const int layer = std::min(static_cast<int>(std::floor(-std::log2(sum))) + 1, levels + 1);
    s += r.weights(k) * layer * u * u;
  }
  double exact = (levels + 1) * std::pow(std::ldexp(1.0, -levels), 4) / 12.0;
  for (int l = 1; l <= levels; ++l) {
    const double a = std::ldexp(1.0, -l);
    exact += l * (std::pow(2 * a, 4) - std::pow(a, 4)) / 12.0;
  }
  EXPECT_NEAR(s, exact, 1e-15);
}

// Providers serve the kinds they have rules for and name the others (never a silent plain-Gauss fallback on
// an infinitely piecewise element).
TEST(PerTileTriangle, ProvidersNameTheKindsTheyCannotServe) {
  using iga::basis::ElementKind;
  using iga::basis::Family;
  using iga::basis::Scheme;
  using iga::basis::Shape;
  const ElementKind half_box{Shape::Triangle, Family::Irregular, 5, false, Scheme::HalfBox};
  const ElementKind unknown{Shape::Quad, Family::Irregular, 5, false, Scheme::None};
  const PerTile t(3, 4);
  EXPECT_EQ(t.rule(half_box).size(), 13 * 9);
  EXPECT_EQ(t.rule(ElementKind{Shape::Triangle, Family::Regular, 6}).size(), 9);
  EXPECT_THROW(t.rule(unknown), iga::UnsupportedError);
  for (const char* spec : {"macro:2", "fitted"}) {
    const auto p = make_rule_provider(spec, 4);
    try {
      p->rule(half_box);
      ADD_FAILURE() << spec << " served a half-box element";
    } catch (const iga::UnsupportedError& e) {
      EXPECT_NE(std::string(e.what()).find("triangle/irregular:5 (half-box)"), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find(spec), std::string::npos) << e.what();
    }
    EXPECT_EQ(p->rule(ElementKind{}).size(), 16);  // polynomial quads: 4 × 4 Gauss
  }
}

// Sides of half-box EF triangles: the dyadic rule integrates functions that are polynomial on each piece
// [2^-l, 2^(1-l)] exactly: f = l · t³ (l the piece, L + 1 on [0, 2^-L]), ∫ = Σ_l l (b⁴ − a⁴)/4 over the pieces;
// the mirrored rule integrates f(1 − t). Side 1 is split at 1/2.
TEST(PerTileTriangle, SideRulesFollowTheTiles) {
  const int levels = 9;
  auto piece = [&](double t) { return std::min(static_cast<int>(std::floor(-std::log2(t))) + 1, levels + 1); };
  double exact = (levels + 1) * std::pow(std::ldexp(1.0, -levels), 4) / 4.0;
  for (int l = 1; l <= levels; ++l) exact += l * (std::pow(std::ldexp(1.0, 1 - l), 4) - std::pow(std::ldexp(1.0, -l), 4)) / 4.0;
  for (const bool toward_zero : {true, false}) {
    const Rule1D r = dyadic_line_rule(2, levels, toward_zero);
    EXPECT_EQ(r.size(), 2 * (levels + 1));
    EXPECT_NEAR(r.weights.sum(), 1.0, 1e-15);
    double s = 0.0;
    for (Eigen::Index k = 0; k < r.size(); ++k) {
      const double t = toward_zero ? r.points(k) : 1.0 - r.points(k);
      s += r.weights(k) * piece(t) * t * t * t;
    }
    EXPECT_NEAR(s, exact, 1e-15) << toward_zero;
  }
  const PerTile tiles(2, levels);
  const iga::basis::ElementKind half_box{iga::basis::Shape::Triangle, iga::basis::Family::Irregular, 5, false,
                                         iga::basis::Scheme::HalfBox};
  EXPECT_EQ(tiles.side_rule(half_box, 0).size(), 2 * (levels + 1));
  EXPECT_EQ(tiles.side_rule(half_box, 2).points(0), 1.0 - tiles.side_rule(half_box, 0).points(0));
  const Rule1D& mid = tiles.side_rule(half_box, 1);
  EXPECT_EQ(mid.size(), 4);
  EXPECT_LT(mid.points(1), 0.5);
  EXPECT_GT(mid.points(2), 0.5);
  EXPECT_EQ(&tiles.side_rule(iga::basis::ElementKind{}, 0), &tiles.edge_rule());  // polynomial elements
}
