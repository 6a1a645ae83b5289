// Boehm and Oslo knot insertion (basis/bspline/spline_curve.hpp) against the Cox–de Boor curve and each other.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "basis/bspline/knot_insertion.hpp"
#include "core/error.hpp"
#include "random_splines.hpp"

using namespace iga;
using namespace iga::basis::bspline;
using iga::refine::test::cox_de_boor;
using iga::refine::test::random_curve;
using iga::refine::test::rel_diff;

namespace {

// Knots with gaps spread over `spread` (log-uniform), interior multiplicities 1..p, clamped or with simple
// unclamped ends.
SplineCurve spread_curve(std::mt19937& rng, int p, int breaks, double spread, bool clamped) {
  std::uniform_real_distribution<double> lg(0.0, std::log(spread)), coord(-1.0, 1.0);
  std::uniform_int_distribution<int> mult(1, p);
  SplineCurve c;
  c.degree = p;
  double x = 0.0;
  for (int i = 0; i <= p; ++i) c.knots.push_back(clamped ? 0.0 : (x += std::exp(lg(rng))));
  if (clamped) x = 0.0;
  for (int b = 0; b < breaks; ++b) {
    x += std::exp(lg(rng));
    for (int m = mult(rng); m > 0; --m) c.knots.push_back(x);
  }
  x += std::exp(lg(rng));
  for (int i = 0; i <= p; ++i) c.knots.push_back(clamped ? x : (x += std::exp(lg(rng))));
  c.control_points.resize(static_cast<Index>(c.knots.size()) - p - 1, 2);
  for (Index i = 0; i < c.control_points.size(); ++i) c.control_points(i) = coord(rng);
  return c;
}

// de Boor's triangle for the point at x on the interval mu: an independent reference for evaluate().
Eigen::VectorXd de_boor(const SplineCurve& c, Index mu, double x) {
  const int p = c.degree;
  Eigen::MatrixXd d = c.control_points.middleRows(mu - p, p + 1);
  for (int r = 1; r <= p; ++r) {
    for (int j = p; j >= r; --j) {
      const double ti = c.knots[static_cast<std::size_t>(mu - p + j)];
      const double a = (x - ti) / (c.knots[static_cast<std::size_t>(mu + 1 + j - r)] - ti);
      d.row(j) = (1.0 - a) * d.row(j - 1) + a * d.row(j);
    }
  }
  return d.row(p).transpose();
}

// Boehm's and Oslo's refinements of c by the same `count` knots, uniform in the domain.
struct Refined {
  SplineCurve boehm, oslo;
};
Refined refine_both(std::mt19937& rng, const SplineCurve& c, int count) {
  std::uniform_real_distribution<double> at(c.domain_begin(), c.domain_end());
  std::vector<double> xs;
  for (int i = 0; i < count; ++i) xs.push_back(at(rng));
  return {insert_knots_boehm(c, xs), insert_knots_oslo(c, xs)};
}

}  // namespace

TEST(KnotInsertion, BoehmEqualsOsloAndKeepsTheCurve) {
  std::mt19937 rng(20240501);
  for (int p = 1; p <= 9; ++p) {
    for (int trial = 0; trial < 5; ++trial) {
      const SplineCurve c = random_curve(rng, p, 1 + trial);
      const auto [b, o] = refine_both(rng, c, 4);
      ASSERT_EQ(b.knots, o.knots);
      std::uniform_real_distribution<double> at(c.domain_begin(), c.domain_end());
      EXPECT_LE(rel_diff(b.control_points, o.control_points), 1e-12) << "degree " << p;
      for (int s = 0; s < 10; ++s) {
        const double x = at(rng);
        EXPECT_LE(rel_diff(cox_de_boor(b, x), cox_de_boor(c, x)), 1e-12);
        EXPECT_LE(rel_diff(evaluate(c, x), cox_de_boor(c, x)), 1e-12);
      }
    }
  }
}

// The one-sweep multi-knot insertion equals single-knot Boehm insertions one after the other, including
// repeated knots, knots at existing knots and a knot in every interval.
TEST(KnotInsertion, SweepEqualsSingleInsertions) {
  std::mt19937 rng(7);
  for (int p = 1; p <= 7; ++p) {
    const SplineCurve c = random_curve(rng, p, 3);
    std::uniform_real_distribution<double> at(c.domain_begin(), c.domain_end());
    std::vector<double> xs = {at(rng), at(rng), c.knots[static_cast<std::size_t>(p + 1)]};
    xs.push_back(xs[0]);
    for (Index mu : domain_intervals(c)) {
      xs.push_back(0.5 * (c.knots[static_cast<std::size_t>(mu)] + c.knots[static_cast<std::size_t>(mu) + 1]));
    }
    SplineCurve one = c;
    for (double x : xs) one = insert_knot_boehm(one, x);
    const SplineCurve all = insert_knots_boehm(c, xs);
    ASSERT_EQ(all.knots, one.knots) << p;
    EXPECT_LE(rel_diff(all.control_points, one.control_points), 1e-13) << p;
  }
}

TEST(KnotInsertion, ValidationNamesTheProblem) {
  SplineCurve c;
  c.degree = 2;
  c.knots = {0, 0, 0, 1, 1, 1};
  c.control_points = Eigen::MatrixXd::Zero(3, 2);
  EXPECT_NO_THROW(validate(c));
  SplineCurve bad = c;
  bad.knots = {0, 0, 0, 1, 0.5, 1};
  EXPECT_THROW(validate(bad), InputError);
  bad = c;
  bad.control_points = Eigen::MatrixXd::Zero(4, 2);
  EXPECT_THROW(validate(bad), InputError);
  bad = c;
  bad.knots = {0, 0, 0, 0, 1, 1, 1};
  bad.control_points = Eigen::MatrixXd::Zero(4, 2);
  EXPECT_THROW(validate(bad), InputError);
  bad = c;
  bad.control_points(1, 1) = std::nan("");
  EXPECT_THROW(validate(bad), InputError);
  EXPECT_THROW(insert_knot_boehm(c, 2.0), InputError);
  // Multiplicity above degree + 1: at the clamped ends at once, inside after three copies (one is fine, a
  // triple knot 0.5 has multiplicity 3 = degree + 1).
  EXPECT_THROW(insert_knot_boehm(c, 1.0), InputError);
  EXPECT_THROW(insert_knots_boehm(c, {0.5, 0.0}), InputError);
  EXPECT_THROW(insert_knots_oslo(c, {1.0}), InputError);
  EXPECT_NO_THROW(insert_knots_boehm(c, {0.5, 0.5, 0.5}));
  EXPECT_NO_THROW(insert_knots_oslo(c, {0.5, 0.5, 0.5}));
  EXPECT_THROW(insert_knots_boehm(c, {0.5, 0.5, 0.5, 0.5}), InputError);
  EXPECT_THROW(insert_knots_oslo(c, {0.5, 0.5, 0.5, 0.5}), InputError);
  EXPECT_THROW(insert_knots_boehm(bad, {0.5}), InputError);  // the curve itself is checked
}

// The Oslo rows take the coarse piece of [tau_j, tau_{j+1}) (its mirror image before an unclamped domain), so
// no factor extrapolates: Oslo equals Boehm's convex combinations to rounding for knot gaps spread over 10^3
// (the earlier choice, the piece nearest the middle of the support, gave errors up to 4e-9 clamped and 3e7
// unclamped on such knots). insert_knots_oslo and refinement_matrix (oslo_matrix) are the same rows, summed in
// another order.
TEST(KnotInsertion, OsloIsStableForIrregularKnots) {
  std::mt19937 rng(5);
  for (bool clamped : {true, false}) {
    for (int trial = 0; trial < 400; ++trial) {
      const int p = 1 + trial % 9;
      const SplineCurve c = spread_curve(rng, p, 1 + trial % 13, 1000.0, clamped);
      const auto [b, o] = refine_both(rng, c, 6);
      ASSERT_EQ(b.knots, o.knots);
      EXPECT_LE((o.control_points - b.control_points).cwiseAbs().maxCoeff(), 1e-14)
          << "degree " << p << (clamped ? " clamped" : " unclamped") << " trial " << trial;
      const Eigen::MatrixXd by_matrix = oslo_matrix(p, c.knots, o.knots) * c.control_points;
      EXPECT_LE((by_matrix - o.control_points).cwiseAbs().maxCoeff(), 1e-14);
    }
  }
}

// evaluate() (basis_functions on the knot window) against de Boor's triangle, on unclamped knots too.
TEST(KnotInsertion, EvaluateEqualsDeBoor) {
  std::mt19937 rng(6);
  for (bool clamped : {true, false}) {
    for (int trial = 0; trial < 100; ++trial) {
      const SplineCurve c = spread_curve(rng, 1 + trial % 9, 1 + trial % 7, 10.0, clamped);
      std::uniform_real_distribution<double> at(c.domain_begin(), c.domain_end());
      for (int s = 0; s < 10; ++s) {
        const double x = s == 0 ? c.domain_begin() : s == 1 ? c.domain_end() : at(rng);
        const Index mu = find_span(c.degree, c.knots, x);
        EXPECT_LE(rel_diff(evaluate(c, x), de_boor(c, mu, x)), 1e-13) << "degree " << c.degree;
      }
    }
  }
}
