#include "fem/poisson.hpp"

#include <sstream>

#include "fem/expression.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>

#include "core/error.hpp"
#include "fem/assembler.hpp"
#include "fem/dirichlet.hpp"
#include "fem/linear_system.hpp"
#include "fem/nitsche.hpp"

namespace iga::fem {

namespace {
double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}
}  // namespace

struct PoissonSolver::Systems {
  std::unique_ptr<Assembler> assembler;
  DirichletConditions bc;
  std::unique_ptr<LinearSystem> system;
  Eigen::VectorXd ones_load;  // m_i = ∫ φ_i, for the mean-zero constraint
  std::chrono::steady_clock::time_point t0;
};

PoissonSolver::PoissonSolver(const basis::Geometry& geometry, const quadrature::RuleProvider& rules,
                             const PoissonProblem& problem, const SolverOptions& solver)
    : geometry_(geometry), rules_(rules), problem_(problem), solver_(solver), sys_(std::make_unique<Systems>()) {}

PoissonSolver::~PoissonSolver() = default;

const Assembler& PoissonSolver::assembler() const {
  if (!sys_->assembler) throw InputError("PoissonSolver: setup() has not run");
  return *sys_->assembler;
}

namespace {

std::vector<int> parse_parts(const std::string& list, const std::vector<std::string>& names) {
  std::vector<int> parts;
  std::stringstream ss(list);
  std::string item;
  while (std::getline(ss, item, ',')) {
    if (item.empty()) continue;
    int found = -1;
    for (std::size_t i = 0; i < names.size(); ++i) {
      if (names[i] == item || std::to_string(i) == item) found = static_cast<int>(i);
    }
    if (found < 0) {
      std::string known;
      for (std::size_t i = 0; i < names.size(); ++i) known += (i ? ", " : "") + names[i];
      throw InputError("--neumann-boundary: no boundary part '" + item + "' (parts: " + known + ", or their indices)");
    }
    parts.push_back(found);
  }
  return parts;
}

}  // namespace

void select_neumann(PoissonProblem& problem, const std::string& neumann, const std::string& boundary,
                    const std::string& where, const std::vector<std::string>& names) {
  if (!neumann.empty()) {
    problem.neumann = std::make_shared<Expression>(neumann, "--neumann", true);
    problem.neumann_parts = parse_parts(boundary, names);
    if (problem.neumann_parts.empty() && where.empty()) {
      throw InputError("--neumann needs --neumann-boundary or --neumann-where to say where");
    }
  } else if (!boundary.empty() || !where.empty()) {
    if (!problem.exact) throw InputError("--neumann-boundary/--neumann-where need --neumann data (or an exact solution)");
    problem.neumann = normal_flux(problem.exact);
    problem.neumann_parts = parse_parts(boundary, names);
  }
  if (!where.empty()) problem.neumann_where = std::make_shared<Expression>(where, "--neumann-where");
}

BoundarySplit split_boundary(const basis::Geometry& geometry, const PoissonProblem& problem) {
  const basis::Space& space = geometry.space();
  const int parts = static_cast<int>(space.boundary_part_names().size());
  for (int p : problem.neumann_parts) {
    if (p < 0 || p >= parts) throw InputError("Neumann boundary part " + std::to_string(p) + " does not exist");
  }
  BoundarySplit split;
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
    (neumann ? split.neumann : split.dirichlet).push_back(e);
  }
  return split;
}

DirichletMethod dirichlet_method(const std::string& word) {
  if (word == "strong") return DirichletMethod::kStrong;
  if (word == "nitsche") return DirichletMethod::kNitsche;
  throw InputError("Dirichlet method '" + word + "': unknown (known: strong, nitsche)");
}

void PoissonSolver::setup() {
  if (done_ >= 1) return;
  const basis::Space& space = geometry_.space();
  const PoissonProblem& problem = problem_;
  if (!(problem.nitsche_penalty >= 0) || !std::isfinite(problem.nitsche_penalty)) {
    throw InputError("Nitsche penalty must be a finite number >= 0 (0: the default), got " + std::to_string(problem.nitsche_penalty));
  }
  if (!(problem.reaction >= 0) || !std::isfinite(problem.reaction)) {
    throw InputError("reaction coefficient must be a finite number >= 0, got " + std::to_string(problem.reaction));
  }
  const std::vector<basis::BoundaryEdge> boundary = space.boundary_edges();
  BoundarySplit split = split_boundary(geometry_, problem);
  dirichlet_edges_ = std::move(split.dirichlet);
  neumann_edges_ = std::move(split.neumann);
  if (!neumann_edges_.empty() && !problem.neumann) throw InputError("Neumann boundary edges are selected but no Neumann data given");
  singular_ = dirichlet_edges_.empty() && problem.reaction == 0.0;
  if (singular_ && !problem.mean_zero) {
    throw InputError(std::string(boundary.empty() ? "closed surface" : "no Dirichlet boundary") +
                     " and no reaction term: the solution is determined only up to a constant; keep a boundary "
                     "part Dirichlet, give a reaction coefficient c > 0, or ask for the mean-zero solution");
  }
  r_.dofs = space.num_dofs();
  r_.elements = space.num_elements();
  r_.neumann_edges = static_cast<Index>(neumann_edges_.size());
  r_.dirichlet_edges = static_cast<Index>(dirichlet_edges_.size());
  sys_->t0 = std::chrono::steady_clock::now();
  sys_->assembler = std::make_unique<Assembler>(geometry_, rules_);
  sys_->system = make_linear_system(*sys_->assembler, solver_);  // its pattern and the colouring
  r_.pattern_seconds = seconds_since(sys_->t0);
  done_ = 1;
}

void PoissonSolver::assemble() {
  if (done_ >= 2) return;
  setup();
  const Assembler& assembler = *sys_->assembler;
  const PoissonProblem& problem = problem_;
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
  LinearSystem& system = *sys_->system;
  AssemblyStats stats;
  system.run_everywhere([&] { stats = assembler.assemble(bilinear, linear, system.sink()); });
  const AssemblyStats total = system.total(stats);  // a distributed system's ranks each took their own elements
  r_.domain_measure = total.measure;
  r_.quadrature_points = total.quadrature_points;

  // Boundary terms are small: every process computes them, and each adds the rows it owns.
  const Eigen::SparseMatrix<double> none;
  if (!neumann_edges_.empty()) {
    Eigen::VectorXd bn;
    const BoundaryLoadForm flux(problem.neumann);
    assembler.assemble_boundary(neumann_edges_, nullptr, &flux, nullptr, &bn);
    system.add(none, bn);
  }
  DirichletConditions& bc = sys_->bc;
  const std::shared_ptr<const Function> g = problem.dirichlet ? problem.dirichlet : constant_function(0.0);
  if (problem.dirichlet_method == DirichletMethod::kNitsche) {
    if (!dirichlet_edges_.empty()) {
      Eigen::SparseMatrix<double> an;
      Eigen::VectorXd bn;
      r_.nitsche_penalty = nitsche_terms(assembler, dirichlet_edges_, g, problem.nitsche_penalty, an, bn);
      system.add(an, bn);
    }
    bc = DirichletConditions{};
  } else {
    bc = project_dirichlet(assembler, dirichlet_edges_, g);
  }
  if (singular_) {
    // The kernel is the constants (Σφ_i = 1): make the load orthogonal to them, pin one dof, and shift to
    // mean zero after the solve.
    Eigen::SparseMatrix<double> unused;
    const SourceForm one(constant_function(1.0));
    const std::vector<const LinearForm*> lf{&one};
    assembler.assemble({}, lf, unused, sys_->ones_load);
    r_.mean_zero = true;
    r_.compatibility_defect = system.load_sum();
    system.add(none, (-r_.compatibility_defect / r_.domain_measure) * sys_->ones_load);
    bc.dofs = {0};
    bc.values = Eigen::VectorXd::Zero(1);
  }
  r_.dirichlet_dofs = static_cast<Index>(bc.dofs.size());
  r_.assembly_seconds = seconds_since(sys_->t0);
  done_ = 2;
}

void PoissonSolver::solve() {
  if (done_ >= 3) return;
  assemble();
  SolveResult s;
  try {
    s = sys_->system->solve(sys_->bc);
  } catch (const NumericalError& e) {
    // Only a fixed γ can be too small: the local estimate is coercive by construction.
    if (problem_.dirichlet_method != DirichletMethod::kNitsche || problem_.nitsche_penalty <= 0.0 ||
        std::string(e.what()).find("not positive definite") == std::string::npos) {
      throw;
    }
    std::ostringstream msg;
    msg << e.what() << " (Nitsche's penalty, γ = " << r_.nitsche_penalty
        << ", is too small for this space: raise --nitsche-penalty, or leave it 0 for the local estimate)";
    throw NumericalError(msg.str());
  }
  r_.solve_seconds = s.seconds;
  r_.solver = s.solver;
  r_.residual_norm = s.residual_norm;
  r_.solver_iterations = s.iterations;
  r_.solver_ordering = s.ordering;
  r_.free_dofs = s.free_dofs;
  r_.ranks = s.ranks;
  r_.elements_per_rank = s.elements_per_rank;
  r_.dofs_per_rank = s.dofs_per_rank;
  r_.element_owner = std::move(s.element_owner);
  r_.u = std::move(s.x);
  if (singular_) r_.u.array() -= sys_->ones_load.dot(r_.u) / r_.domain_measure;
  done_ = 3;
}

void PoissonSolver::errors() {
  if (done_ >= 4) return;
  solve();
  const auto t0 = std::chrono::steady_clock::now();
  std::shared_ptr<const Function> exact = problem_.exact;
  // The error norms' rules (finer than the assembly's), also for the mean of the exact solution below.
  const std::unique_ptr<quadrature::RuleProvider> finer = exact ? rules_.error_rules() : nullptr;
  std::optional<Assembler> error_assembler;
  if (finer) error_assembler.emplace(geometry_, *finer);
  const Assembler& norms = error_assembler ? *error_assembler : *sys_->assembler;
  // Each process integrates its own elements (all of them in a serial run), then the parts are summed.
  const LinearSystem& system = *sys_->system;
  const std::vector<char>* own = system.own_elements();
  if (exact && singular_) {
    // Compare with the mean-zero representative of the exact solution.
    Eigen::VectorXd mean;
    system.run_everywhere([&] {
      mean = norms.integrate(2, [&](const ElementContext& ctx, Eigen::Ref<Eigen::VectorXd> out) {
        Eigen::VectorXd ue;
        exact->values(ctx.geo.x, ue);
        out(0) = ue.dot(ctx.weight);
        out(1) = ctx.weight.sum();
      }, 1, own);
    });
    mean = system.sum(mean);
    exact = shifted_function(exact, -mean(0) / mean(1));
  }
  if (exact) {
    r_.error_quadrature = finer ? finer->name() : rules_.name();
    Eigen::Vector4d squares;
    system.run_everywhere([&] { squares = error_squares(norms, r_.u, *exact, own); });
    r_.errors = error_norms(system.sum(squares));
    if (!std::isfinite(r_.errors->l2) || !std::isfinite(r_.errors->h1) || !std::isfinite(r_.errors->l2_exact)) {
      throw NumericalError("the error norms against the exact solution are not finite (L2 " + std::to_string(r_.errors->l2) +
                           ", H1 " + std::to_string(r_.errors->h1) + "): does the exact solution overflow?");
    }
  }
  r_.error_seconds = seconds_since(t0);
  done_ = 4;
}

PoissonResult solve_poisson(const basis::Geometry& geometry, const quadrature::RuleProvider& rules,
                            const PoissonProblem& problem, const SolverOptions& solver) {
  PoissonSolver s(geometry, rules, problem, solver);
  s.setup();
  s.assemble();
  s.solve();
  s.errors();
  return s.result();
}

}  // namespace iga::fem
