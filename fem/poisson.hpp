#pragma once
// Poisson / Laplace (planar) and Laplace–Beltrami (surface) problems -Δu + c u = f with strong Dirichlet
// and natural Neumann conditions: the whole pipeline from a geometry to a solution and its report figures.
#include <Eigen/Core>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "basis/geometry.hpp"
#include "fem/compatibility.hpp"
#include "fem/errors.hpp"
#include "fem/function.hpp"
#include "fem/solver.hpp"
#include "quadrature/rule_provider.hpp"

namespace iga::fem {

/// How u = g is imposed on the Dirichlet parts: strongly (project_dirichlet: L2 projection onto the traces,
/// eliminated), or weakly by Nitsche's method (NitscheForm), which needs no trace space.
enum class DirichletMethod { kStrong, kNitsche };
/// "strong" / "nitsche"; InputError otherwise.
DirichletMethod dirichlet_method(const std::string& word);

struct PoissonProblem {
  std::shared_ptr<const Function> source;           ///< f; null means 0
  std::shared_ptr<const Function> dirichlet;        ///< g_D on the Dirichlet parts; null means 0
  std::shared_ptr<const BoundaryFunction> neumann;  ///< g_N = ∂u/∂n on the Neumann parts
  std::vector<int> neumann_parts;                   ///< indices into Space::boundary_part_names()
  /// Optional: a boundary edge is also Neumann when this is > 0 at the physical midpoint of the edge.
  std::shared_ptr<const Function> neumann_where;
  std::shared_ptr<const Function> exact;            ///< optional: enables error norms
  double reaction = 0.0;                            ///< c >= 0
  /// Without Dirichlet boundary and with c = 0 (a closed surface, or Neumann data everywhere) u is defined up
  /// to a constant: with mean_zero the solution with ∫u = 0 is returned (the load is made compatible by
  /// removing its mean, reported as compatibility_defect; error norms compare with exact - mean(exact)).
  bool mean_zero = false;
  /// Pure-Neumann data must satisfy ∫f + ∫g = 0 (fem/compatibility.hpp): a defect beyond kCompatibilityTolerance
  /// of ∫|f| + ∫|g| is refused (InputError naming both integrals) unless this is set, which removes any defect
  /// (for data known to belong to a nearby domain, e.g. a sphere's source on its Catmull–Clark surface).
  bool remove_incompatible = false;
  DirichletMethod dirichlet_method = DirichletMethod::kStrong;
  /// Nitsche's penalty: γ > 0 gives β = γ / h on every side (h its length); 0 (default) gives β_K from each
  /// element's local eigenvalue estimate (fem/nitsche.hpp), which is coercive by construction. A fixed γ that
  /// is too small leaves the system indefinite: the solve fails with a message naming it. (Measured with the
  /// clamped Catmull–Clark boundary: γ = 160 sufficed on regular nets, square_evs.obj needed more than 1600.)
  double nitsche_penalty = 0.0;
};

struct PoissonResult {
  Eigen::VectorXd u;                ///< coefficients of the solution in the geometry's space
  Index dofs = 0, free_dofs = 0, dirichlet_dofs = 0, elements = 0, quadrature_points = 0;
  double domain_measure = 0.0;      ///< area (planar) or surface area by the chosen quadrature
  double pattern_seconds = 0.0;     ///< sparsity pattern and colouring
  double assembly_seconds = 0.0;    ///< pattern + element loop + boundary terms + Dirichlet projection
  double solve_seconds = 0.0;
  double error_seconds = 0.0;       ///< error norms (with an exact solution)
  std::string error_quadrature;     ///< the rules of the error norms (RuleProvider::error_rules(), else the assembly's)
  std::string error_derivatives;    ///< how the exact solution's gradient in the H1 error was computed
  std::string solver;
  double residual_norm = 0.0;       ///< relative residual of the reduced system
  Index solver_iterations = 0;
  std::string solver_ordering;  ///< the direct solver's fill-reducing ordering ("amd", "metis"; empty for CG)
  MultigridFacts multigrid;     ///< --solver mg: levels, smoother, coarse solver
  int ranks = 1;                ///< processes that held the system (SolverKind::Petsc)
  std::vector<Index> elements_per_rank, dofs_per_rank;  ///< owned elements and dofs of each rank (PETSc)
  std::vector<int> element_owner;  ///< per element, the rank that assembled it (PETSc; for the output's pieces)
  PartitionFacts partition;        ///< how the elements were parted (PETSc on more than one rank)
  std::optional<ErrorNorms> errors; ///< with an exact solution
  Index neumann_edges = 0, dirichlet_edges = 0;
  double nitsche_penalty = 0.0;     ///< the γ used, or max_K β_K h_K of the local estimate (Nitsche only)
  bool mean_zero = false;           ///< the mean-zero constraint was applied
  double compatibility_defect = 0;  ///< ∫f + ∫g_N before it was removed (mean_zero only)
  Compatibility compatibility;      ///< the data's integrals and verdict (mean_zero only)
};

/// The boundary edges of a geometry split by the problem's selection (neumann_parts, neumann_where): the one
/// rule every program uses (the FEM here, the BEM in bem/). InputError for a part index that does not exist.
struct BoundarySplit {
  std::vector<basis::BoundaryEdge> dirichlet, neumann;
};
BoundarySplit split_boundary(const basis::Geometry& geometry, const PoissonProblem& problem);

/// The programs' Neumann selection (--neumann EXPR, --neumann-boundary PARTS, --neumann-where EXPR; empty = not
/// given) into problem: the data (the expression, else the normal flux of problem.exact), the parts (names in
/// `names` or their indices, comma-separated) and the geometric selector. InputError naming the option for an
/// unknown part, Neumann data without a place, or a place without data or an exact solution.
void select_neumann(PoissonProblem& problem, const std::string& neumann, const std::string& boundary,
                    const std::string& where, const std::vector<std::string>& names);

/// The pipeline in steps (deal.II step-6's setup_system / assemble_system / solve, DESIGN item 5): the one problem
/// pipeline (fem::ProblemSolver, fem/problem.hpp) run on Poisson's fem::Problem, with Poisson's figures; for loops
/// that need the pieces: setup() → assemble() → solve() → errors(), each once and in this order (a step
/// called out of order runs the missing ones first). The solver keeps references to geometry and rules (they must
/// outlive it) and a copy of the problem.
class PoissonSolver {
 public:
  PoissonSolver(const basis::Geometry& geometry, const quadrature::RuleProvider& rules, const PoissonProblem& problem,
                const SolverOptions& solver = {});
  ~PoissonSolver();
  PoissonSolver(const PoissonSolver&) = delete;
  PoissonSolver& operator=(const PoissonSolver&) = delete;

  /// Checks the problem, splits the boundary into Dirichlet and Neumann edges, builds the sparsity pattern.
  /// InputError for an ill-posed set-up (see solve_poisson).
  void setup();
  /// Element loop, Neumann load, Dirichlet projection, elimination (and the mean-zero treatment).
  void assemble();
  /// The reduced system's solution, expanded to all dofs (result().u).
  void solve();
  /// Error norms against problem.exact (nothing without one).
  void errors();

  const PoissonResult& result() const { return r_; }
  const basis::Geometry& geometry() const { return geometry_; }
  const PoissonProblem& problem() const { return problem_; }
  const Assembler& assembler() const;
  const std::vector<basis::BoundaryEdge>& neumann_edges() const { return neumann_edges_; }
  const std::vector<basis::BoundaryEdge>& dirichlet_edges() const { return dirichlet_edges_; }

 private:
  struct Systems;
  const basis::Geometry& geometry_;
  const quadrature::RuleProvider& rules_;
  PoissonProblem problem_;  // a copy (shared data): a temporary problem is safe
  SolverOptions solver_;
  PoissonResult r_;
  std::vector<basis::BoundaryEdge> neumann_edges_, dirichlet_edges_;
  bool singular_ = false;
  int done_ = 0;  // steps completed: 1 setup, 2 assemble, 3 solve, 4 errors
  std::unique_ptr<Systems> sys_;
};

/// Solves the problem: PoissonSolver's setup, assemble, solve and errors. InputError for an ill-posed set-up (every boundary part Neumann, or no boundary,
/// with c = 0 and no mean-zero constraint), for Neumann parts out of range, or Neumann parts without data.
PoissonResult solve_poisson(const basis::Geometry& geometry, const quadrature::RuleProvider& rules,
                            const PoissonProblem& problem, const SolverOptions& solver = {});

}  // namespace iga::fem
