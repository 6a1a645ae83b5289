// The adaptive loop on the L-shaped domain with the corner singularity u = r^(2/3) sin(2φ/3) (fem problem
// "corner", domain basis::bspline::make_l_shape): THB refinement by the residual estimator and Dörfler marking
// against uniform refinement; the estimator's efficiency index; the local patch test; marking.
#include "support/paths.hpp"
#include <gtest/gtest.h>

#include <cmath>

#include "basis/bspline/patches.hpp"
#include "basis/registry.hpp"
#include "fem/problems.hpp"
#include "mesh/obj_reader.hpp"
#include "quadrature/rule_provider.hpp"
#include "refine/adaptive.hpp"
#include "support/rates.hpp"

namespace {

using namespace iga;

double rate(const std::vector<double>& dofs, const std::vector<double>& err) {
  return test::fitted_rate_in_dofs(dofs, err);
}

fem::PoissonProblem corner_problem() {
  const fem::ManufacturedProblem mp = fem::manufactured_problem("corner");
  fem::PoissonProblem p;
  p.source = mp.source;
  p.exact = mp.exact;
  p.dirichlet = mp.exact;
  return p;
}

refine::AdaptiveRun run_adaptive(int degree, int steps) {
  basis::BackendFacts facts;
  const basis::Refinement start = basis::refine_uniform(basis::bspline::make_l_shape(degree), 1, facts);
  const auto rules = quadrature::make_rule_provider("gauss:" + std::to_string(degree + 1), degree + 1);
  refine::AdaptiveOptions o;
  o.steps = steps;
  o.theta = 0.5;
  return refine::adaptive_solve(start.geometry, *rules, corner_problem(), {}, o);
}

struct Case {
  int degree, steps;
};
class AdaptiveLShape : public ::testing::TestWithParam<Case> {};

TEST_P(AdaptiveLShape, OptimalRateAndABoundedEfficiencyIndex) {
  const auto [p, steps] = GetParam();
  const refine::AdaptiveRun run = run_adaptive(p, steps);
  ASSERT_EQ(run.stopped, "steps");
  ASSERT_EQ(static_cast<int>(run.history.size()), steps + 1);
  std::vector<double> dofs, err;
  double lo = 1e300, hi = 0;
  for (const refine::AdaptiveStep& s : run.history) {
    ASSERT_TRUE(s.energy_error && s.efficiency);
    lo = std::min(lo, *s.efficiency);
    hi = std::max(hi, *s.efficiency);
  }
  // The last 8 steps.
  for (std::size_t i = run.history.size() - 8; i < run.history.size(); ++i) {
    dofs.push_back(static_cast<double>(run.history[i].dofs));
    err.push_back(*run.history[i].energy_error);
  }
  const double r = rate(dofs, err);
  std::cout << "degree " << p << ": " << run.history.back().dofs << " dofs, " << run.history.back().levels
            << " levels, rate over the last 8 steps " << r << ", efficiency index " << lo << " .. " << hi << "\n";
  // Optimal: p/2 in the dofs. Degree 3 at these sizes is still dominated by the corner element, each step halving
  // it, so its measured slope (about 3) is above the asymptotic 1.5; the assertion is the optimal-rate bound.
  EXPECT_GE(r, p / 2.0 - 0.1);
  // Measured bands (all steps): degree 2: 5.9 .. 9.1; degree 3: 5.0 .. 13.8, the widest on the coarse start.
  EXPECT_LT(hi / lo, 3.0);
  EXPECT_GT(lo, 1.0);  // reliability with this constant-free estimator: η is above the energy error
}

INSTANTIATE_TEST_SUITE_P(Degrees, AdaptiveLShape, ::testing::Values(Case{2, 18}, Case{3, 24}));

TEST(AdaptiveLShape, UniformRefinementConvergesAtTheSingularRate) {
  // Uniform refinement is limited by the singularity: |e|_H1 ~ h^(2/3) = dofs^(-1/3).
  std::vector<double> dofs, err;
  const auto rules = quadrature::make_rule_provider("gauss:3", 3);
  for (int k = 2; k <= 5; ++k) {
    basis::BackendFacts facts;
    const basis::Refinement r = basis::refine_uniform(basis::bspline::make_l_shape(2), k, facts);
    const fem::PoissonResult res = fem::solve_poisson(r.geometry, *rules, corner_problem());
    dofs.push_back(static_cast<double>(res.dofs));
    err.push_back(res.errors->h1);
  }
  const double r = rate(dofs, err);
  std::cout << "uniform rate " << r << "\n";
  EXPECT_NEAR(r, 1.0 / 3.0, 0.06);
}

TEST(AdaptiveLShape, LocallyRefinedPatchTest) {
  // A linear solution is in every THB space on the (bilinear) L: reproduced after local refinement near the corner.
  for (int p : {2, 3}) {
    basis::BackendFacts facts;
    basis::Geometry g = basis::refine_uniform(basis::bspline::make_l_shape(p), 1, facts).geometry;
    for (int s = 0; s < 4; ++s) {
      // Refine the elements that touch the reflex corner (1,1).
      std::vector<Index> marked;
      for (Index e = 0; e < g.space().num_elements(); ++e) {
        basis::GeometryValues gv;
        Eigen::Matrix2Xd corners(2, 4);
        corners << 0, 1, 0, 1, 0, 0, 1, 1;
        g.evaluate(e, corners, gv);
        for (int k = 0; k < 4; ++k) {
          if ((gv.x.col(k).head<2>() - Eigen::Vector2d(1, 1)).norm() < 1e-12) marked.push_back(e);
        }
      }
      g = basis::refine_marked(g, marked, 2, facts).geometry;
    }
    ASSERT_GE(g.space().num_elements(), 10);
    const fem::ManufacturedProblem mp = fem::manufactured_problem("linear");
    fem::PoissonProblem problem;
    problem.source = mp.source;
    problem.exact = mp.exact;
    problem.dirichlet = mp.exact;
    const auto rules = quadrature::make_rule_provider("gauss:" + std::to_string(p + 1), p + 1);
    const fem::PoissonResult r = fem::solve_poisson(g, *rules, problem);
    EXPECT_LT(r.errors->l2, 1e-10) << "degree " << p;
    EXPECT_LT(r.errors->h1, 1e-10) << "degree " << p;
    EXPECT_NEAR(r.domain_measure, 3.0, 1e-12);
  }
}

TEST(Marking, DoerflerTakesTheFewestLargestAndMaxTheRelative) {
  Eigen::VectorXd eta(6);
  eta << 1.0, 3.0, 2.0, 2.0, 0.5, 0.0;  // η² sum 18.25
  // θ = 0.5: 9 + 4 = 13 >= 9.125 after two elements (3, then the first 2 by index).
  EXPECT_EQ(refine::mark(eta, refine::Marking::Doerfler, 0.5), (std::vector<Index>{1, 2}));
  EXPECT_EQ(refine::mark(eta, refine::Marking::Doerfler, 1.0), (std::vector<Index>{0, 1, 2, 3, 4}));
  EXPECT_EQ(refine::mark(eta, refine::Marking::Maximum, 0.6), (std::vector<Index>{1, 2, 3}));
  EXPECT_TRUE(refine::mark(Eigen::VectorXd::Zero(3), refine::Marking::Doerfler, 0.5).empty());
  EXPECT_THROW(refine::mark(eta, refine::Marking::Doerfler, 0.0), InputError);
  Eigen::VectorXd bad = eta;
  bad(0) = std::nan("");
  EXPECT_THROW(refine::mark(bad, refine::Marking::Maximum, 0.5), InputError);
}

TEST(PoissonSolver, StepsComposeToSolvePoisson) {
  const basis::Geometry g = basis::bspline::make_l_shape(2);
  basis::BackendFacts facts;
  const basis::Refinement r = basis::refine_uniform(g, 2, facts);
  const auto rules = quadrature::make_rule_provider("gauss:3", 3);
  const fem::PoissonProblem problem = corner_problem();
  const fem::PoissonResult whole = fem::solve_poisson(r.geometry, *rules, problem);
  fem::PoissonSolver s(r.geometry, *rules, problem);
  s.errors();  // runs setup, assemble and solve first
  EXPECT_EQ((s.result().u - whole.u).cwiseAbs().maxCoeff(), 0.0);
  EXPECT_EQ(s.result().errors->h1, whole.errors->h1);
}

TEST(Estimator, JumpTermsOnlyAcrossTheC0Line) {
  // The L patch is C0 along u = 1/2 (from the reflex corner to (0,0)) and C1 elsewhere (degree 2): only edges
  // on that line carry jumps, and for the exact linear solution every part of the estimator vanishes.
  basis::BackendFacts facts;
  const basis::Refinement r = basis::refine_uniform(basis::bspline::make_l_shape(2), 2, facts);
  const auto rules = quadrature::make_rule_provider("gauss:3", 3);
  fem::PoissonProblem linear;
  const fem::ManufacturedProblem mp = fem::manufactured_problem("linear");
  linear.source = mp.source;
  linear.dirichlet = mp.exact;
  fem::PoissonSolver s(r.geometry, *rules, linear);
  s.solve();
  const fem::Estimate e = fem::estimate_residual(s);
  EXPECT_EQ(e.jump_edges, 4);  // 4 element edges along the C0 line after two uniform steps
  EXPECT_LT(e.total, 1e-9);
  fem::PoissonSolver c(r.geometry, *rules, corner_problem());
  c.solve();
  const fem::Estimate ec = fem::estimate_residual(c);
  EXPECT_GT(ec.jump, 0.0);
  EXPECT_GT(ec.residual, 0.0);
  EXPECT_NEAR(ec.total * ec.total, ec.residual * ec.residual + ec.jump * ec.jump + ec.neumann * ec.neumann,
              1e-12 * ec.total * ec.total);
}

}  // namespace

namespace {

TEST(AdaptiveCatmullClark, LShapeNetWithABoundaryEvRefinesTowardTheCorner) {
  // Hierarchical truncated Catmull–Clark on data/meshes/l_shape.obj (the reflex corner is a boundary EV). The
  // limit domain rounds the reflex corner (area 3.0052, not 3), so r^(2/3) sin(2φ/3) is not this domain's
  // solution and its "error" does not converge; what is asserted is what was measured for the estimator:
  // η 0.575 → 0.283 from 65 to 336 dofs over 11 steps (a rate of about 0.43 in dofs), not monotone (the
  // admissibility closure adds up to 22 elements a step), and the loop stops cleanly at the deepest level the
  // global level nets allow (7 levels for this 48-face net: 4^l · faces <= 2^20).
  const basis::Backend& cc = basis::backend("cc");
  basis::BackendFacts facts;
  const mesh::PolyMesh net = mesh::read_obj(std::string(IGA_SOURCE_DIR) + "/data/meshes/l_shape.obj");
  const basis::Geometry g = basis::make_geometry(cc, &net, {}, facts);
  const auto rules = quadrature::make_rule_provider("tiles:4:24", 4);
  refine::AdaptiveOptions o;
  o.steps = 7;
  const refine::AdaptiveRun run = refine::adaptive_solve(g, *rules, corner_problem(), {}, o);
  ASSERT_EQ(run.history.size(), 8u);
  const refine::AdaptiveStep& first = run.history.front();
  const refine::AdaptiveStep& last = run.history.back();
  EXPECT_EQ(first.dofs, 65);
  EXPECT_GT(last.levels, 4);
  EXPECT_LT(last.estimate, 0.5 * first.estimate);
  std::vector<double> dofs, eta;
  for (const auto& s : run.history) {
    dofs.push_back(static_cast<double>(s.dofs));
    eta.push_back(s.estimate);
  }
  const double r = test::fitted_rate_in_dofs(dofs, eta);
  std::cout << "cc: " << last.dofs << " dofs, " << last.levels << " levels, estimator rate " << r << "\n";
  EXPECT_GT(r, 0.2);
}

}  // namespace
