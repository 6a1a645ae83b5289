// muparser expressions: values, constants, normals, errors that name the option, threads.
#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <thread>
#include <vector>

#include "core/error.hpp"
#include "fem/expression.hpp"
#include "fem/function.hpp"

using namespace iga;

TEST(Expression, EvaluatesInBatches) {
  const fem::Expression e("sin(pi*x)*cos(y) + z^2 + atan2(y, x) + pow(2, 3)", "--source");
  Eigen::Matrix3Xd x(3, 2);
  x << 0.25, 1.0, 0.5, 2.0, 3.0, -1.0;
  Eigen::VectorXd v;
  e.values(x, v);
  for (int k = 0; k < 2; ++k) {
    const double ex = std::sin(M_PI * x(0, k)) * std::cos(x(1, k)) + x(2, k) * x(2, k) + std::atan2(x(1, k), x(0, k)) + 8;
    EXPECT_NEAR(v(k), ex, 1e-14);
  }
}

TEST(Expression, NormalVariablesAndFiniteDifferenceGradient) {
  const fem::Expression e("x*nx + y*ny", "--neumann", true);
  Eigen::Matrix3Xd x(3, 1), n(3, 1);
  x << 2, 3, 0;
  n << 0.6, 0.8, 0;
  Eigen::VectorXd v;
  e.values(x, n, v);
  EXPECT_NEAR(v(0), 2 * 0.6 + 3 * 0.8, 1e-15);
  // The default gradient is a fourth-order difference: exact for cubics up to rounding.
  const fem::Expression c("x^3 - 2*x*y^2 + z", "--exact");
  Eigen::Matrix3Xd g;
  c.gradients(x, g);
  EXPECT_NEAR(g(0, 0), 3 * 4 - 2 * 9, 1e-9);
  EXPECT_NEAR(g(1, 0), -4 * 2 * 3, 1e-9);
  EXPECT_NEAR(g(2, 0), 1, 1e-9);
  // The in-plane gradient (error norms on planar domains): the same differences in x and y, z left 0; and for a
  // closed-form gradient the closed form with z zeroed. Bad component counts are refused.
  Eigen::Matrix3Xd p;
  c.partial_gradients(x, 2, p);
  EXPECT_EQ(p(0, 0), g(0, 0));
  EXPECT_EQ(p(1, 0), g(1, 0));
  EXPECT_EQ(p(2, 0), 0.0);
  const auto closed = fem::make_function([](const Eigen::Vector3d& y) { return y(0) * y(1) * y(2); },
                                         [](const Eigen::Vector3d& y) {
                                           return Eigen::Vector3d(y(1) * y(2), y(0) * y(2), y(0) * y(1));
                                         });
  x(2, 0) = 5;
  closed->partial_gradients(x, 1, p);
  EXPECT_EQ(p(0, 0), 15.0);
  EXPECT_EQ(p(1, 0), 0.0);
  EXPECT_EQ(p(2, 0), 0.0);
  EXPECT_THROW(c.partial_gradients(x, 0, p), InputError);
  EXPECT_THROW(c.partial_gradients(x, 4, p), InputError);
}

TEST(Expression, ErrorsNameTheOption) {
  try {
    fem::Expression("sin(x", "--source");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("--source"), std::string::npos);
  }
  EXPECT_THROW(fem::Expression("x + w", "--exact"), InputError);       // unknown variable
  EXPECT_THROW(fem::Expression("x + nx", "--dirichlet"), InputError);  // normals only for Neumann data
  EXPECT_THROW(fem::Expression("  ", "--source"), InputError);
}

TEST(Expression, ThreadSafe) {
  const fem::Expression e("x*y", "--source");
  Eigen::Matrix3Xd x = Eigen::Matrix3Xd::Random(3, 1000);
  Eigen::VectorXd ref;
  e.values(x, ref);
  std::atomic<int> bad{0};
  std::vector<std::thread> threads;
  for (int t = 0; t < 4; ++t) {
    threads.emplace_back([&] {
      for (int k = 0; k < 50; ++k) {
        Eigen::VectorXd v;
        e.values(x, v);
        if ((v - ref).cwiseAbs().maxCoeff() != 0.0) ++bad;
      }
    });
  }
  for (auto& t : threads) t.join();
  EXPECT_EQ(bad.load(), 0);
}

TEST(Expression, CommaAndAssignmentAreRefused) {
  // Issue 14, class 4: muparser reads '1,2' as two results (2 is used) and 'x=3' as an assignment (3): both
  // silently gave another formula. Comparisons stay formulas.
  using iga::fem::Expression;
  auto message = [](const std::string& text) {
    try {
      Expression e(text, "--source");
    } catch (const iga::InputError& err) {
      return std::string(err.what());
    }
    return std::string();
  };
  EXPECT_NE(message("1,2").find("',' separates several expressions"), std::string::npos) << message("1,2");
  EXPECT_NE(message("x=3").find("'=' assigns"), std::string::npos) << message("x=3");
  EXPECT_NE(message("sin(x) , y").find("--source"), std::string::npos);
  for (const std::string ok : {"x==3", "x<=3", "x>=0.5", "x!=y", "(x>0.5)*(y<=1)"}) EXPECT_EQ(message(ok), "") << ok;
  // A long expression's error is one short line.
  const std::string longer = std::string(100000, '(') + "x";
  const std::string m = message(longer);
  EXPECT_FALSE(m.empty());
  EXPECT_LT(m.size(), 300u) << m.substr(0, 300);
  EXPECT_EQ(m.find('\n'), std::string::npos);
}

TEST(Expression, NonFiniteValuesAreErrorsNamingThePoint) {
  // Issue 14, class 3: 1/0, sqrt(-1), log(0) and an overflow gave NaN or infinite data and a NaN solution with
  // exit 0. A value that is not finite is an error naming the option, the expression and the point.
  using iga::fem::Expression;
  Eigen::Matrix3Xd x(3, 2);
  x << 0.5, 0.0, 0.25, 0.0, 0.0, 0.0;
  Eigen::VectorXd out;
  auto message = [&](const std::string& text) {
    try {
      Expression(text, "--source").values(x, out);
    } catch (const iga::InputError& err) {
      return std::string(err.what());
    }
    return std::string();
  };
  EXPECT_EQ(message("1/0"), "--source: '1/0' is infinite at (0.5, 0.25, 0); data must be finite wherever they are used");
  EXPECT_EQ(message("sqrt(-1)"), "--source: 'sqrt(-1)' is NaN at (0.5, 0.25, 0); data must be finite wherever they are used");
  // The second point is where log(x) is -inf: the message names it, not the first.
  EXPECT_EQ(message("log(x)"), "--source: 'log(x)' is infinite at (0, 0, 0); data must be finite wherever they are used");
  EXPECT_EQ(message("exp(1000*(x+1))"), "--source: 'exp(1000*(x+1))' is infinite at (0.5, 0.25, 0); data must be finite wherever they are used");
  EXPECT_EQ(message("x*y+1"), "");
  // Boundary data with a normal go through the same check.
  const Expression g("nx/ny", "--neumann", true);
  Eigen::Matrix3Xd n = Eigen::Matrix3Xd::Zero(3, 2);
  n(0, 0) = 1.0;
  n(1, 1) = 1.0;
  EXPECT_THROW(g.values(x, n, out), iga::InputError);
}

// Issue 38, class 5: the singular set read symbolically (fem/data_check.hpp uses it). GiNaC's order of terms is
// its own: the factors are looked up by name.
TEST(ExpressionSingular, DenominatorsAndLogArgumentsAreNamed) {
  const fem::Expression pole("1/(x-3/10) + log(abs(y-1/2)) + 1/(1+x^2)", "--source");
  const std::vector<std::string>& names = pole.singular_factor_names();
  ASSERT_EQ(names.size(), 3u);
  const auto at = [&](const std::string& name) {
    return static_cast<Eigen::Index>(std::find(names.begin(), names.end(), name) - names.begin());
  };
  const Eigen::Index pole_x = at("the denominator -3+10*x");
  ASSERT_LT(pole_x, 3);
  ASSERT_LT(at("the argument of log -1/2+y"), 3);
  ASSERT_LT(at("the denominator 1+x^2"), 3);
  Eigen::Matrix3Xd x = Eigen::Matrix3Xd::Zero(3, 2);
  x(0, 1) = 1.0;
  Eigen::MatrixXd d;
  pole.singular_factors(x, d);
  EXPECT_EQ(d(pole_x, 0), -3.0);
  EXPECT_EQ(d(pole_x, 1), 7.0);
  EXPECT_TRUE(fem::Expression("sin(pi*x)", "--source").singular_factor_names().empty());
}
