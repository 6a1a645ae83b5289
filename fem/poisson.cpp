#include "fem/poisson.hpp"

#include <sstream>
#include <span>

#include "fem/expression.hpp"

#include <algorithm>
#include <cmath>

#include "core/error.hpp"
#include "fem/assembler.hpp"
#include "fem/dirichlet.hpp"
#include "fem/linear_system.hpp"
#include "fem/nitsche.hpp"
#include "fem/problem.hpp"

namespace iga::fem {


void select_neumann(PoissonProblem& problem, const std::string& neumann, const std::string& boundary,
                    const std::string& where, const std::vector<std::string>& names) {
  if (!neumann.empty()) {
    problem.neumann = std::make_shared<Expression>(neumann, "--neumann", true);
    problem.neumann_parts = parse_boundary_parts(boundary, names, "--neumann-boundary");
    if (problem.neumann_parts.empty() && where.empty()) {
      throw InputError("--neumann needs --neumann-boundary or --neumann-where to say where");
    }
  } else if (!boundary.empty() || !where.empty()) {
    if (!problem.exact) throw InputError("--neumann-boundary/--neumann-where need --neumann data (or an exact solution)");
    problem.neumann = normal_flux(problem.exact);
    problem.neumann_parts = parse_boundary_parts(boundary, names, "--neumann-boundary");
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

namespace {

// |g| of a Neumann datum, for the scale of its integral.
class AbsBoundaryFunction final : public BoundaryFunction {
 public:
  explicit AbsBoundaryFunction(std::shared_ptr<const BoundaryFunction> g) : g_(std::move(g)) {}
  void values(const Eigen::Matrix3Xd& x, const Eigen::Matrix3Xd& n, Eigen::VectorXd& out) const override {
    g_->values(x, n, out);
    out = out.cwiseAbs();
  }

 private:
  std::shared_ptr<const BoundaryFunction> g_;
};

// ∫f, ∫|f| over the domain and ∫g, ∫|g| over the Neumann edges by the rules of `by` (every element, on every process).
DataIntegrals data_integrals(const Assembler& by, const std::shared_ptr<const Function>& f,
                             const std::shared_ptr<const BoundaryFunction>& g, std::span<const basis::BoundaryEdge> edges) {
  DataIntegrals d;
  if (f) {
    const Eigen::VectorXd s = by.integrate(2, [&](const ElementContext& ctx, Eigen::Ref<Eigen::VectorXd> out) {
      Eigen::VectorXd v;
      f->values(ctx.geo.x, v);
      out(0) = v.dot(ctx.weight);
      out(1) = v.cwiseAbs().dot(ctx.weight);
    });
    d.source = s(0);
    d.source_abs = s(1);
  }
  if (g && !edges.empty()) {
    Eigen::VectorXd b;
    const BoundaryLoadForm flux(g), magnitude(std::make_shared<AbsBoundaryFunction>(g));
    by.assemble_boundary(edges, nullptr, &flux, nullptr, &b);
    d.neumann = b.sum();
    by.assemble_boundary(edges, nullptr, &magnitude, nullptr, &b);
    d.neumann_abs = b.sum();
  }
  return d;
}

// −Δu + c u = f as a fem::Problem: Poisson's pieces for the one pipeline (fem/problem.hpp).
class PoissonPde final : public Problem {
 public:
  explicit PoissonPde(const PoissonProblem& problem) : p_(problem), reaction_(problem.reaction) {
    if (p_.source) source_ = std::make_unique<SourceForm>(p_.source);
  }
  std::string name() const override { return "poisson"; }

  void check(const basis::Geometry& geometry) const override {
    if (!(p_.nitsche_penalty >= 0) || !std::isfinite(p_.nitsche_penalty)) {
      throw InputError("Nitsche penalty must be a finite number >= 0 (0: the default), got " + std::to_string(p_.nitsche_penalty));
    }
    if (!(p_.reaction >= 0) || !std::isfinite(p_.reaction)) {
      throw InputError("reaction coefficient must be a finite number >= 0, got " + std::to_string(p_.reaction));
    }
    const bool no_boundary = geometry.space().boundary_edges().empty();
    BoundarySplit split = split_boundary(geometry, p_);
    dirichlet_ = std::move(split.dirichlet);
    neumann_ = std::move(split.neumann);
    if (!neumann_.empty() && !p_.neumann) throw InputError("Neumann boundary edges are selected but no Neumann data given");
    singular_ = dirichlet_.empty() && p_.reaction == 0.0;
    if (p_.mean_zero && !singular_) {
      throw InputError(std::string("the mean-zero solution was asked for, but ") +
                       (dirichlet_.empty() ? "the reaction term c > 0" : "the Dirichlet boundary") +
                       " already makes the solution unique (the mean-zero constraint would change it): leave it out");
    }
    if (singular_ && !p_.mean_zero) {
      throw InputError(std::string(no_boundary ? "closed surface" : "no Dirichlet boundary") +
                       " and no reaction term: the solution is determined only up to a constant; keep a boundary "
                       "part Dirichlet, give a reaction coefficient c > 0, or ask for the mean-zero solution");
    }
  }

  std::vector<const BilinearForm*> bilinear_forms() const override {
    if (p_.reaction != 0.0) return {&stiffness_, &reaction_};
    return {&stiffness_};
  }
  std::vector<const LinearForm*> linear_forms() const override {
    if (source_) return {source_.get()};
    return {};
  }

  // Boundary terms are small: every process computes them, and each adds the rows it owns.
  void add_boundary_terms(const Assembler& assembler, LinearSystem& system, Choices&) const override {
    const Eigen::SparseMatrix<double> none;
    if (!neumann_.empty()) {
      Eigen::VectorXd bn;
      const BoundaryLoadForm flux(p_.neumann);
      assembler.assemble_boundary(neumann_, nullptr, &flux, nullptr, &bn);
      system.add(none, bn);
    }
    if (p_.dirichlet_method == DirichletMethod::kNitsche && !dirichlet_.empty()) {
      Eigen::SparseMatrix<double> an;
      Eigen::VectorXd bn;
      penalty_ = nitsche_terms(assembler, dirichlet_, dirichlet_data(), p_.nitsche_penalty, an, bn);
      system.add(an, bn);
    }
    if (singular_) {
      // The kernel is the constants (Σφ_i = 1): make the load orthogonal to them, pin one dof, and shift to
      // mean zero after the solve.
      Eigen::SparseMatrix<double> unused;
      const SourceForm one(constant_function(1.0));
      const std::vector<const LinearForm*> lf{&one};
      assembler.assemble({}, lf, unused, ones_load_);
      measure_ = ones_load_.sum();
      defect_ = system.load_sum();
      check_data(assembler);
      system.add(none, (-defect_ / measure_) * ones_load_);
    }
  }

  DirichletConditions constraints(const Assembler& assembler, Choices&) const override {
    if (singular_) {
      DirichletConditions bc;
      bc.dofs = {0};
      bc.values = Eigen::VectorXd::Zero(1);
      return bc;
    }
    if (p_.dirichlet_method == DirichletMethod::kNitsche) return {};
    return project_dirichlet(assembler, dirichlet_, dirichlet_data());
  }

  std::string explain_solve_failure(const std::string& message) const override {
    // Only a fixed γ can be too small: the local estimate is coercive by construction.
    if (p_.dirichlet_method != DirichletMethod::kNitsche || p_.nitsche_penalty <= 0.0 ||
        message.find("not positive definite") == std::string::npos) {
      return message;
    }
    std::ostringstream msg;
    msg << message << " (Nitsche's penalty, γ = " << penalty_
        << ", is too small for this space: raise --nitsche-penalty, or leave it 0 for the local estimate)";
    return msg.str();
  }

  void finish(const Assembler&, Eigen::VectorXd& u) const override {
    if (singular_) u.array() -= ones_load_.dot(u) / measure_;
  }

  std::vector<std::string> error_names() const override {
    if (!p_.exact) return {};
    return {"L2", "H1"};
  }
  std::vector<std::string> error_derivatives() const override {
    if (!p_.exact) return {};
    return {derivatives_in(Norm::kL2, *p_.exact), derivatives_in(Norm::kH1, *p_.exact)};
  }
  Eigen::VectorXd error_squares(const Assembler& by, const Eigen::VectorXd& u,
                                const LinearSystem& system) const override {
    std::shared_ptr<const Function> exact = p_.exact;
    if (singular_) {
      // Compare with the mean-zero representative of the exact solution.
      const Eigen::VectorXd mean = summed_squares(system, [&](const std::vector<char>* only) -> Eigen::VectorXd {
        return by.integrate(2, [&](const ElementContext& ctx, Eigen::Ref<Eigen::VectorXd> out) {
          Eigen::VectorXd ue;
          exact->values(ctx.geo.x, ue);
          out(0) = ue.dot(ctx.weight);
          out(1) = ctx.weight.sum();
        }, 1, only);
      });
      exact = shifted_function(exact, -mean(0) / mean(1));
    }
    const Norm norms[2] = {Norm::kL2, Norm::kH1};
    return summed_squares(system, [&](const std::vector<char>* only) { return norm_squares(by, u, *exact, norms, only); });
  }

  const std::vector<basis::BoundaryEdge>& dirichlet() const { return dirichlet_; }
  const std::vector<basis::BoundaryEdge>& neumann() const { return neumann_; }
  bool singular() const { return singular_; }
  double penalty() const { return penalty_; }
  double defect() const { return defect_; }
  const Compatibility& compatibility() const { return compatibility_; }

 private:
  // The solvability condition ∫f + ∫g = 0, by the assembly's rules and by the finer error rules: refused beyond
  // the tolerance unless the problem asks for the defect to be removed.
  void check_data(const Assembler& assembler) const {
    const std::unique_ptr<quadrature::RuleProvider> finer = assembler.rules().error_rules();
    compatibility_.assembly = data_integrals(assembler, p_.source, p_.neumann, neumann_);
    compatibility_.finer = finer ? data_integrals(Assembler(assembler.geometry(), *finer), p_.source, p_.neumann, neumann_)
                                 : compatibility_.assembly;
    if (p_.remove_incompatible) return;
    check_compatibility(compatibility_, assembler.geometry().space().boundary_edges().empty()
                                            ? "make the data compatible, or give a reaction term c > 0"
                                            : "make the data compatible, or give a Dirichlet part or a reaction term c > 0");
  }

  std::shared_ptr<const Function> dirichlet_data() const {
    return p_.dirichlet ? p_.dirichlet : constant_function(0.0);
  }

  PoissonProblem p_;
  StiffnessForm stiffness_;
  MassForm reaction_;
  std::unique_ptr<SourceForm> source_;
  // From check() and the assembly (each runs once, in the pipeline's order).
  mutable std::vector<basis::BoundaryEdge> dirichlet_, neumann_;
  mutable bool singular_ = false;
  mutable Eigen::VectorXd ones_load_;  // m_i = ∫ φ_i, for the mean-zero constraint
  mutable double measure_ = 0.0, defect_ = 0.0, penalty_ = 0.0;
  mutable Compatibility compatibility_;
};

}  // namespace

struct PoissonSolver::Systems {
  std::shared_ptr<const PoissonPde> pde;
  std::unique_ptr<ProblemSolver> pipeline;
};

PoissonSolver::PoissonSolver(const basis::Geometry& geometry, const quadrature::RuleProvider& rules,
                             const PoissonProblem& problem, const SolverOptions& solver)
    : geometry_(geometry), rules_(rules), problem_(problem), solver_(solver), sys_(std::make_unique<Systems>()) {
  sys_->pde = std::make_shared<const PoissonPde>(problem_);
  sys_->pipeline = std::make_unique<ProblemSolver>(geometry_, rules_, sys_->pde, solver_);
}

PoissonSolver::~PoissonSolver() = default;

const Assembler& PoissonSolver::assembler() const {
  if (done_ < 1) throw InputError("PoissonSolver: setup() has not run");
  return sys_->pipeline->assembler();
}

void PoissonSolver::setup() {
  if (done_ >= 1) return;
  sys_->pipeline->setup();
  const ProblemResult& p = sys_->pipeline->result();
  dirichlet_edges_ = sys_->pde->dirichlet();
  neumann_edges_ = sys_->pde->neumann();
  singular_ = sys_->pde->singular();
  r_.dofs = p.dofs;
  r_.elements = p.elements;
  r_.neumann_edges = static_cast<Index>(neumann_edges_.size());
  r_.dirichlet_edges = static_cast<Index>(dirichlet_edges_.size());
  r_.pattern_seconds = p.pattern_seconds;
  done_ = 1;
}

void PoissonSolver::assemble() {
  if (done_ >= 2) return;
  setup();
  sys_->pipeline->assemble();
  const ProblemResult& p = sys_->pipeline->result();
  r_.domain_measure = p.domain_measure;
  r_.quadrature_points = p.quadrature_points;
  r_.nitsche_penalty = sys_->pde->penalty();
  r_.mean_zero = singular_;
  r_.compatibility_defect = sys_->pde->defect();
  r_.compatibility = sys_->pde->compatibility();
  r_.dirichlet_dofs = p.constrained_dofs;
  r_.assembly_seconds = p.assembly_seconds;
  done_ = 2;
}

void PoissonSolver::solve() {
  if (done_ >= 3) return;
  assemble();
  sys_->pipeline->solve();
  const ProblemResult& p = sys_->pipeline->result();
  r_.solve_seconds = p.solve_seconds;
  r_.solver = p.solver;
  r_.residual_norm = p.residual_norm;
  r_.solver_iterations = p.solver_iterations;
  r_.solver_ordering = p.solver_ordering;
  r_.multigrid = p.multigrid;
  r_.free_dofs = p.free_dofs;
  r_.ranks = p.ranks;
  r_.elements_per_rank = p.elements_per_rank;
  r_.dofs_per_rank = p.dofs_per_rank;
  r_.element_owner = p.element_owner;
  r_.partition = p.partition;
  r_.u = p.u;
  done_ = 3;
}

void PoissonSolver::errors() {
  if (done_ >= 4) return;
  solve();
  sys_->pipeline->errors();
  const ProblemResult& p = sys_->pipeline->result();
  if (!p.errors.empty()) {
    r_.error_quadrature = p.error_quadrature;
    r_.errors = ErrorNorms{p.error("L2").error, p.error("H1").error, p.error("L2").exact, p.error("H1").exact};
    r_.error_derivatives = p.error("H1").derivatives;
  }
  r_.error_seconds = p.error_seconds;
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
