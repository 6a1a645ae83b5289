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
}
