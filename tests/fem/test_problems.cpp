// The built-in manufactured problems' expressions (what reports record as the problem that ran) evaluate to the
// same u and f as their closed-form C++ functions: two independent codings of each formula, compared at points
// all over [0, 2]^2 and for two reaction coefficients.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "fem/expression.hpp"
#include "fem/problems.hpp"

namespace {

using iga::fem::Expression;

TEST(ManufacturedProblems, ExpressionsEvaluateToTheFunctions) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> coordinate(0.0, 2.0);
  Eigen::Matrix3Xd x(3, 200);
  for (Eigen::Index k = 0; k < x.cols(); ++k) x.col(k) << coordinate(rng), coordinate(rng), 0.0;
  for (const std::string& name : iga::fem::manufactured_problem_names()) {
    for (const double c : {0.0, 2.5}) {
      SCOPED_TRACE(name + ", c = " + std::to_string(c));
      const iga::fem::ManufacturedProblem p = iga::fem::manufactured_problem(name, c);
      ASSERT_FALSE(p.exact_expression.empty());
      ASSERT_FALSE(p.source_expression.empty());
      Eigen::VectorXd u, u_text, f, f_text;
      p.exact->values(x, u);
      Expression(p.exact_expression, "exact").values(x, u_text);
      p.source->values(x, f);
      Expression(p.source_expression, "source").values(x, f_text);
      for (Eigen::Index k = 0; k < x.cols(); ++k) {
        EXPECT_NEAR(u_text(k), u(k), 1e-13 * (1.0 + std::abs(u(k)))) << "at (" << x(0, k) << ", " << x(1, k) << ")";
        EXPECT_NEAR(f_text(k), f(k), 1e-13 * (1.0 + std::abs(f(k)))) << "at (" << x(0, k) << ", " << x(1, k) << ")";
      }
    }
  }
}

}  // namespace
