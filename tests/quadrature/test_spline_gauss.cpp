// Gaussian rules for univariate spline spaces (quadrature/spline_gauss/generator.hpp): counts, exactness,
// feasibility, the knot vectors of the thesis (Fig. 4.7, Fig. 4.8) and input checking.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "core/error.hpp"
#include "quadrature/spline_gauss/generator.hpp"

using namespace iga::quadrature;
using namespace iga::quadrature::spline_gauss;

namespace {

std::vector<double> scaled(std::vector<double> t, double s) {
  for (double& x : t) x /= s;
  return t;
}

// Feasible (increasing interior nodes, positive weights) and exact on the space's B-splines.
void expect_gaussian(const Rule1D& r, int p, const std::vector<double>& t, Eigen::Index expected_points) {
  EXPECT_EQ(r.size(), expected_points);
  for (Eigen::Index i = 0; i < r.size(); ++i) {
    EXPECT_GT(r.points(i), t.front());
    EXPECT_LT(r.points(i), t.back());
    EXPECT_GT(r.weights(i), 0.0);
    if (i > 0) {
      EXPECT_GT(r.points(i), r.points(i - 1));
    }
  }
  EXPECT_LE(moment_residual(r, p, t), 1e-14 * (t.back() - t.front()));
  // polynomials of degree <= p (in the space whenever the knots are open) integrate exactly
  const double a = t.front(), b = t.back();
  for (int k = 0; k <= p; ++k) {
    double s = 0;
    for (Eigen::Index i = 0; i < r.size(); ++i) s += r.weights(i) * std::pow(r.points(i) - a, k);
    EXPECT_NEAR(s, std::pow(b - a, k + 1) / (k + 1), 1e-14 * std::pow(b - a, k + 1)) << "degree " << k;
  }
}

}  // namespace

TEST(SplineGauss, BSplineBasicsPartitionOfUnityAndIntegrals) {
  const std::vector<double> t = {0, 0, 0, 0, 1, 2, 3, 3, 3, 3};
  std::vector<double> v, d;
  for (double x : {0.0, 0.3, 1.0, 1.7, 2.5, 3.0}) {
    bspline_values(3, t, x, v, &d);
    double s = 0, sd = 0;
    for (std::size_t j = 0; j < v.size(); ++j) s += v[j], sd += d[j];
    EXPECT_NEAR(s, 1.0, 1e-15);
    EXPECT_NEAR(sd, 0.0, 1e-14);
  }
  const auto ints = bspline_integrals(3, t);
  double s = 0;
  for (double x : ints) s += x;
  EXPECT_NEAR(s, 3.0, 1e-15);
}

// Thesis Fig. 4.7 (lines 8455-8462): the long side of the strip, (3,2) on [0,0,0,0,1,2,3,3,3,3]/2,
// 6 B-splines, 3 points (symmetric).
TEST(SplineGauss, StripLongSideCubicC2ThreePoints) {
  const auto t = scaled({0, 0, 0, 0, 1, 2, 3, 3, 3, 3}, 2);
  const Rule1D r = gaussian_rule(3, t);
  expect_gaussian(r, 3, t, 3);
  EXPECT_NEAR(r.points(0) + r.points(2), 1.5, 1e-14);
  EXPECT_NEAR(r.points(1), 0.75, 1e-14);
  EXPECT_NEAR(r.weights(0), r.weights(2), 1e-14);
}

// Thesis Fig. 4.8 (lines 8463-8466): the r = 3 macro element, long side [0,0,0,0,4,6,7,8,9,9,9,9]/8 -> 4 points,
// short side [0,0,0,0,4,6,7,7,7,7]/8 -> 3 points.
TEST(SplineGauss, MacroElementR3KnotVectorsOfFigure48) {
  const auto tl = scaled({0, 0, 0, 0, 4, 6, 7, 8, 9, 9, 9, 9}, 8);
  const auto ts = scaled({0, 0, 0, 0, 4, 6, 7, 7, 7, 7}, 8);
  expect_gaussian(gaussian_rule(3, tl), 3, tl, 4);
  expect_gaussian(gaussian_rule(3, ts), 3, ts, 3);
}

// Thesis lines 8610-8616: area strip long side (5,1) on three intervals, dimension 14 -> 7 points; volume long side
// (8,1), dimension 23 (odd: here the superspace with one inserted knot, 12 points — the thesis mentions a
// 12-point Gauss–Radau rule) and the superspace (9,1), dimension 26 -> 13 points.
TEST(SplineGauss, AreaAndVolumeStripLongSides) {
  const std::vector<double> br = {0, 1, 2, 3};
  const auto t51 = open_knots(5, br, {1, 1});
  EXPECT_EQ(t51.size() - 6, 14u);
  expect_gaussian(gaussian_rule(5, t51), 5, t51, 7);
  const auto t81 = open_knots(8, br, {1, 1});
  EXPECT_EQ(t81.size() - 9, 23u);
  const Rule1D r81 = gaussian_rule(8, t81);
  expect_gaussian(r81, 8, t81, 12);  // exact on the (8,1) space itself
  const auto t91 = open_knots(9, br, {1, 1});
  EXPECT_EQ(t91.size() - 10, 26u);
  expect_gaussian(gaussian_rule(9, t91), 9, t91, 13);
}

TEST(SplineGauss, PolynomialSpaceIsGaussLegendre) {
  for (int p = 0; p <= 12; ++p) {
    const auto t = open_knots(p, {0.25, 2.0}, {});
    expect_gaussian(gaussian_rule(p, t), p, t, (p + 2) / 2);
  }
}

// Random open and non-open knot vectors of degrees 1..9 and various continuities.
TEST(SplineGauss, RandomSpaces) {
  std::mt19937 gen(7);
  std::uniform_real_distribution<double> len(0.2, 2.0);
  for (int p = 1; p <= 9; ++p) {
    for (int trial = 0; trial < 6; ++trial) {
      const int k = 1 + trial;  // intervals
      std::vector<double> br = {0};
      for (int i = 0; i < k; ++i) br.push_back(br.back() + len(gen));
      std::vector<int> c;
      for (int i = 1; i < k; ++i) c.push_back(static_cast<int>(gen() % static_cast<unsigned>(p)));
      const auto t = open_knots(p, br, c);
      const int m = static_cast<int>(t.size()) - p - 1;
      const Rule1D r = gaussian_rule(p, t);
      SCOPED_TRACE("p " + std::to_string(p) + " intervals " + std::to_string(k));
      expect_gaussian(r, p, t, k == 1 ? (p + 2) / 2 : (m + 1) / 2);
    }
  }
  // non-open: uniform cubic knots 0..10 (7 B-splines; superspace 8 -> 4 points on [0,10])
  std::vector<double> t;
  for (int i = 0; i <= 10; ++i) t.push_back(i);
  const Rule1D r = gaussian_rule(3, t);
  EXPECT_EQ(r.size(), 4);
  EXPECT_LE(moment_residual(r, 3, t), 1e-13);
}

TEST(SplineGauss, RejectsBadInput) {
  EXPECT_THROW(gaussian_rule(3, std::vector<double>{0, 0, 1}), iga::InputError);
  EXPECT_THROW(gaussian_rule(2, std::vector<double>{0, 0, 0, 0, 1, 1, 1}), iga::InputError);
  EXPECT_THROW(gaussian_rule(2, std::vector<double>{0, 1, 0.5, 2}), iga::InputError);
  EXPECT_THROW(open_knots(2, {0, 1, 2}, {}), iga::InputError);
  EXPECT_THROW(open_knots(2, {0, 1, 2}, {2}), iga::InputError);
}
