// bem, slow: larger systems (about 500 to 2100 dofs) through the GMRES path and the timings of assembly and
// solve. Labelled "slow" (not in the default run); test_bem_solve holds the quick variants.
#include <gtest/gtest.h>

#include <cstdio>

#include "bem/boundary_discretization.hpp"
#include "bem/errors.hpp"
#include "bem/solve.hpp"
#include "bem_geometries.hpp"
#include "support/rates.hpp"

using iga::Index;
namespace bem = iga::bem;
namespace tb = iga::test::bem;

// The square with a hole, mixed, e^x cos y, refine 4..8 (p = 3: 152..2072 dofs), GMRES (block Jacobi, tolerance 1e-14) above 400 unknowns.
// The rate over the four levels is that of test_bem_solve's quick variant (3.85 measured there) and GMRES
// agrees with LU on the largest system.
TEST(BemSlow, HoleMixedLargeSystems) {
  const auto hole = tb::square_with_hole();
  const std::vector<int> cond{0, 0, 1, 1, 1, 0, 1, 0};
  const auto u = tb::exp_cos();
  const bem::Problem problem{u, iga::fem::normal_flux(u), u};
  std::vector<double> errors;
  for (int r = 4; r <= 8; ++r) {
    bem::DiscretizationOptions o;
    o.degree = 3;
    o.refine = r;
    const bem::BoundaryDiscretization d(hole, cond, o);
    bem::SolveOptions so;
    so.lu_limit = 400;
    so.gmres_tolerance = 1e-14;
    const bem::Solution s = bem::solve(d, problem, so);
    const double e = bem::flux_l2_error(d, s, *u) / bem::flux_l2_norm(d, *u);
    std::printf("refine %d dofs %ld solver %s iterations %d assembly %.2f s solve %.2f s condition %.3e flux %.3e\n", r,
                static_cast<long>(d.num_dofs()), s.solver.c_str(), s.gmres_iterations, s.assembly_seconds,
                s.solve_seconds, s.condition_estimate, e);
    errors.push_back(e);
    if (r == 8) {
      bem::SolveOptions lu;
      lu.solver = bem::SolveOptions::Solver::LU;
      const bem::Solution l = bem::solve(d, problem, lu);
      EXPECT_EQ(s.solver, "gmres");
      EXPECT_LT((l.q - s.q).cwiseAbs().maxCoeff(), 1e-8 * l.q.cwiseAbs().maxCoeff());
      std::printf("LU: solve %.2f s condition %.3e flux %.3e\n", l.solve_seconds, l.condition_estimate,
                  bem::flux_l2_error(d, l, *u) / bem::flux_l2_norm(d, *u));
    }
  }
  EXPECT_GE(iga::test::fitted_rate(errors), 3.6);
}
