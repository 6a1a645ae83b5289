// Boehm and Oslo knot insertion (refine/knot_insertion.hpp) against the Cox–de Boor curve and each other.
#include <gtest/gtest.h>

#include "core/error.hpp"
#include "random_splines.hpp"

using namespace iga;
using namespace iga::refine;
using iga::refine::test::cox_de_boor;
using iga::refine::test::random_curve;
using iga::refine::test::rel_diff;

TEST(KnotInsertion, BoehmEqualsOsloAndKeepsTheCurve) {
  std::mt19937 rng(20240501);
  for (int p = 1; p <= 9; ++p) {
    for (int trial = 0; trial < 5; ++trial) {
      const SplineCurve c = random_curve(rng, p, 1 + trial);
      std::uniform_real_distribution<double> at(c.domain_begin(), c.domain_end());
      std::vector<double> xs;
      for (int i = 0; i < 4; ++i) xs.push_back(at(rng));
      const SplineCurve b = insert_knots_boehm(c, xs);
      const SplineCurve o = insert_knots_oslo(c, xs);
      ASSERT_EQ(b.knots, o.knots);
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
