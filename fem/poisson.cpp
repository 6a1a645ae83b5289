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
  if (problem.reaction < 0) throw InputError("reaction coefficient must be >= 0");
  std::vector<basis::BoundaryEdge> dirichlet_edges, neumann_edges;
  Eigen::VectorXd where;
  for (const basis::BoundaryEdge& e : space.boundary_edges()) {
    bool neumann = std::find(problem.neumann_parts.begin(), problem.neumann_parts.end(), e.part) !=
                   problem.neumann_parts.end();
    if (!neumann && problem.neumann_where) {
      Eigen::Matrix2Xd mid(2, 1);
      mid.col(0) = basis::side_point(space.kind(e.element).shape, e.side, 0.5);
      basis::BasisValues bv;
      basis::GeometryValues gv;
      space.evaluate(e.element, mid, 1, bv);
      geometry.evaluate(e.element, bv, gv, false);
      problem.neumann_where->values(gv.x, where);
      neumann = where(0) > 0.0;
    }
    (neumann ? neumann_edges : dirichlet_edges).push_back(e);
  }
  if (!neumann_edges.empty() && !problem.neumann) throw InputError("Neumann boundary edges are selected but no Neumann data given");
  const bool singular = dirichlet_edges.empty() && problem.reaction == 0.0;
  if (singular && !problem.mean_zero) {
    throw InputError(std::string(space.boundary_edges().empty() ? "closed surface" : "no Dirichlet boundary") +
                     " and no reaction term: the solution is determined only up to a constant; keep a boundary "
                     "part Dirichlet, give a reaction coefficient c > 0, or ask for the mean-zero solution");
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
  r.neumann_edges = static_cast<Index>(neumann_edges.size());
  r.dirichlet_edges = static_cast<Index>(dirichlet_edges.size());
  DirichletConditions bc =
      project_dirichlet(assembler, dirichlet_edges, problem.dirichlet ? problem.dirichlet : constant_function(0.0));
  Eigen::VectorXd ones_load;  // m_i = ∫ φ_i, for the mean-zero constraint
  if (singular) {
    // The kernel is the constants (Σφ_i = 1): make the load orthogonal to them, pin one dof, and shift to
    // mean zero after the solve.
    Eigen::SparseMatrix<double> unused;
    const SourceForm one(constant_function(1.0));
    const std::vector<const LinearForm*> lf{&one};
    assembler.assemble({}, lf, unused, ones_load);
    r.mean_zero = true;
    r.compatibility_defect = b.sum();
    b -= (r.compatibility_defect / r.domain_measure) * ones_load;
    bc.dofs = {0};
    bc.values = Eigen::VectorXd::Zero(1);
  }
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
  std::shared_ptr<const Function> exact = problem.exact;
  if (singular) {
    r.u.array() -= ones_load.dot(r.u) / r.domain_measure;
    if (exact) {
      // Compare with the mean-zero representative of the exact solution.
      const Eigen::VectorXd mean = assembler.integrate(1, [&](const ElementContext& ctx, Eigen::Ref<Eigen::VectorXd> out) {
        Eigen::VectorXd ue;
        exact->values(ctx.geo.x, ue);
        out(0) = ue.dot(ctx.weight);
      });
      exact = shifted_function(exact, -mean(0) / r.domain_measure);
    }
  }
  if (exact) r.errors = compute_errors(assembler, r.u, *exact);
  return r;
}

}  // namespace iga::fem
