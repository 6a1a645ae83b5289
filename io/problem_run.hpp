#pragma once
// What a solver program does around fem::ProblemSolver (fem/problem.hpp), in one place for every PDE: the
// pipeline's steps as progress phases (run_problem_program), the report's figures of a solve, the solver options of --solver and
// --petsc-options, and a run on the ranks of mpirun when the solver is PETSc.
#include <functional>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <utility>
#include <vector>

#include "fem/parallel.hpp"
#include "fem/problem.hpp"
#include "fem/threads.hpp"
#include "fem/solver.hpp"
#include "io/discretisation.hpp"
#include "io/progress.hpp"

namespace iga::io {

/// The figures every solve reports, of a fem::ProblemResult or a fem::PoissonResult r: domain_measure, threads, the
/// seconds of pattern and assembly (the slowest rank's: a distributed phase ends with it) and solve, ranks (with
/// elements_per_rank and dofs_per_rank when distributed), petsc_options, solver, solver_iterations,
/// solver_ordering, residual_norm and residual_tolerance; multigrid (levels, smoother, coarse_solver,
/// coarse_operators) for --solver mg.
template <class Result>
void report_solve(nlohmann::json& j, const Result& r, const fem::SolverOptions& solver) {
  j["domain_measure"] = r.domain_measure;
  j["threads"] = fem::num_threads();
  j["pattern_seconds"] = r.pattern_seconds;
  j["assembly_seconds"] = fem::max_over_ranks(r.assembly_seconds);
  j["solve_seconds"] = r.solve_seconds;
  j["ranks"] = r.ranks;
  if (r.ranks > 1 || !r.elements_per_rank.empty()) {
    j["elements_per_rank"] = r.elements_per_rank;
    j["dofs_per_rank"] = r.dofs_per_rank;
  }
  if (!r.partition.method.empty()) {
    j["partition"] = {{"method", r.partition.method}, {"seconds", r.partition.seconds},
                      {"interface_dofs", r.partition.interface_dofs}};
  }
  if (!solver.petsc_options.empty()) j["petsc_options"] = solver.petsc_options;
  j["solver"] = r.solver;
  j["solver_iterations"] = r.solver_iterations;
  j["solver_ordering"] = r.solver_ordering;
  j["residual_norm"] = r.residual_norm;
  j["residual_tolerance"] = solver.max_residual;
  if (r.multigrid.levels > 0) {
    j["multigrid"] = {{"levels", r.multigrid.levels}, {"smoother", r.multigrid.smoother},
                      {"coarse_solver", r.multigrid.coarse_solver}, {"coarse_operators", "galerkin"}};
  }
}

/// The report's figures of a solve r, into j (report_solve's, and): pde (the problem's name), dofs, free_dofs, constrained_dofs, elements, quadrature (the rules'
/// name), quadrature_points, error_quadrature, domain_measure, threads, the seconds of pattern, assembly (the
/// slowest rank's), solve and errors, ranks (with elements_per_rank and dofs_per_rank when distributed), solver,
/// solver_iterations, solver_ordering, residual_norm, residual_tolerance, petsc_options, the problem's choices
/// ({"what": "how"}) and errors: {"NAME": {"error", "exact", "relative"}} in the problem's order ("relative" null
/// when the exact solution's norm is 0), {} without an exact solution.
void report_problem_result(nlohmann::json& j, const fem::ProblemResult& r, const std::string& quadrature,
                           const fem::SolverOptions& solver);

/// --solver, --petsc-options and --partition (empty: the default, fem::SolverOptions::partition): InputError naming
/// --petsc-options or --partition when it is given for another solver, or an unknown partition. --solver mg: the
/// prolongations of the uniform refinement steps (basis::Refinement::steps) are its levels.
fem::SolverOptions solver_options(const std::string& solver, const std::string& petsc_options, const std::string& partition,
                                  std::vector<Eigen::SparseMatrix<double>> hierarchy = {});

/// Whether --solver runs on PETSc (petsc, and mg on a --basis whose spaces are nested: mg on another is refused
/// before any solve): the program opens a PETSc session (run_solver_program). Never throws.
bool solver_uses_petsc(const std::string& solver, const std::string& basis);

/// Runs body() (io::run_program's exit codes and one error line) — with petsc, inside a PETSc session on the ranks
/// of mpirun: PETSc reads no command-line option of its own (they come through --petsc-options and PETSC_OPTIONS),
/// the ranks other than 0 are quiet with stderr muted (their errors included), threads left at 0 become the
/// machine's processors shared among the ranks, and every rank waits at the end until rank 0 has written its lines
/// (mpirun ends the whole job at the first rank that exits non-zero).
int run_solver_program(const std::string& program, bool petsc, char** argv, bool& quiet, int& threads,
                       const std::function<int()>& body);

/// A solver program's run for one PDE (iga-biharmonic, iga-elasticity): everything but the PDE's own data and output.
struct ProblemProgram {
  explicit ProblemProgram(std::string name) : program(std::move(name)) {}
  std::string program;  ///< "iga-biharmonic": the log's and the progress' prefix
  DiscretisationOptions discretisation;
  std::string solver = "cholmod", petsc_options, partition;
  int threads = 0;          ///< 0: OpenMP's
  bool quiet = false;
  bool timer_table = true;  ///< the time per phase on stderr at the end
  double max_memory = 0.0;  ///< GiB; 0: what the system has available
  nlohmann::json run_info;  ///< io::run_info: the report starts with it
  int components = 1;  ///< of the field (the memory check before the problem is made)
  /// Bytes of the output per element (0: none written), for the memory check before the work.
  double output_bytes_per_element = 0.0;
  /// The problem on the refined geometry (with what its backend told of it: facts.fit_distance, how far points given
  /// on an exact shape may lie from a fitted geometry); describes its data in report["problem"].
  std::function<std::shared_ptr<const fem::Problem>(const basis::Geometry&, const basis::BackendFacts& facts,
                                                    nlohmann::json& report)>
      problem;
  /// Writes the output of the solve (every rank calls it: a distributed run writes its pieces), names the files in
  /// the report; runs as the phase "output".
  std::function<void(const basis::Geometry&, const fem::ProblemResult&, nlohmann::json& report)> output;
  /// The paths `output` writes ("none" or empty: none), checked before the work (io::check_writable).
  std::vector<std::string> output_paths;
  /// The JSON report's path ("none" or empty: none): checked before the work, written (rank 0) at the end.
  std::string json;
};

/// The run: the discretisation (its size checked against the memory before it is made: the solve of
/// components × (degree + 1)² functions per element and the output), the problem, the pipeline in phases, the
/// output; returns the report (run_info, discretisation_report, report_problem_result, total and phase seconds),
/// written to run.json. Every output path is checked first: an unwritable one is the only line, before any work.
/// The log goes to stderr as "PROGRAM: ..." unless quiet.
nlohmann::json run_problem_program(const ProblemProgram& run);

}  // namespace iga::io
