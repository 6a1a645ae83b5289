// The biharmonic equation Δ²u = f (pde/biharmonic) through the one problem pipeline (fem::ProblemSolver):
// rates against manufactured solutions fitted over three levels, the classical plate deflections (Navier's double
// series, summed here; the clamped square's published value), the clamped circular plate's closed form, and the
// refusals of spaces that are not C1.
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <numbers>

#include "basis/bspline/patches.hpp"
#include "basis/catmull_clark/space.hpp"
#include "core/error.hpp"
#include "fem/problem.hpp"
#include "pde/biharmonic/biharmonic.hpp"
#include "quadrature/rule_provider.hpp"
#include "refine/uniform.hpp"
#include "support/biharmonic_solutions.hpp"
#include "support/nets.hpp"
#include "support/rates.hpp"

using namespace iga;
using std::numbers::pi;
using test::bump;
using test::bump_source;

namespace {

// u = sin(2x) cos(y) + x⁴ y, Δ²u = 25 sin(2x) cos(y) + 24 y: boundary data of every kind non-zero.
std::shared_ptr<fem::Function> mixed() {
  return fem::make_function(
      [](const Eigen::Vector3d& p) { return std::sin(2 * p(0)) * std::cos(p(1)) + std::pow(p(0), 4) * p(1); },
      [](const Eigen::Vector3d& p) {
        const double x = p(0), y = p(1);
        return Eigen::Vector3d(2 * std::cos(2 * x) * std::cos(y) + 4 * x * x * x * y,
                               -std::sin(2 * x) * std::sin(y) + std::pow(x, 4), 0);
      },
      [](const Eigen::Vector3d& p) {
        const double x = p(0), y = p(1);
        Eigen::Matrix3d h = Eigen::Matrix3d::Zero();
        h(0, 0) = -4 * std::sin(2 * x) * std::cos(y) + 12 * x * x * y;
        h(0, 1) = h(1, 0) = -2 * std::cos(2 * x) * std::sin(y) + 4 * x * x * x;
        h(1, 1) = -std::sin(2 * x) * std::cos(y);
        return h;
      });
}
std::shared_ptr<fem::Function> mixed_source() {
  return fem::make_function(
      [](const Eigen::Vector3d& p) { return 25 * std::sin(2 * p(0)) * std::cos(p(1)) + 24 * p(1); });
}

struct Rates {
  double l2, h1, h2;
  std::vector<double> el2, eh1, eh2;
};

Rates rates(const basis::Geometry& coarse, int first, int levels, const pde::BiharmonicData& data, int gauss) {
  Rates r;
  const quadrature::Gauss rules(gauss);
  for (int level = first; level < first + levels; ++level) {
    const basis::Geometry g = refine::refine_uniform(coarse, level).geometry;
    const fem::ProblemResult res = fem::solve_problem(g, rules, pde::make_biharmonic(data));
    r.el2.push_back(res.error("L2").error);
    r.eh1.push_back(res.error("H1").error);
    r.eh2.push_back(res.error("H2").error);
  }
  r.l2 = test::fitted_rate(r.el2);
  r.h1 = test::fitted_rate(r.eh1);
  r.h2 = test::fitted_rate(r.eh2);
  std::cout << "rates L2 " << r.l2 << " H1 " << r.h1 << " H2 " << r.h2 << " (finest errors " << r.el2.back() << ", "
            << r.eh1.back() << ", " << r.eh2.back() << ")\n";
  return r;
}

// The discrete solution at physical point p of a geometry whose element corners include p.
double value_at_corner(const basis::Geometry& g, const Eigen::VectorXd& u, const Eigen::Vector2d& p) {
  const basis::Space& space = g.space();
  Eigen::Matrix2Xd corners(2, 4);
  corners << 0, 1, 0, 1, 0, 0, 1, 1;
  for (Index e = 0; e < space.num_elements(); ++e) {
    basis::BasisValues bv;
    basis::GeometryValues gv;
    space.evaluate(e, corners, 1, bv);
    g.evaluate(e, bv, gv, false);
    for (int k = 0; k < 4; ++k) {
      if ((gv.x.col(k).head<2>() - p).norm() < 1e-12) {
        const auto dofs = space.dofs(e);
        double v = 0;
        for (std::size_t a = 0; a < dofs.size(); ++a) v += bv.value(static_cast<Index>(a), k) * u(dofs[a]);
        return v;
      }
    }
  }
  ADD_FAILURE() << "no element corner at the point";
  return 0;
}

}  // namespace

TEST(Biharmonic, BicubicClampedSquareRates) {
  const pde::BiharmonicData data = pde::biharmonic_data_from_exact(bump(), bump_source());
  const Rates r = rates(basis::bspline::make_rectangle(3), 3, 3, data, 4);
  EXPECT_GE(r.l2, 3.8);
  EXPECT_GE(r.h1, 2.8);
  EXPECT_GE(r.h2, 1.8);
  EXPECT_LT(r.eh2.back(), 0.1 * r.eh2.front());
}

TEST(Biharmonic, BiquadraticClampedSquareRates) {
  const pde::BiharmonicData data = pde::biharmonic_data_from_exact(bump(), bump_source());
  const Rates r = rates(basis::bspline::make_rectangle(2), 2, 3, data, 3);
  EXPECT_GE(r.l2, 1.8);
  EXPECT_GE(r.h2, 0.9);
}

TEST(Biharmonic, SimplySupportedWithNonZeroDataRates) {
  // Every part simply supported: u = g strongly, Δu = m through the natural load.
  pde::BiharmonicData data = pde::biharmonic_data_from_exact(mixed(), mixed_source(), {0, 1, 2, 3});
  const Rates r = rates(basis::bspline::make_rectangle(3), 2, 3, data, 4);
  EXPECT_GE(r.l2, 3.8);
  EXPECT_GE(r.h1, 2.8);
  EXPECT_GE(r.h2, 1.8);
}

TEST(Biharmonic, ClampedQuarterAnnulusNurbsRates) {
  const pde::BiharmonicData data = pde::biharmonic_data_from_exact(mixed(), mixed_source());
  const Rates r = rates(basis::bspline::make_quarter_annulus(3), 3, 3, data, 5);
  EXPECT_GE(r.l2, 3.8);
  EXPECT_GE(r.h1, 2.8);
  EXPECT_GE(r.h2, 1.8);
}

TEST(Biharmonic, CatmullClarkClampedBoundaryRegularNetRates) {
  // The clamped boundary rule on a regular net: bicubic in every element, the B-spline rates.
  const basis::Geometry coarse = basis::catmull_clark::make_catmull_clark_geometry(
      test::square_grid(4), "net", basis::catmull_clark::BoundaryRule::kClamped);
  const pde::BiharmonicData data = pde::biharmonic_data_from_exact(bump(), bump_source());
  const Rates r = rates(coarse, 1, 3, data, 4);
  EXPECT_GE(r.l2, 3.8);
  EXPECT_GE(r.h1, 2.8);
  EXPECT_GE(r.h2, 1.8);
  // The clamped rule on a regular net spans the bicubic open-knot B-splines: the same solution as the tensor
  // backend on the same 32 × 32 elements (two independent evaluations of one space).
  const basis::Geometry g = refine::refine_uniform(basis::bspline::make_rectangle(3), 5).geometry;
  const fem::ProblemResult b = fem::solve_problem(g, quadrature::Gauss(4), pde::make_biharmonic(data));
  // Rounding of two factorisations of a system with condition number ~ h⁻⁴: 1e-7 relative.
  EXPECT_NEAR(r.el2.back(), b.error("L2").error, 1e-7 * r.el2.back());
  EXPECT_NEAR(r.eh2.back(), b.error("H2").error, 1e-7 * r.eh2.back());
}

TEST(Biharmonic, NavierSimplySupportedSquarePlate) {
  // D Δ²w = q on the unit square, w = Δw = 0 on the edges. Navier's double series at the centre:
  // w = 16 q a⁴ / (π⁶ D) Σ_{m, n odd} (−1)^((m+n)/2 − 1) / (m n (m² + n²)²) = 0.00406235 q a⁴ / D.
  double sum = 0;
  for (int m = 1; m < 4000; m += 2) {
    for (int n = 1; n < 4000; n += 2) {
      sum += (((m + n) / 2 - 1) % 2 ? -1.0 : 1.0) / (m * double(n) * std::pow(double(m) * m + double(n) * n, 2));
    }
  }
  const double series = 16 * sum / std::pow(pi, 6);
  EXPECT_NEAR(series, 0.00406235, 5e-9);  // the classical table value, to its digits
  pde::BiharmonicData data;
  data.source = fem::constant_function(1.0);
  data.simply_supported = {0, 1, 2, 3};
  const basis::Geometry g = refine::refine_uniform(basis::bspline::make_rectangle(3), 4).geometry;
  const fem::ProblemResult r = fem::solve_problem(g, quadrature::Gauss(4), pde::make_biharmonic(data));
  const double w = value_at_corner(g, r.u, {0.5, 0.5});
  std::cout << "Navier plate: w(centre) = " << w << ", series " << series << "\n";
  EXPECT_NEAR(w / series, 1.0, 1e-4) << w;
}

TEST(Biharmonic, ClampedSquarePlate) {
  // The clamped square under uniform load: w_max = 0.00126532 q a⁴ / D (the classical value).
  pde::BiharmonicData data;
  data.source = fem::constant_function(1.0);
  const basis::Geometry g = refine::refine_uniform(basis::bspline::make_rectangle(3), 5).geometry;
  const fem::ProblemResult r = fem::solve_problem(g, quadrature::Gauss(4), pde::make_biharmonic(data));
  const double w = value_at_corner(g, r.u, {0.5, 0.5});
  std::cout << "clamped plate: w(centre) = " << w << "\n";
  EXPECT_NEAR(w / 0.00126532, 1.0, 1e-4) << w;
}

TEST(Biharmonic, ClampedCircularPlateOnTheAnnulus) {
  // w = q (R² − r²)² / (64 D) solves D Δ²w = q and is clamped at r = R; on the quarter annulus 1 <= r <= 2 (R = 2)
  // the other sides take its own values and slopes. Relative errors at 16 × 16 bicubic elements.
  const double big_r = 2.0;
  auto w = fem::make_function(
      [=](const Eigen::Vector3d& x) { return std::pow(big_r * big_r - x.head<2>().squaredNorm(), 2) / 64; },
      [=](const Eigen::Vector3d& x) {
        const double c = -(big_r * big_r - x.head<2>().squaredNorm()) / 16;
        return Eigen::Vector3d(c * x(0), c * x(1), 0);
      },
      [=](const Eigen::Vector3d& x) {
        const double c = -(big_r * big_r - x.head<2>().squaredNorm()) / 16;
        Eigen::Matrix3d h = Eigen::Matrix3d::Zero();
        h(0, 0) = c + x(0) * x(0) / 8;
        h(1, 1) = c + x(1) * x(1) / 8;
        h(0, 1) = h(1, 0) = x(0) * x(1) / 8;
        return h;
      });
  const pde::BiharmonicData data = pde::biharmonic_data_from_exact(w, fem::constant_function(1.0));
  const basis::Geometry g = refine::refine_uniform(basis::bspline::make_quarter_annulus(3), 4).geometry;
  const fem::ProblemResult r = fem::solve_problem(g, quadrature::Gauss(5), pde::make_biharmonic(data));
  EXPECT_LT(r.error("L2").error, 1e-6 * r.error("L2").exact);
  EXPECT_LT(r.error("H2").error, 1e-3 * r.error("H2").exact);
  ASSERT_GE(r.choices.size(), 2u);
  EXPECT_EQ(r.choices[1].first, "clamped");
}

TEST(Biharmonic, RefusesSpacesThatAreNotC1) {
  pde::BiharmonicData data;
  data.source = fem::constant_function(1.0);
  const basis::Geometry bilinear = refine::refine_uniform(basis::bspline::make_rectangle(1), 2).geometry;
  try {
    fem::solve_problem(bilinear, quadrature::Gauss(2), pde::make_biharmonic(data));
    FAIL() << "degree 1 accepted";
  } catch (const InputError& e) {
    // Elements are numbered from 0 in messages, as in the .vtu's "element" cell data and the geometry's errors.
    EXPECT_NE(std::string(e.what()).find("element 0 has degree 1"), std::string::npos) << e.what();
  }
  // The L-shape's two pieces meet C0 along the segment from (1,1) to (0,0) (a knot of multiplicity p).
  const basis::Geometry l_shape = basis::bspline::make_l_shape(3);
  try {
    fem::solve_problem(l_shape, quadrature::Gauss(4), pde::make_biharmonic(data));
    FAIL() << "a C0 edge accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("only C0 across the side shared by elements 0 and 1"), std::string::npos)
        << e.what();
  }
}

TEST(Biharmonic, RefusesBadSetUps) {
  pde::BiharmonicData data;
  data.simply_supported = {7};
  const basis::Geometry g = basis::bspline::make_rectangle(3);
  EXPECT_THROW(fem::solve_problem(g, quadrature::Gauss(4), pde::make_biharmonic(data)), InputError);
  data.simply_supported = {};
  data.nitsche_penalty = -1;
  EXPECT_THROW(fem::solve_problem(g, quadrature::Gauss(4), pde::make_biharmonic(data)), InputError);
}
