#include "fem/poisson.hpp"

#include <algorithm>
#include <chrono>

#include "core/error.hpp"
#include "fem/assembler.hpp"
#include "fem/dirichlet.hpp"

namespace iga::fem {

namespace {
double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}
}  // namespace

PoissonResult solve_poisson(const basis::Geometry& geometry, const quadrature::RuleProvider& rules,
                            const PoissonProblem& problem, const SolverOptions& solver) {
  const basis::Space& space = geometry.space();
  const int parts = static_cast<int>(space.boundary_part_names().size());
  for (int p : problem.neumann_parts) {
    if (p < 0 || p >= parts) throw InputError("Neumann boundary part " + std::to_string(p) + " does not exist");
  }
  if (!problem.neumann_parts.empty() && !problem.neumann) {
    throw InputError("Neumann boundary parts are given but no Neumann data");
  }
  if (problem.reaction < 0) throw InputError("reaction coefficient must be >= 0");
  std::vector<basis::BoundaryEdge> dirichlet_edges, neumann_edges;
  for (const basis::BoundaryEdge& e : space.boundary_edges()) {
    const bool neumann = std::find(problem.neumann_parts.begin(), problem.neumann_parts.end(), e.part) !=
                         problem.neumann_parts.end();
    (neumann ? neumann_edges : dirichlet_edges).push_back(e);
  }
  if (dirichlet_edges.empty() && problem.reaction == 0.0) {
    throw InputError(
        "no Dirichlet boundary and no reaction term: the solution is determined only up to a constant; "
        "keep a boundary part Dirichlet or give a reaction coefficient c > 0");
  }

  PoissonResult r;
  r.dofs = space.num_dofs();
  r.elements = space.num_elements();
  const auto t0 = std::chrono::steady_clock::now();
  Assembler assembler(geometry, rules);
  assembler.plan();
  r.pattern_seconds = seconds_since(t0);

  const StiffnessForm stiffness;
  const MassForm reaction(problem.reaction);
  std::vector<const BilinearForm*> bilinear{&stiffness};
  if (problem.reaction != 0.0) bilinear.push_back(&reaction);
  std::unique_ptr<SourceForm> source;
  std::vector<const LinearForm*> linear;
  if (problem.source) {
    source = std::make_unique<SourceForm>(problem.source);
    linear.push_back(source.get());
  }
  Eigen::SparseMatrix<double> a;
  Eigen::VectorXd b;
  const AssemblyStats stats = assembler.assemble(bilinear, linear, a, b);
  r.domain_measure = stats.measure;
  r.quadrature_points = stats.quadrature_points;

  if (!neumann_edges.empty()) {
    Eigen::VectorXd bn;
    const BoundaryLoadForm flux(problem.neumann);
    assembler.assemble_boundary(neumann_edges, nullptr, &flux, nullptr, &bn);
    b += bn;
  }
  const DirichletConditions bc =
      project_dirichlet(assembler, dirichlet_edges, problem.dirichlet ? problem.dirichlet : constant_function(0.0));
  r.dirichlet_dofs = static_cast<Index>(bc.dofs.size());
  const ReducedSystem sys = eliminate(a, b, bc);
  r.free_dofs = static_cast<Index>(sys.free.size());
  r.assembly_seconds = seconds_since(t0);

  const SolveResult s = solve(sys.a, sys.b, solver);
  r.solve_seconds = s.seconds;
  r.solver = s.solver;
  r.residual_norm = s.residual_norm;
  r.solver_iterations = s.iterations;
  r.u = expand(sys, s.x, bc, space.num_dofs());
  if (problem.exact) r.errors = compute_errors(assembler, r.u, *problem.exact);
  return r;
}

}  // namespace iga::fem
