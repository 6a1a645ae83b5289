#include "fem/problem.hpp"

#include <algorithm>
#include <chrono>
#include <sstream>
#include <optional>

#include "core/error.hpp"
#include "fem/linear_system.hpp"

namespace iga::fem {

namespace {
double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}
}  // namespace

const NormError& ProblemResult::error(const std::string& name) const {
  for (const NormError& e : errors) {
    if (e.name == name) return e;
  }
  throw InputError("the " + name + " error was not computed (no exact solution, or not one of the problem's norms)");
}

struct ProblemSolver::Systems {
  std::unique_ptr<Assembler> assembler;
  std::unique_ptr<LinearSystem> system;
  DirichletConditions bc;
  std::chrono::steady_clock::time_point t0;
};

ProblemSolver::ProblemSolver(const basis::Geometry& geometry, const quadrature::RuleProvider& rules,
                             std::shared_ptr<const Problem> problem, const SolverOptions& solver)
    : geometry_(geometry), rules_(rules), problem_(std::move(problem)), solver_(solver),
      sys_(std::make_unique<Systems>()) {
  if (!problem_) throw InputError("ProblemSolver: no problem given");
}

ProblemSolver::~ProblemSolver() = default;

const Assembler& ProblemSolver::assembler() const {
  if (!sys_->assembler) throw InputError("ProblemSolver: setup() has not run");
  return *sys_->assembler;
}

void ProblemSolver::setup() {
  if (done_ >= 1) return;
  problem_->check(geometry_);
  const basis::Space& space = geometry_.space();
  r_.problem = problem_->name();
  r_.dofs = problem_->components() * space.num_dofs();
  r_.elements = space.num_elements();
  sys_->t0 = std::chrono::steady_clock::now();
  sys_->assembler = std::make_unique<Assembler>(geometry_, rules_, problem_->components());
  sys_->system = make_linear_system(*sys_->assembler, solver_);
  r_.pattern_seconds = seconds_since(sys_->t0);
  done_ = 1;
}

void ProblemSolver::assemble() {
  if (done_ >= 2) return;
  setup();
  const Assembler& assembler = *sys_->assembler;
  LinearSystem& system = *sys_->system;
  const std::vector<const BilinearForm*> bilinear = problem_->bilinear_forms();
  const std::vector<const LinearForm*> linear = problem_->linear_forms();
  AssemblyStats stats;
  system.run_everywhere([&] { stats = assembler.assemble(bilinear, linear, system.sink()); });
  const AssemblyStats total = system.total(stats);
  r_.domain_measure = total.measure;
  r_.quadrature_points = total.quadrature_points;
  problem_->add_boundary_terms(assembler, system, r_.choices);
  sys_->bc = problem_->constraints(assembler, r_.choices);
  r_.constrained_dofs = static_cast<Index>(sys_->bc.dofs.size());
  r_.assembly_seconds = seconds_since(sys_->t0);
  done_ = 2;
}

void ProblemSolver::solve() {
  if (done_ >= 3) return;
  assemble();
  SolveResult s;
  try {
    s = sys_->system->solve(sys_->bc);
  } catch (const NumericalError& e) {
    const std::string explained = problem_->explain_solve_failure(e.what());
    if (explained == e.what()) throw;
    throw NumericalError(explained);
  }
  r_.solve_seconds = s.seconds;
  r_.solver = s.solver;
  r_.solver_ordering = s.ordering;
  r_.residual_norm = s.residual_norm;
  r_.solver_iterations = s.iterations;
  r_.multigrid = s.multigrid;
  r_.free_dofs = s.free_dofs;
  r_.ranks = s.ranks;
  r_.elements_per_rank = std::move(s.elements_per_rank);
  r_.dofs_per_rank = std::move(s.dofs_per_rank);
  r_.element_owner = std::move(s.element_owner);
  r_.partition = s.partition;
  r_.u = std::move(s.x);
  problem_->finish(*sys_->assembler, r_.u);
  r_.quantities = problem_->quantities(*sys_->assembler, r_.u);
  done_ = 3;
}

void ProblemSolver::errors() {
  if (done_ >= 4) return;
  solve();
  const auto t0 = std::chrono::steady_clock::now();
  const std::vector<std::string> names = problem_->error_names();
  if (!names.empty()) {
    const std::unique_ptr<quadrature::RuleProvider> finer = rules_.error_rules();
    std::optional<Assembler> error_assembler;
    error_assembler.emplace(geometry_, finer ? *finer : rules_);
    const Assembler& by = *error_assembler;
    r_.error_quadrature = finer ? finer->name() : rules_.name();
    r_.errors = norm_errors(names, problem_->error_squares(by, r_.u, *sys_->system), problem_->error_derivatives());
  }
  r_.error_seconds = seconds_since(t0);
  done_ = 4;
}

std::vector<basis::BoundaryEdge> edges_on(const std::vector<basis::BoundaryEdge>& edges, const std::vector<int>& parts) {
  std::vector<basis::BoundaryEdge> out;
  for (const basis::BoundaryEdge& e : edges) {
    if (std::find(parts.begin(), parts.end(), e.part) != parts.end()) out.push_back(e);
  }
  return out;
}

std::string part_names(const std::vector<int>& parts, const std::vector<std::string>& names) {
  std::string out;
  for (int p : parts) out += (out.empty() ? "" : ", ") + names[static_cast<std::size_t>(p)];
  return out;
}

std::vector<std::string> item_fields(const std::string& text, char separator) {
  std::vector<std::string> out;
  std::stringstream ss(text);
  std::string item;
  while (std::getline(ss, item, separator)) {
    item.erase(0, item.find_first_not_of(" \t"));
    item.erase(item.find_last_not_of(" \t") + 1);
    out.push_back(item);
  }
  return out;
}

std::vector<int> parse_boundary_parts(const std::string& list, const std::vector<std::string>& names,
                                      const std::string& what) {
  std::vector<int> parts;
  std::stringstream ss(list);
  std::string item;
  while (std::getline(ss, item, ',')) {
    item.erase(0, item.find_first_not_of(" \t"));
    item.erase(item.find_last_not_of(" \t") + 1);
    if (item.empty()) continue;
    if (item == "all") {
      for (std::size_t i = 0; i < names.size(); ++i) parts.push_back(static_cast<int>(i));
      continue;
    }
    int found = -1;
    for (std::size_t i = 0; i < names.size(); ++i) {
      if (names[i] == item || std::to_string(i) == item) found = static_cast<int>(i);
    }
    if (found < 0) {
      std::string known;
      for (std::size_t i = 0; i < names.size(); ++i) known += (i ? ", " : "") + names[i];
      throw InputError(what + ": no boundary part '" + item + "' (parts: " + known + ", their indices, or all)");
    }
    parts.push_back(found);
  }
  for (std::size_t i = 0; i < parts.size(); ++i) {
    if (std::find(parts.begin(), parts.begin() + static_cast<std::ptrdiff_t>(i), parts[i]) != parts.begin() + static_cast<std::ptrdiff_t>(i)) {
      throw InputError(what + ": boundary part '" + names[static_cast<std::size_t>(parts[i])] + "' is named twice (\"" + list + "\")");
    }
  }
  return parts;
}

Eigen::VectorXd summed_squares(const LinearSystem& system,
                               const std::function<Eigen::VectorXd(const std::vector<char>* only)>& f) {
  Eigen::VectorXd own;
  system.run_everywhere([&] { own = f(system.own_elements()); });
  return system.sum(own);
}

ProblemResult solve_problem(const basis::Geometry& geometry, const quadrature::RuleProvider& rules,
                            std::shared_ptr<const Problem> problem, const SolverOptions& solver) {
  ProblemSolver s(geometry, rules, std::move(problem), solver);
  s.errors();
  return s.result();
}

}  // namespace iga::fem
