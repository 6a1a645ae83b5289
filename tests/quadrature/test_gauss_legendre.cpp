// Gauss–Legendre and tensor/triangle rules against exact integrals of monomials.
#include <gtest/gtest.h>

#include <cmath>

#include "core/error.hpp"
#include "quadrature/gauss_legendre.hpp"
#include "quadrature/rule_provider.hpp"
#include "quadrature/tensor_rule.hpp"

using namespace iga::quadrature;

// ∫_0^1 x^k dx = 1/(k+1): exact for k <= 2n-1, relative error <= 1e-14.
TEST(GaussLegendre, IntegratesMonomialsOfDegree2nMinus1) {
  for (int n = 1; n <= 40; ++n) {
    const Rule1D r = gauss_legendre(n);
    ASSERT_EQ(r.size(), n);
    for (int k = 0; k <= 2 * n - 1; ++k) {
      const double exact = 1.0 / (k + 1);
      double sum = 0;
      for (int i = 0; i < n; ++i) sum += r.weights(i) * std::pow(r.points(i), k);
      EXPECT_LE(std::abs(sum - exact) / exact, 1e-14) << "n = " << n << ", k = " << k;
    }
  }
}

// The rule is not exact for degree 2n: the remainder for x^{2n} on [0,1] is the closed form
// (n!)^4 / ((2n+1) ((2n)!)^2) (the Gauss error term with f^(2n) = (2n)!). Checks that the test above can fail.
TEST(GaussLegendre, RemainderForDegree2nIsTheClosedForm) {
  for (int n = 1; n <= 8; ++n) {
    const Rule1D r = gauss_legendre(n);
    double sum = 0;
    for (int i = 0; i < n; ++i) sum += r.weights(i) * std::pow(r.points(i), 2 * n);
    double nf = 1, n2f = 1;
    for (int k = 2; k <= n; ++k) nf *= k;
    for (int k = 2; k <= 2 * n; ++k) n2f *= k;
    const double remainder = std::pow(nf, 4) / ((2 * n + 1) * n2f * n2f);
    EXPECT_NEAR((1.0 / (2 * n + 1) - sum) / remainder, 1.0, 1e-5) << n;
  }
}

TEST(GaussLegendre, PointsAscendInsideSymmetricWeightsPositive) {
  for (int n = 1; n <= 40; ++n) {
    const Rule1D r = gauss_legendre(n);
    for (int i = 0; i < n; ++i) {
      EXPECT_GT(r.points(i), 0.0);
      EXPECT_LT(r.points(i), 1.0);
      EXPECT_GT(r.weights(i), 0.0);
      EXPECT_NEAR(r.points(i) + r.points(n - 1 - i), 1.0, 1e-15);
      EXPECT_NEAR(r.weights(i), r.weights(n - 1 - i), 1e-15);
      if (i > 0) {
        EXPECT_LT(r.points(i - 1), r.points(i));
      }
    }
  }
  // Known nodes: the 2-point rule on [-1,1] has ±1/sqrt(3).
  const Rule1D r2 = gauss_legendre(2);
  EXPECT_NEAR(r2.points(0), 0.5 - 0.5 / std::sqrt(3.0), 1e-16);
  EXPECT_THROW(gauss_legendre(0), iga::InputError);
}

// ∫∫_[0,1]^2 x^a y^b = 1/((a+1)(b+1)).
TEST(TensorRule, IntegratesTensorMonomials) {
  const Rule r = tensor_rule(gauss_legendre(3), gauss_legendre(4));
  for (int a = 0; a <= 5; ++a) {
    for (int b = 0; b <= 7; ++b) {
      double sum = 0;
      for (Eigen::Index k = 0; k < r.size(); ++k) sum += r.weights(k) * std::pow(r.points(0, k), a) * std::pow(r.points(1, k), b);
      EXPECT_NEAR(sum, 1.0 / ((a + 1) * (b + 1)), 1e-15);
    }
  }
}

// ∫_T u^a v^b = a! b! / (a+b+2)! on the unit triangle.
TEST(TriangleRule, IntegratesMonomialsOfTotalDegree2nMinus2) {
  const int n = 4;
  const Rule r = collapsed_triangle_rule(gauss_legendre(n), gauss_legendre(n));
  auto fact = [](int k) { double f = 1; for (int i = 2; i <= k; ++i) f *= i; return f; };
  for (int a = 0; a <= 2 * n - 2; ++a) {
    for (int b = 0; a + b <= 2 * n - 2; ++b) {
      double sum = 0;
      for (Eigen::Index k = 0; k < r.size(); ++k) sum += r.weights(k) * std::pow(r.points(0, k), a) * std::pow(r.points(1, k), b);
      EXPECT_NEAR(sum, fact(a) * fact(b) / fact(a + b + 2), 1e-15) << a << " " << b;
    }
  }
}

TEST(RuleProvider, ParsesSpecifications) {
  auto p = make_rule_provider("gauss:5", 2);
  EXPECT_EQ(p->name(), "gauss:5");
  EXPECT_EQ(p->rule({}).size(), 25);
  EXPECT_EQ(p->edge_rule().size(), 5);
  EXPECT_EQ(make_rule_provider("gauss", 3)->name(), "gauss:3");
  EXPECT_THROW(make_rule_provider("gauss:x", 3), iga::InputError);
  EXPECT_THROW(make_rule_provider("gauss:0", 3), iga::InputError);
  EXPECT_THROW(make_rule_provider("simpson:3", 3), iga::InputError);
}
