// Exact derivatives of expressions (fem/symbolic.hpp, issue 32): the reading agrees with muparser on its own
// grammar, gradients and Hessians equal closed forms (smooth, singular, piecewise), and the error norms' integrals of
// the exact solution equal closed-form integrals by each derivative method (symbolic, closed form, finite
// differences with their error estimate).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "basis/bspline/patches.hpp"
#include "core/error.hpp"
#include "fem/assembler.hpp"
#include "fem/errors.hpp"
#include "fem/expression.hpp"
#include "fem/problems.hpp"
#include "fem/symbolic.hpp"
#include "quadrature/rule_provider.hpp"
#include "refine/uniform.hpp"

using namespace iga;

namespace {

constexpr double kPi = std::numbers::pi;

Eigen::Matrix3Xd grid_points() {
  Eigen::Matrix3Xd x(3, 7 * 7 * 3);
  int k = 0;
  for (int i = 0; i < 7; ++i) {
    for (int j = 0; j < 7; ++j) {
      for (int l = 0; l < 3; ++l) x.col(k++) << -1.9 + 0.61 * i, -1.7 + 0.57 * j, -0.8 + 0.83 * l;
    }
  }
  return x;
}

// The values of an expression at the points where it is finite (NaN elsewhere), one point at a time.
Eigen::VectorXd values_or_nan(const fem::Expression& e, const Eigen::Matrix3Xd& x) {
  Eigen::VectorXd out(x.cols()), one;
  for (Eigen::Index k = 0; k < x.cols(); ++k) {
    try {
      e.values(x.col(k), one);
      out(k) = one(0);
    } catch (const InputError&) {
      out(k) = std::nan("");
    }
  }
  return out;
}

}  // namespace

// Each text is read and written back; muparser evaluates both: the same values wherever the text is finite. The
// bank covers muparser's precedences (checked against the library: -2^2 = -4, 2^3^2 = 512, 2^-x^2 = 2^(-(x^2)),
// 2^-1*4 = 2, right-associative ?:) and every function.
TEST(Symbolic, ReadingAgreesWithMuparser) {
  const std::vector<std::string> bank = {
      "-2^2 + x", "2^3^2*x", "2^-x^2", "2^-1*4*y", "x^2^-1", "-x^2", "-sin(x)^2", "3*-y", "1--x", "x- -2",
      "2*-3^2+z", "x-y-z", "x/y/2", "1+2<4 ? x : y", "x<0 ? 1 : y<0 ? 2 : 3", "(x<0 ? 1 : 2)*y", "x ? y : z",
      "x>0 && y>0 || z<0", "x>=y", "x<=y", "x==x", "x!=y", "sin(x)+cos(y)+tan(z)", "asin(x/3)+acos(y/2)+atan(z)",
      "sinh(x)+cosh(y)+tanh(z)", "asinh(x)+acosh(abs(y)+1)+atanh(z/2)", "exp(x)+sqrt(abs(y))", "ln(abs(x))+log(abs(y)+1)",
      "log2(abs(x)+1)+log10(abs(y)+1)", "abs(x-y)*sign(z)", "rint(3*x)", "min(x, y, z)", "max(x, y)", "sum(x, y, 1)",
      "avg(x, y, z, 1)", "atan2(y, x)", "pow(abs(x), y)", "pi*x + e*y + _pi*z + _e", "1e-3*x + .5*y + 2.5E+1*z",
      "+x", "((x))", "2/3*x", "x^(1/3)", "(x^2 + y^2)^(1/3)*sin(2/3*(y >= 0 ? acos(x/sqrt(x^2+y^2)) : 2*pi - acos(x/sqrt(x^2+y^2))))"};
  const Eigen::Matrix3Xd x = grid_points();
  for (const std::string& text : bank) {
    std::string why;
    const std::optional<std::string> reading = fem::symbolic_reading(text, why);
    ASSERT_TRUE(reading.has_value()) << text << ": " << why;
    const Eigen::VectorXd a = values_or_nan(fem::Expression(text, "t"), x);
    const Eigen::VectorXd b = values_or_nan(fem::Expression(*reading, "t"), x);
    int compared = 0;
    for (Eigen::Index k = 0; k < x.cols(); ++k) {
      ASSERT_EQ(std::isfinite(a(k)), std::isfinite(b(k))) << text << " read as " << *reading << " at point " << k;
      if (!std::isfinite(a(k))) continue;
      EXPECT_NEAR(a(k), b(k), 1e-12 * std::max(1.0, std::abs(a(k)))) << text << " read as " << *reading;
      ++compared;
    }
    EXPECT_GT(compared, 10) << text;
    EXPECT_TRUE(fem::Expression(text, "t").exact_gradient()) << text;
  }
}

TEST(Symbolic, NamesWhatItDoesNotRead) {
  std::string why;
  EXPECT_FALSE(fem::differentiate("foo(x)", why).has_value());
  EXPECT_NE(why.find("'foo'"), std::string::npos) << why;
  EXPECT_FALSE(fem::differentiate("x + nx", why).has_value());
  EXPECT_NE(why.find("'nx'"), std::string::npos) << why;
  // Boundary data with the normal are not differentiated: finite differences, and the report says so.
  const fem::Expression g("x*nx", "--neumann", true);
  EXPECT_FALSE(g.exact_gradient());
  EXPECT_EQ(g.derivative_method(1).rfind("finite differences", 0), 0U) << g.derivative_method(1);
}

// Gradients and Hessians against hand-derived closed forms at scattered points: smooth, singular (the corner
// function written with acos and ?:, as a user would), and piecewise (abs, min).
TEST(Symbolic, DerivativesEqualClosedForms) {
  struct Case {
    std::string text;
    std::function<Eigen::Vector3d(const Eigen::Vector3d&)> grad;
    std::function<Eigen::Matrix3d(const Eigen::Vector3d&)> hess;
  };
  const std::vector<Case> cases = {
      {"sin(pi*x)*exp(y)*z^2",
       [](const Eigen::Vector3d& p) -> Eigen::Vector3d {
         const double s = std::sin(kPi * p(0)), c = std::cos(kPi * p(0)), e = std::exp(p(1)), z = p(2);
         return {kPi * c * e * z * z, s * e * z * z, 2 * s * e * z};
       },
       [](const Eigen::Vector3d& p) -> Eigen::Matrix3d {
         const double s = std::sin(kPi * p(0)), c = std::cos(kPi * p(0)), e = std::exp(p(1)), z = p(2);
         Eigen::Matrix3d h;
         h << -kPi * kPi * s * e * z * z, kPi * c * e * z * z, 2 * kPi * c * e * z,  //
             kPi * c * e * z * z, s * e * z * z, 2 * s * e * z,                    //
             2 * kPi * c * e * z, 2 * s * e * z, 2 * s * e;
         return h;
       }},
      {"(x^2 + y^2)^(1/3)*sin(2/3*(y >= 0 ? acos(x/sqrt(x^2+y^2)) : 2*pi - acos(x/sqrt(x^2+y^2))))",
       [](const Eigen::Vector3d& p) -> Eigen::Vector3d {  // α r^(α−1) (sin((α−1)θ), cos((α−1)θ)), θ ∈ [0, 2π)
         const double a = 2.0 / 3, r = std::hypot(p(0), p(1));
         double t = std::atan2(p(1), p(0));
         if (t < 0) t += 2 * kPi;
         return {a * std::pow(r, a - 1) * std::sin((a - 1) * t), a * std::pow(r, a - 1) * std::cos((a - 1) * t), 0};
       },
       [](const Eigen::Vector3d& p) -> Eigen::Matrix3d {  // u = Im z^α: u_xx = −u_yy = Im f'', u_xy = Re f''
         const double a = 2.0 / 3, r = std::hypot(p(0), p(1));
         double t = std::atan2(p(1), p(0));
         if (t < 0) t += 2 * kPi;
         const double m = a * (a - 1) * std::pow(r, a - 2);
         const double uxx = m * std::sin((a - 2) * t), uxy = m * std::cos((a - 2) * t);
         Eigen::Matrix3d h;
         h << uxx, uxy, 0, uxy, -uxx, 0, 0, 0, 0;
         return h;
       }},
      {"abs(x - 0.5)*y + min(x, y)^2",
       [](const Eigen::Vector3d& p) -> Eigen::Vector3d {
         const double m = std::min(p(0), p(1));
         return {(p(0) > 0.5 ? 1.0 : -1.0) * p(1) + (p(1) < p(0) ? 0.0 : 2 * m),
                 std::abs(p(0) - 0.5) + (p(1) < p(0) ? 2 * m : 0.0), 0};
       },
       [](const Eigen::Vector3d& p) -> Eigen::Matrix3d {
         const double s = p(0) > 0.5 ? 1.0 : -1.0;
         Eigen::Matrix3d h = Eigen::Matrix3d::Zero();
         h(0, 1) = h(1, 0) = s;
         (p(1) < p(0) ? h(1, 1) : h(0, 0)) += 2;
         return h;
       }}};
  const Eigen::Matrix3Xd x = grid_points();
  for (const Case& c : cases) {
    const fem::Expression e(c.text, "--exact");
    ASSERT_TRUE(e.exact_gradient() && e.exact_hessian()) << c.text << ": " << e.derivative_method(1);
    EXPECT_EQ(e.derivative_method(2), "symbolic (GiNaC)");
    for (Eigen::Index k = 0; k < x.cols(); ++k) {
      const Eigen::Vector3d p = x.col(k);
      if (std::abs(p(0) - 0.5) < 1e-9 || std::abs(p(0) - p(1)) < 1e-9) continue;  // a kink
      Eigen::Matrix3Xd g;
      Eigen::Matrix<double, 6, Eigen::Dynamic> h;
      e.gradients(p, g);
      e.hessians(p, h);
      const Eigen::Vector3d ge = c.grad(p);
      const Eigen::Matrix3d he = c.hess(p);
      const double gs = std::max(1.0, ge.norm()), hs = std::max(1.0, he.norm());
      for (int i = 0; i < 3; ++i) EXPECT_NEAR(g(i, 0), ge(i), 1e-11 * gs) << c.text << " at " << p.transpose();
      const double hv[6] = {he(0, 0), he(0, 1), he(1, 1), he(0, 2), he(1, 2), he(2, 2)};
      for (int i = 0; i < 6; ++i) EXPECT_NEAR(h(i, 0), hv[i], 1e-9 * hs) << c.text << " row " << i << " at " << p.transpose();
    }
  }
}

// |u|²_H1, |u|²_H2 and ‖u‖²_L2 of u = r^(2/3) sin(2θ/3) on the quarter annulus 1 ≤ r ≤ 2 (smooth there), as
// norm_squares integrates them (u_h = 0: the "error" is u) by each derivative method, against the closed forms
// ‖u‖² = (3/10)(2^(10/3) − 1)(π/4 − 3√3/16), |u|²_1 = (π/6)(2^(4/3) − 1), |u|²_2 = (2π/27)(1 − 2^(−2/3)), Δu = 0.
TEST(Symbolic, NormsOfEachMethodEqualClosedFormIntegrals) {
  const basis::Geometry g = refine::refine_uniform(basis::bspline::make_quarter_annulus(4), 3).geometry;
  const quadrature::Gauss rule(9);
  const fem::Assembler a(g, rule);
  const Eigen::VectorXd zero = Eigen::VectorXd::Zero(g.space().num_dofs());
  const double l2 = 0.3 * (std::pow(2.0, 10.0 / 3) - 1) * (kPi / 4 - 3 * std::sqrt(3.0) / 16);
  const double h1 = kPi / 6 * (std::pow(2.0, 4.0 / 3) - 1), h2 = 2 * kPi / 27 * (1 - std::pow(2.0, -2.0 / 3));
  const auto symbolic = std::make_shared<fem::Expression>("(x^2+y^2)^(1/3)*sin(2/3*atan2(y, x))", "--exact");
  const auto polar = [](const Eigen::Vector3d& p, double& r, double& t) {
    r = std::hypot(p(0), p(1));
    t = std::atan2(p(1), p(0));
  };
  const auto value = [polar](const Eigen::Vector3d& p) {
    double r, t;
    polar(p, r, t);
    return std::pow(r, 2.0 / 3) * std::sin(2.0 / 3 * t);
  };
  const auto closed = fem::make_function(value, [polar](const Eigen::Vector3d& p) -> Eigen::Vector3d {
    double r, t;
    polar(p, r, t);
    const double m = 2.0 / 3 * std::pow(r, -1.0 / 3);
    return {m * std::sin(-t / 3), m * std::cos(-t / 3), 0};
  });
  const auto differenced = fem::make_function(value);
  const fem::Norm norms[4] = {fem::Norm::kL2, fem::Norm::kH1, fem::Norm::kH2, fem::Norm::kLaplacian};
  for (const auto& [name, u] : std::vector<std::pair<std::string, std::shared_ptr<const fem::Function>>>{
           {"symbolic", symbolic}, {"closed form", closed}, {"finite differences", differenced}}) {
    const Eigen::VectorXd s = fem::norm_squares(a, zero, *u, norms);
    ASSERT_EQ(s.size(), 12);
    EXPECT_NEAR(s(1), l2, 1e-11 * l2) << name;
    EXPECT_NEAR(s(3), h1, 1e-10 * h1) << name;
    EXPECT_NEAR(s(5), h2, (name == "finite differences" ? 1e-6 : 1e-9) * h2) << name;
    EXPECT_NEAR(std::sqrt(s(7)), 0.0, name == "finite differences" ? 1e-4 : 1e-8) << name;
    // Estimates of the derivatives' error: 0 where they are exact; for differences, above the true error.
    if (name == "symbolic") {
      EXPECT_EQ(s.tail(4).norm(), 0.0);
    }
    if (name == "closed form") {
      EXPECT_EQ(s(9), 0.0);  // the gradient; its Hessian is differenced
    }
    if (name == "finite differences") {
      EXPECT_GT(s(9), 0.0);
      EXPECT_LT(std::sqrt(s(9)), 1e-6);
    }
  }
}

// The corner function on the L-shape, singular at the reflex corner (1, 1): |u|²_1 = (4/9) ∫ r^(−2/3) over three
// unit squares about the corner = 2 ∫_0^{π/4} sec^{4/3} θ dθ (each square is two triangles 0 ≤ r ≤ sec θ), the 1D
// integral by Gauss–Legendre here. The symbolic gradient of the user's text agrees with the built-in closed form;
// finite differences, whose stencil crosses the singularity on the finest elements, estimate an error far above
// the closed-form difference, and norm_errors refuses to report a norm they would spoil.
TEST(Symbolic, SingularCornerNormsAndTheRefusalOfFiniteDifferences) {
  // Reference: 64-point Gauss–Legendre of the smooth sec^{4/3} on [0, π/4] (Golub–Welsch by Newton on P_64).
  double integral = 0.0;
  const int n = 64;
  for (int i = 1; i <= n; ++i) {
    double t = std::cos(kPi * (i - 0.25) / (n + 0.5)), dp = 0.0;
    for (int it = 0; it < 100; ++it) {
      double p0 = 1.0, p1 = t;
      for (int k = 2; k <= n; ++k) {
        const double p2 = ((2.0 * k - 1) * t * p1 - (k - 1.0) * p0) / k;
        p0 = p1;
        p1 = p2;
      }
      dp = n * (t * p1 - p0) / (t * t - 1);
      const double dt = p1 / dp;
      t -= dt;
      if (std::abs(dt) < 1e-16) break;
    }
    const double w = 2.0 / ((1 - t * t) * dp * dp), theta = kPi / 8 * (t + 1);
    integral += kPi / 8 * w * std::pow(1.0 / std::cos(theta), 4.0 / 3);
  }
  const double h1 = 2 * integral;
  const basis::Geometry g = refine::refine_uniform(basis::bspline::make_l_shape(2), 6).geometry;
  const quadrature::Gauss rule(8);
  const fem::Assembler a(g, rule);
  const Eigen::VectorXd zero = Eigen::VectorXd::Zero(g.space().num_dofs());
  const fem::Norm norms[2] = {fem::Norm::kL2, fem::Norm::kH1};
  const fem::ManufacturedProblem corner = fem::manufactured_problem("corner");
  const fem::Expression text(
      "((x-1)^2 + (y-1)^2)^(1/3)*sin(2/3*(y > 1 ? acos((x-1)/sqrt((x-1)^2+(y-1)^2)) - pi/2 : "
      "3*pi/2 - acos((x-1)/sqrt((x-1)^2+(y-1)^2))))",
      "--exact");
  ASSERT_TRUE(text.exact_gradient()) << text.derivative_method(1);
  const Eigen::VectorXd sc = fem::norm_squares(a, zero, *corner.exact, norms);
  const Eigen::VectorXd st = fem::norm_squares(a, zero, text, norms);
  EXPECT_NEAR(sc(3), h1, 2e-3 * h1);  // the rule on the corner's elements: the singularity's quadrature error
  EXPECT_NEAR(st(3), sc(3), 1e-9 * h1);
  EXPECT_NEAR(st(1), sc(1), 1e-12 * sc(1));
  auto differenced = fem::make_function([&](const Eigen::Vector3d& p) {
    Eigen::VectorXd v;
    text.values(p, v);
    return v(0);
  });
  const Eigen::VectorXd sd = fem::norm_squares(a, zero, *differenced, norms);
  const double true_error = std::abs(std::sqrt(sd(3)) - std::sqrt(sc(3)));
  EXPECT_GT(std::sqrt(sd(5)), true_error);
  // As an error norm against a discrete solution whose error is of that size, it is refused with the reason:
  // reported only when the estimate is at most 1 % of the error.
  Eigen::VectorXd squares = sd;
  squares(2) = std::pow(std::sqrt(sd(5)) * 200, 2);  // 0.5 %: reported
  EXPECT_NO_THROW(fem::norm_errors({"L2", "H1"}, squares));
  squares(2) = std::pow(std::sqrt(sd(5)) * 20, 2);  // 5 %: refused
  try {
    fem::norm_errors({"L2", "H1"}, squares, {"values", differenced->derivative_method(1)});
    ADD_FAILURE() << "a norm spoilt by its finite differences was reported";
  } catch (const NumericalError& e) {
    EXPECT_NE(std::string(e.what()).find("the H1 error"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("finite differences"), std::string::npos) << e.what();
  }
}
