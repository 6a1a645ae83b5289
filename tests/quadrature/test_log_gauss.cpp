// Gauss rules for ∫_0^1 f(x) (−ln x) dx (BEM's weakly singular integrals, thesis (4.51)) against closed forms.
#include <gtest/gtest.h>

#include <cmath>

#include "core/error.hpp"
#include "quadrature/log_gauss.hpp"

namespace {

using iga::quadrature::log_gauss_rule;

TEST(LogGauss, ExactForPolynomialsOfDegreeTwoNMinusOne) {
  // ∫_0^1 x^k (−ln x) dx = 1 / (k + 1)².
  for (int n = 1; n <= 40; ++n) {
    const iga::quadrature::Rule1D r = log_gauss_rule(n);
    ASSERT_EQ(r.size(), n);
    EXPECT_GT(r.points.minCoeff(), 0.0);
    EXPECT_LT(r.points.maxCoeff(), 1.0);
    EXPECT_GT(r.weights.minCoeff(), 0.0);
    for (int k = 0; k <= 2 * n - 1; ++k) {
      const double exact = 1.0 / ((k + 1.0) * (k + 1.0));
      const double q = r.weights.dot(r.points.array().pow(k).matrix());
      EXPECT_NEAR(q / exact, 1.0, 2e-13) << "n " << n << ", x^" << k;
      if (n <= 20) {
        EXPECT_NEAR(q, exact, 1e-14) << "n " << n << ", x^" << k;  // issue 13: absolute, up to n = 20
      }
    }
    // Degree 2n is not integrated exactly (the rule is Gauss, not better).
    const double exact = 1.0 / ((2.0 * n + 1) * (2.0 * n + 1));
    EXPECT_GT(std::abs(r.weights.dot(r.points.array().pow(2 * n).matrix()) / exact - 1.0), 1e-15) << n;
  }
}

TEST(LogGauss, PublishedTwoPointRule) {
  // Abramowitz and Stegun, Table 25.7 (∫_0^1 ln(1/x) f(x) dx), n = 2, to the 18 digits quoted in issue 13;
  // compared to a few units of double rounding.
  const iga::quadrature::Rule1D r = log_gauss_rule(2);
  EXPECT_NEAR(r.points(0), 0.112008806166976183, 2e-16);
  EXPECT_NEAR(r.points(1), 0.602276908118738103, 4e-16);
  EXPECT_NEAR(r.weights(0), 0.718539319030384441, 4e-16);
  EXPECT_NEAR(r.weights(1), 0.281460680969615559, 4e-16);
}

TEST(LogGauss, SmoothIntegrandConvergesToTheClosedForm) {
  // ∫_0^1 cos(x) (−ln x) dx = Si(1) (by parts) = 0.946083070367183.
  const double si1 = 0.9460830703671830;
  double error6 = 0;
  for (int n : {3, 6, 10}) {
    const iga::quadrature::Rule1D r = log_gauss_rule(n);
    const double q = r.weights.dot(r.points.array().cos().matrix());
    if (n == 6) error6 = std::abs(q - si1);
    if (n == 10) {
      EXPECT_NEAR(q, si1, 1e-15);
    }
  }
  EXPECT_LT(error6, 1e-14);
}

TEST(LogGauss, RefusesBadSizes) {
  EXPECT_THROW(log_gauss_rule(0), iga::InputError);
  EXPECT_THROW(log_gauss_rule(41), iga::InputError);
}

}  // namespace
