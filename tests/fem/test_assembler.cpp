// The element loop: closed-form element matrices, the sparsity pattern and colouring, reproducibility.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include <set>

#include "basis/bspline/patches.hpp"
#include "fem/assembler.hpp"
#include "fem/threads.hpp"
#include "quadrature/rule_provider.hpp"
#include "refine/uniform.hpp"

using namespace iga;

// Bilinear (Q1) element on the unit square, dofs (0,0),(1,0),(0,1),(1,1): the textbook stiffness matrix
// (1/6)[4 -1 -1 -2; -1 4 -2 -1; -1 -2 4 -1; -2 -1 -1 4] and mass matrix (1/36)[4 2 2 1; 2 4 1 2; 2 1 4 2; 1 2 2 4].
TEST(Assembler, BilinearElementMatricesInClosedForm) {
  const basis::Geometry g = basis::bspline::make_rectangle(1);
  const quadrature::Gauss rules(2);
  const fem::Assembler assembler(g, rules);
  const fem::StiffnessForm k;
  const fem::MassForm m;
  const std::vector<const fem::BilinearForm*> bk{&k}, bm{&m};
  Eigen::SparseMatrix<double> a;
  Eigen::VectorXd b;
  assembler.assemble(bk, {}, a, b);
  Eigen::Matrix4d ks, ms;
  ks << 4, -1, -1, -2, -1, 4, -2, -1, -1, -2, 4, -1, -2, -1, -1, 4;
  ms << 4, 2, 2, 1, 2, 4, 1, 2, 2, 1, 4, 2, 1, 2, 2, 4;
  EXPECT_LE((Eigen::MatrixXd(a) - ks / 6.0).cwiseAbs().maxCoeff(), 1e-15);
  const fem::AssemblyStats stats = assembler.assemble(bm, {}, a, b);
  EXPECT_LE((Eigen::MatrixXd(a) - ms / 36.0).cwiseAbs().maxCoeff(), 1e-15);
  EXPECT_NEAR(stats.measure, 1.0, 1e-15);
  EXPECT_EQ(stats.quadrature_points, 4);
}

// On a stretched rectangle [0,2]×[0,1] the Q1 stiffness scales as (hy/hx) K_xx + (hx/hy) K_yy.
TEST(Assembler, StretchedElement) {
  const basis::Geometry g = basis::bspline::make_rectangle(1, 0.0, 2.0, 0.0, 1.0);
  const quadrature::Gauss rules(2);
  const fem::Assembler assembler(g, rules);
  const fem::StiffnessForm k;
  const std::vector<const fem::BilinearForm*> bk{&k};
  Eigen::SparseMatrix<double> a;
  Eigen::VectorXd b;
  assembler.assemble(bk, {}, a, b);
  // K_xx = (1/6)[2 -2 1 -1; -2 2 -1 1; 1 -1 2 -2; -1 1 -2 2], K_yy likewise with y.
  Eigen::Matrix4d kxx, kyy;
  kxx << 2, -2, 1, -1, -2, 2, -1, 1, 1, -1, 2, -2, -1, 1, -2, 2;
  kyy << 2, 1, -2, -1, 1, 2, -1, -2, -2, -1, 2, 1, -1, -2, 1, 2;
  const Eigen::Matrix4d expected = (0.5 * kxx + 2.0 * kyy) / 6.0;
  EXPECT_LE((Eigen::MatrixXd(a) - expected).cwiseAbs().maxCoeff(), 1e-15);
}

TEST(AssemblyPlan, PatternAndColouring) {
  const basis::Geometry g = refine::refine_uniform(basis::bspline::make_quarter_annulus(3), 3).geometry;
  const fem::AssemblyPlan plan = fem::make_assembly_plan(g.space());
  const basis::Space& s = g.space();
  // 8×8 elements, degree 3: 11×11 dofs; interior dofs couple with 7×7 others.
  EXPECT_EQ(plan.pattern.rows(), 121);
  // 1D: functions i, j of 11 couple when |i - j| <= 3: 11·7 - 2·(3+2+1) = 65 pairs; 2D: 65^2.
  EXPECT_EQ(plan.pattern.nonZeros(), 65 * 65);
  Index total = 0;
  for (const auto& colour : plan.colors) {
    std::set<Index> used;
    for (Index e : colour) {
      for (Index d : s.dofs(e)) EXPECT_TRUE(used.insert(d).second) << "colour shares dof " << d;
    }
    total += static_cast<Index>(colour.size());
  }
  EXPECT_EQ(total, s.num_elements());
  // Greedy colouring of a tensor mesh needs (p+1)^2 = 16 colours.
  EXPECT_EQ(plan.colors.size(), 16u);
  // Symmetric pattern.
  const Eigen::SparseMatrix<double> t = plan.pattern.transpose();
  EXPECT_EQ(t.nonZeros(), plan.pattern.nonZeros());
  for (Index j = 0; j < t.outerSize(); ++j) {
    EXPECT_EQ(t.outerIndexPtr()[j + 1], plan.pattern.outerIndexPtr()[j + 1]);
  }
}

// Assembly sums each entry in colour order: the same bits for 1 and 2 threads.
// The NURBS annulus (every element evaluated) and the B-spline L-shape (interior elements share reference values,
// basis::Space::reference_element).
TEST(Assembler, ReproducibleForAnyThreadCount) {
  for (const basis::Geometry& g : {refine::refine_uniform(basis::bspline::make_quarter_annulus(3), 4).geometry,
                                   refine::refine_uniform(basis::bspline::make_l_shape(3), 3).geometry}) {
    SCOPED_TRACE(g.space().num_elements());
  const quadrature::Gauss rules(4);
  const fem::StiffnessForm k;
  const fem::SourceForm f(fem::make_function([](const Eigen::Vector3d& x) { return std::sin(x(0)) + x(1); }));
  const std::vector<const fem::BilinearForm*> bk{&k};
  const std::vector<const fem::LinearForm*> lf{&f};
  const int before = fem::num_threads();
  Eigen::SparseMatrix<double> a1, a2;
  Eigen::VectorXd b1, b2;
  fem::set_num_threads(1);
  fem::Assembler(g, rules).assemble(bk, lf, a1, b1);
  fem::set_num_threads(2);
  fem::Assembler(g, rules).assemble(bk, lf, a2, b2);
  fem::set_num_threads(before);
  ASSERT_EQ(a1.nonZeros(), a2.nonZeros());
  for (Index k2 = 0; k2 < a1.nonZeros(); ++k2) EXPECT_EQ(a1.valuePtr()[k2], a2.valuePtr()[k2]);
  EXPECT_EQ((b1 - b2).cwiseAbs().maxCoeff(), 0.0);
  // Rows of a stiffness matrix sum to zero (constants are in the kernel).
  EXPECT_LE((a1 * Eigen::VectorXd::Ones(a1.cols())).cwiseAbs().maxCoeff(), 1e-12);
  }
}

// Issue 17's bicubic path: on a uniform bicubic patch with a curved map (interior elements are twins), prepare()
// gives every element the values a direct evaluation gives (to rounding: the twin's operator may differ from the
// element's own in the last bit), and the stiffness form's compile-time 16 × 16 kernel equals the element matrix
// summed point by point from the same gradients.
TEST(Assembler, TwinReferenceValuesAndTheBicubicKernelAgreeWithDirectEvaluation) {
  basis::Geometry coarse = basis::bspline::make_rectangle(3);
  Eigen::MatrixXd p = coarse.control_points();
  for (Index i = 0; i < p.rows(); ++i) p(i, 0) += 0.1 * std::sin(3.0 * p(i, 1));  // a curved, non-affine map
  const basis::Geometry g =
      refine::refine_uniform(basis::Geometry(coarse.space_ptr(), p), 3).geometry;  // 8 × 8 uniform intervals
  const basis::Space& space = g.space();
  Index twins = 0;
  for (Index e = 0; e < space.num_elements(); ++e) twins += space.reference_element(e) != e;
  EXPECT_EQ(twins, 64 - 25);  // (2p − 1)² = 25 distinct operators at p = 3 on 8 uniform intervals
  const quadrature::Gauss rules(4);
  const fem::Assembler assembler(g, rules);
  const fem::StiffnessForm stiffness;
  fem::ElementContext ctx;
  basis::BasisValues direct;
  for (Index e = 0; e < space.num_elements(); ++e) {
    assembler.prepare(e, ctx);
    space.evaluate(e, ctx.rule->points, 1, direct);
    EXPECT_LE((ctx.basis.value - direct.value).cwiseAbs().maxCoeff(), 1e-14) << "element " << e;
    EXPECT_LE((ctx.basis.du - direct.du).cwiseAbs().maxCoeff(), 1e-13) << "element " << e;
    EXPECT_LE((ctx.basis.dv - direct.dv).cwiseAbs().maxCoeff(), 1e-13) << "element " << e;
    Eigen::MatrixXd k = Eigen::MatrixXd::Zero(16, 16), sum = Eigen::MatrixXd::Zero(16, 16);
    stiffness.add(ctx, k);
    const Eigen::Index q = ctx.num_points();
    for (Eigen::Index pt = 0; pt < q; ++pt) {
      for (int i = 0; i < 16; ++i) {
        for (int j = 0; j < 16; ++j) {
          sum(i, j) += ctx.weight(pt) * (ctx.grad(i, pt) * ctx.grad(j, pt) + ctx.grad(i, q + pt) * ctx.grad(j, q + pt));
        }
      }
    }
    EXPECT_LE((k - sum).cwiseAbs().maxCoeff(), 1e-14 * sum.cwiseAbs().maxCoeff()) << "element " << e;
  }
}

// Per-element integrals (one value per element, the joint estimators need): on the quarter annulus refined
// twice (16 elements), the element areas are positive and sum to the exact area 3π/4 (a rational integrand: 8
// Gauss points per direction leave 1e-15), a column equals its rule
// sum computed by hand, integrate() is their sum in element order, and 1 and 2 threads agree bit for bit.
TEST(Assembler, PerElementIntegralsSumToTheGlobalOne) {
  const basis::Geometry g = refine::refine_uniform(basis::bspline::make_quarter_annulus(2), 2).geometry;
  const quadrature::Gauss rules(8);
  auto area_and_moment = [](const fem::ElementContext& c, Eigen::Ref<Eigen::VectorXd> out) {
    out(0) = c.weight.sum();
    out(1) = c.weight.dot(c.geo.x.row(0).transpose());
  };
  const int before = fem::num_threads();
  fem::set_num_threads(1);
  const Eigen::MatrixXd one = fem::Assembler(g, rules).integrate_per_element(2, area_and_moment);
  fem::set_num_threads(2);
  const Eigen::MatrixXd two = fem::Assembler(g, rules).integrate_per_element(2, area_and_moment);
  const Eigen::VectorXd total = fem::Assembler(g, rules).integrate(2, area_and_moment);
  fem::set_num_threads(before);
  ASSERT_EQ(one.cols(), g.space().num_elements());
  EXPECT_EQ((one - two).cwiseAbs().maxCoeff(), 0.0);
  EXPECT_GT(one.row(0).minCoeff(), 0.0);
  EXPECT_NEAR(one.row(0).sum(), 0.75 * std::numbers::pi, 1e-13);  // the exact quarter annulus r ∈ [1, 2]
  double in_order = 0.0;
  for (Index e = 0; e < one.cols(); ++e) in_order += one(0, e);
  EXPECT_EQ(total(0), in_order);  // the same numbers, summed in element order
  // Column 5 by hand: Σ_q w_q |det J|(q).
  basis::BasisValues bv;
  basis::GeometryValues gv;
  const quadrature::Rule& r = rules.rule(g.space().kind(5));
  g.space().evaluate(5, r.points, 1, bv);
  g.evaluate(5, bv, gv);
  EXPECT_NEAR(one(0, 5), r.weights.dot(gv.measure), 1e-15);
  EXPECT_NEAR(one(1, 5), (r.weights.array() * gv.measure.array() * gv.x.row(0).transpose().array()).sum(), 1e-15);
}
