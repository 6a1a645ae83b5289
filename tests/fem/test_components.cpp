// The joints widened for other PDEs: fields of d components (the plan's pattern, the loop's refusal of a form of
// other components, conditions per component), Hessians of data (the default difference against closed forms).
#include <gtest/gtest.h>

#include <cmath>

#include "basis/bspline/patches.hpp"
#include "core/error.hpp"
#include "fem/assembler.hpp"
#include "fem/assembly_plan.hpp"
#include "fem/dirichlet.hpp"
#include "fem/forms.hpp"
#include "quadrature/rule_provider.hpp"
#include "refine/uniform.hpp"

using namespace iga;

TEST(Components, PatternIsTheScalarOneTimesAFullBlock) {
  const basis::Geometry g = refine::refine_uniform(basis::bspline::make_quarter_annulus(2), 2).geometry;
  const fem::AssemblyPlan scalar = fem::make_assembly_plan(g.space());
  for (int d : {2, 3}) {
    const fem::AssemblyPlan field = fem::make_assembly_plan(g.space(), true, d);
    const Index n = scalar.pattern.rows();
    ASSERT_EQ(field.pattern.rows(), d * n);
    EXPECT_EQ(field.pattern.nonZeros(), scalar.pattern.nonZeros() * d * d);
    // Entry (d i + a, d j + b) exists exactly when (i, j) does: compare with the Kronecker product built densely.
    Eigen::MatrixXd mask = Eigen::MatrixXd::Zero(n, n);
    for (Index j = 0; j < n; ++j) {
      for (Eigen::SparseMatrix<double>::InnerIterator it(scalar.pattern, j); it; ++it) mask(it.row(), j) = 1;
    }
    Eigen::MatrixXd got = Eigen::MatrixXd::Zero(d * n, d * n);
    for (Index j = 0; j < d * n; ++j) {
      for (Eigen::SparseMatrix<double>::InnerIterator it(field.pattern, j); it; ++it) got(it.row(), j) = 1;
    }
    for (Index i = 0; i < d * n; ++i) {
      for (Index j = 0; j < d * n; ++j) ASSERT_EQ(got(i, j), mask(i / d, j / d)) << i << " " << j;
    }
    EXPECT_EQ(field.colors, scalar.colors);
    EXPECT_EQ(field.dense.size(), scalar.dense.size() * static_cast<std::size_t>(d));
  }
}

TEST(Components, TheLoopRefusesAFormOfOtherComponents) {
  const basis::Geometry g = basis::bspline::make_rectangle(2);
  const quadrature::Gauss rules(3);
  const fem::Assembler field(g, rules, 2);
  const fem::StiffnessForm scalar_form;
  const std::vector<const fem::BilinearForm*> forms{&scalar_form};
  Eigen::SparseMatrix<double> a;
  Eigen::VectorXd b;
  try {
    field.assemble(forms, {}, a, b);
    FAIL() << "a scalar form was taken by a 2-component loop";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("a form for 1 component(s) given to the loop of a field with 2"),
              std::string::npos)
        << e.what();
  }
  EXPECT_THROW(fem::Assembler(g, rules, 0), InputError);
}

TEST(Components, ConditionsPerComponentAndTheirMerge) {
  fem::DirichletConditions s;
  s.dofs = {0, 3};
  s.values = Eigen::Vector2d(1.5, -2.0);
  const fem::DirichletConditions x = fem::component_conditions(s, 0, 2);
  const fem::DirichletConditions y = fem::component_conditions(s, 1, 2);
  EXPECT_EQ(x.dofs, (std::vector<Index>{0, 6}));
  EXPECT_EQ(y.dofs, (std::vector<Index>{1, 7}));
  const fem::DirichletConditions both = fem::merge_conditions({y, x}, 10);
  EXPECT_EQ(both.dofs, (std::vector<Index>{0, 1, 6, 7}));
  EXPECT_EQ(both.values, Eigen::Vector4d(1.5, 1.5, -2.0, -2.0));
  EXPECT_THROW(fem::merge_conditions({x, x}, 10), InputError);
  // A coupled row: its columns move with the component.
  s.coupling.resize(2, 5);
  s.coupling.insert(1, 4) = 0.25;
  const fem::DirichletConditions cy = fem::component_conditions(s, 1, 3);
  EXPECT_EQ(cy.coupling.cols(), 15);
  EXPECT_EQ(cy.coupling.coeff(1, 13), 0.25);
  EXPECT_EQ(fem::merge_conditions({cy}, 15).coupling.coeff(1, 13), 0.25);
}

// Homogeneous rows R u = 0, one of them redundant (the sum of two others), as conditions: one dof per independent row,
// the preferred ones first, coupling zero on the conditions' own dofs, and every u they admit satisfies R u = 0.
TEST(Components, LinearConditionsFromRedundantRows) {
  Eigen::MatrixXd r(4, 8);
  r << 1, -1, 0, 0, 0, 0, 2, 0,  //
      0, 1, -1, 0, 0, 0, 0, 0,   //
      1, 0, -1, 0, 0, 0, 2, 0,   // row 0 + row 1
      0, 0, 0, 0.5, 0, -0.5, 0, 0;
  const Eigen::SparseMatrix<double, Eigen::RowMajor> rs = r.sparseView();
  const fem::DirichletConditions bc = fem::linear_conditions(rs, {6, 5});
  EXPECT_EQ(bc.dofs, (std::vector<Index>{1, 5, 6}));  // 6 and 5 preferred, then the lowest column: 0, 1 (0 drops)
  ASSERT_EQ(bc.coupling.rows(), 3);
  for (std::size_t k = 0; k < bc.dofs.size(); ++k) {
    for (Index d : bc.dofs) EXPECT_EQ(bc.coupling.coeff(static_cast<Index>(k), d), 0.0);
  }
  // u = 0 on the conditions' dofs minus the coupling: free values arbitrary.
  Eigen::VectorXd u(8);
  u << 0.3, 0, -1.7, 2.2, 0.9, 0, 0, 4.1;
  Eigen::VectorXd held = bc.values - bc.coupling * u;
  for (std::size_t k = 0; k < bc.dofs.size(); ++k) u(bc.dofs[k]) = held(static_cast<Index>(k));
  EXPECT_LT((r * u).norm(), 1e-14);
  EXPECT_NE(u(6), 0.0);
}

TEST(Hessians, TheDefaultDifferenceMatchesClosedForms) {
  // u = sin(x) e^{2y} + x³ z: its Hessian in closed form; the default differences the closed-form gradient.
  auto f = [](const Eigen::Vector3d& p) { return std::sin(p(0)) * std::exp(2 * p(1)) + std::pow(p(0), 3) * p(2); };
  auto grad = [](const Eigen::Vector3d& p) {
    return Eigen::Vector3d(std::cos(p(0)) * std::exp(2 * p(1)) + 3 * p(0) * p(0) * p(2),
                           2 * std::sin(p(0)) * std::exp(2 * p(1)), std::pow(p(0), 3));
  };
  const auto differenced = fem::make_function(f, grad);
  Eigen::Matrix3Xd x(3, 2);
  x << 0.3, -0.7, 0.2, 0.4, 1.1, -0.5;
  Eigen::Matrix<double, 6, Eigen::Dynamic> h;
  differenced->hessians(x, h);
  EXPECT_FALSE(differenced->exact_hessian());
  for (Index k = 0; k < 2; ++k) {
    const double a = x(0, k), b = x(1, k), c = x(2, k), e = std::exp(2 * b);
    const Eigen::Matrix<double, 6, 1> exact =
        (Eigen::Matrix<double, 6, 1>() << -std::sin(a) * e + 6 * a * c, 2 * std::cos(a) * e, 4 * std::sin(a) * e,
         3 * a * a, 0.0, 0.0).finished();
    EXPECT_LT((h.col(k) - exact).cwiseAbs().maxCoeff(), 1e-9) << h.col(k).transpose();
  }
  // The Laplacian of it, planar and in 3D.
  Eigen::VectorXd lap;
  fem::laplacian_of(differenced)->values(x, lap);
  EXPECT_NEAR(lap(0), h(0, 0) + h(2, 0), 1e-12);
  fem::laplacian_of(differenced, false)->values(x, lap);
  EXPECT_NEAR(lap(1), h(0, 1) + h(2, 1) + h(5, 1), 1e-12);
}
