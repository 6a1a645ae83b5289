#pragma once
// One problem pipeline (DESIGN.md item 1): setup → assemble → solve → errors for any PDE that says what it
// assembles. A PDE implements fem::Problem in its own folder (pde/<name>/); the pipeline owns the assembler, the
// linear system (CHOLMOD, CG, or PETSc under MPI: fem/linear_system.hpp) and the report, and never names a PDE.
#include <Eigen/Core>
#include <functional>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "basis/geometry.hpp"
#include "fem/assembler.hpp"
#include "fem/dirichlet.hpp"
#include "fem/errors.hpp"
#include "fem/forms.hpp"
#include "fem/function.hpp"
#include "fem/solver.hpp"
#include "quadrature/rule_provider.hpp"

namespace iga::fem {

class LinearSystem;

/// Settings a problem chose and reports, in order: ("clamped parts", "v0, u1: u strong, ∂u/∂n by Nitsche").
using Choices = std::vector<std::pair<std::string, std::string>>;

/// What a PDE gives the pipeline. The forms it returns live as long as the problem.
class Problem {
 public:
  virtual ~Problem() = default;
  /// As in reports and messages: "biharmonic".
  virtual std::string name() const = 0;
  /// The number of components of the unknown field (DESIGN.md item 2): 1 scalar, 2 a planar displacement, ...
  virtual int components() const { return 1; }
  /// Checks the set-up against the geometry before anything is built: InputError (or UnsupportedError) naming what
  /// is wrong, in the user's terms (a boundary part, an element).
  virtual void check(const basis::Geometry& geometry) const = 0;
  virtual std::vector<const BilinearForm*> bilinear_forms() const = 0;
  virtual std::vector<const LinearForm*> linear_forms() const = 0;
  /// Boundary terms every process computes alike (natural loads, Nitsche's terms), through system.add(); what was
  /// chosen goes into choices.
  virtual void add_boundary_terms(const Assembler& assembler, LinearSystem& system, Choices& choices) const = 0;
  /// The essential conditions, applied after assembly as the reduced system.
  virtual DirichletConditions constraints(const Assembler& assembler, Choices& choices) const = 0;
  /// A failed solve's message, with what this problem knows of its cause (a Nitsche penalty too small): by default
  /// as it is.
  virtual std::string explain_solve_failure(const std::string& message) const { return message; }
  /// The solution after the solve, on every process (a constant removed for a mean-zero solution): by default as it
  /// is.
  virtual void finish(const Assembler& /*assembler*/, Eigen::VectorXd& /*u*/) const {}
  /// Scalar quantities of the solution a report shows beside the error norms (a shell's strain energy), in report
  /// order, computed on every process after finish(); none by default.
  virtual std::vector<std::pair<std::string, double>> quantities(const Assembler& /*assembler*/,
                                                              const Eigen::VectorXd& /*u*/) const {
    return {};
  }
  /// The error figures, in report order; none without an exact solution.
  virtual std::vector<std::string> error_names() const = 0;
  /// Their squares over the whole domain, error² and exact² per name and (optionally) the squared estimates of
  /// finite-difference derivatives' errors (norm_squares' layout), by the assembler `by`
  /// (the error rules; scalar, on the same geometry): each process integrates system.own_elements() and the parts
  /// are summed over the processes (summed_squares() does both).
  virtual Eigen::VectorXd error_squares(const Assembler& by, const Eigen::VectorXd& u,
                                        const LinearSystem& system) const = 0;
  /// How each figure uses the exact solution's derivatives (fem::derivatives_in: "values", "closed form",
  /// "symbolic (GiNaC)", "finite differences ..."), in the order of error_names(): what a report says of how its
  /// figures were computed. Empty: not said.
  virtual std::vector<std::string> error_derivatives() const { return {}; }
};

/// Boundary parts named in a comma-separated list, by name (Space::boundary_part_names(): "v0", "b0.1", ...) or
/// 0-based index, or "all"; in the order given. InputError naming the option for a part that does not exist ("<what>:
/// no boundary part 'x' (parts: ...)") and for one named twice (by name, index or "all"). An empty list gives none.
std::vector<int> parse_boundary_parts(const std::string& list, const std::vector<std::string>& names,
                                      const std::string& what);

/// The boundary edges of `edges` on the parts `parts` (Space::boundary_part_names() indices), in order.
std::vector<basis::BoundaryEdge> edges_on(const std::vector<basis::BoundaryEdge>& edges, const std::vector<int>& parts);
/// The parts by name, comma-separated ("v0, u1"): what a problem reports of a condition.
std::string part_names(const std::vector<int>& parts, const std::vector<std::string>& names);
/// A condition item's fields: the text split at `separator`, each trimmed of blanks ("x; v0 ; 0" → x, v0, 0).
std::vector<std::string> item_fields(const std::string& text, char separator = ';');

/// f(only) on each process for its own elements (LinearSystem::run_everywhere: a failure anywhere fails all),
/// summed over the processes.
Eigen::VectorXd summed_squares(const LinearSystem& system,
                               const std::function<Eigen::VectorXd(const std::vector<char>* only)>& f);

struct ProblemResult {
  std::string problem;              ///< Problem::name()
  Eigen::VectorXd u;                ///< coefficients of the solution in the geometry's space
  Index dofs = 0;  ///< of the field: components × the space's functions
  Index free_dofs = 0, constrained_dofs = 0, elements = 0, quadrature_points = 0;
  double domain_measure = 0.0;
  double pattern_seconds = 0.0, assembly_seconds = 0.0, solve_seconds = 0.0, error_seconds = 0.0;
  std::string solver, solver_ordering, error_quadrature;
  double residual_norm = 0.0;
  Index solver_iterations = 0;
  MultigridFacts multigrid;  ///< --solver mg: levels, smoother, coarse solver
  int ranks = 1;
  std::vector<Index> elements_per_rank, dofs_per_rank;  ///< owned elements and dofs of each rank (PETSc)
  std::vector<int> element_owner;  ///< per element, the rank that assembled it (PETSc; for the output's pieces)
  PartitionFacts partition;        ///< how the elements were parted (PETSc on more than one rank)
  std::vector<NormError> errors;    ///< with an exact solution, in the order of Problem::error_names()
  Choices choices;
  std::vector<std::pair<std::string, double>> quantities;  ///< Problem::quantities
  /// The figure of that name; InputError when it was not computed.
  const NormError& error(const std::string& name) const;
};

/// The pipeline in steps, each once and in order (a step called out of order runs the missing ones first). Keeps
/// references to geometry and rules (they must outlive it) and shares the problem.
class ProblemSolver {
 public:
  ProblemSolver(const basis::Geometry& geometry, const quadrature::RuleProvider& rules,
                std::shared_ptr<const Problem> problem, const SolverOptions& solver = {});
  ~ProblemSolver();
  ProblemSolver(const ProblemSolver&) = delete;
  ProblemSolver& operator=(const ProblemSolver&) = delete;

  void setup();     ///< Problem::check, the assembler, the system's pattern
  void assemble();  ///< element loop, boundary terms, constraints
  void solve();     ///< the reduced system's solution, expanded to all dofs
  void errors();    ///< the problem's norms against its exact solution (nothing without one)

  const ProblemResult& result() const { return r_; }
  const Assembler& assembler() const;
  const Problem& problem() const { return *problem_; }

 private:
  struct Systems;
  const basis::Geometry& geometry_;
  const quadrature::RuleProvider& rules_;
  std::shared_ptr<const Problem> problem_;
  SolverOptions solver_;
  ProblemResult r_;
  int done_ = 0;
  std::unique_ptr<Systems> sys_;
};

/// setup, assemble, solve and errors in one call.
ProblemResult solve_problem(const basis::Geometry& geometry, const quadrature::RuleProvider& rules,
                            std::shared_ptr<const Problem> problem, const SolverOptions& solver = {});

}  // namespace iga::fem
