// The Poisson solve of poisson_annulus.cpp on PETSc, distributed over the ranks of mpirun (one without it):
//   mpirun -np 2 ./poisson_petsc
// Each rank assembles the elements of its part of a METIS partition into one PETSc matrix; CG + GAMG solves it
// (change it with PETSC_OPTIONS, e.g. PETSC_OPTIONS="-pc_type hypre"). The same three calls as the serial driver:
// a geometry, a problem, solve_poisson; what changes is the ParallelSession and the solver's name. Every rank
// gets the whole solution; rank 0 reports. Exit 1 when the L2 error is not what this discretisation reaches.
#include <cmath>
#include <iostream>
#include <numbers>

#include "basis/bspline/patches.hpp"
#include "fem/parallel.hpp"
#include "fem/poisson.hpp"
#include "quadrature/rule_provider.hpp"
#include "refine/uniform.hpp"

int main(int argc, char** argv) {
  using namespace iga;
  using V = Eigen::Vector3d;
  constexpr double pi = std::numbers::pi;
  const int degree = 3;
  // 0. PETSc and MPI, for the whole run (PETSc reads its options from argv and PETSC_OPTIONS).
  fem::ParallelSession session(argc, argv);

  // 1. Geometry: the quarter annulus, refined 5 times (32 × 32 elements), on every rank.
  const basis::Geometry geometry = refine::refine_uniform(basis::bspline::make_quarter_annulus(degree), 5).geometry;

  // 2. The problem: u = sin(πx) sin(πy), f = -Δu, u on the boundary.
  fem::PoissonProblem problem;
  problem.exact = fem::make_function(
      [](const V& x) { return std::sin(pi * x(0)) * std::sin(pi * x(1)); },
      [](const V& x) -> V {
        return {pi * std::cos(pi * x(0)) * std::sin(pi * x(1)), pi * std::sin(pi * x(0)) * std::cos(pi * x(1)), 0};
      });
  problem.source = fem::make_function(
      [](const V& x) { return 2 * pi * pi * std::sin(pi * x(0)) * std::sin(pi * x(1)); });
  problem.dirichlet = problem.exact;

  // 3. Solve on PETSc: relative residual 1e-12.
  fem::SolverOptions solver;
  solver.kind = fem::SolverKind::Petsc;
  const quadrature::Gauss rules(degree + 1);
  const fem::PoissonResult r = fem::solve_poisson(geometry, rules, problem, solver);

  // 4. Report (rank 0) and check on every rank: the serial driver reaches 5.8e-6 here.
  const bool ok = r.errors->l2 < 1e-5;
  if (fem::rank() == 0) {
    std::cout << "dofs " << r.dofs << " on " << r.ranks << " ranks (owned dofs:";
    for (Index d : r.dofs_per_rank) std::cout << " " << d;
    std::cout << "), " << r.solver << " in " << r.solver_iterations << " iterations\n"
              << "L2 error " << r.errors->l2 << ", H1 error " << r.errors->h1 << "\n"
              << (ok ? "OK" : "FAILED: L2 error above 1e-5") << "\n";
  }
  return ok ? 0 : 1;
}
