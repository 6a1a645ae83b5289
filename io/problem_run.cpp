#include "io/problem_run.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <iomanip>
#include <iostream>
#include <sstream>
#include <optional>
#include <thread>

#include "core/error.hpp"
#include "fem/partition.hpp"
#include "fem/memory.hpp"
#include "fem/parallel.hpp"
#include "fem/threads.hpp"
#include "io/report.hpp"
#include "io/run_program.hpp"

namespace iga::io {

void report_problem_result(nlohmann::json& j, const fem::ProblemResult& r, const std::string& quadrature,
                           const fem::SolverOptions& solver) {
  j["pde"] = r.problem;
  j["dofs"] = r.dofs;
  j["free_dofs"] = r.free_dofs;
  j["constrained_dofs"] = r.constrained_dofs;
  j["elements"] = r.elements;
  j["quadrature"] = quadrature;
  j["quadrature_points"] = r.quadrature_points;
  if (!r.error_quadrature.empty()) j["error_quadrature"] = r.error_quadrature;
  j["error_seconds"] = r.error_seconds;
  report_solve(j, r, solver);
  j["choices"] = nlohmann::json::object();
  for (const auto& [what, how] : r.choices) j["choices"][what] = how;
  if (!r.quantities.empty()) {
    j["quantities"] = nlohmann::json::object();
    for (const auto& [name, value] : r.quantities) j["quantities"][name] = value;
  }
  j["errors"] = nlohmann::json::object();
  j["error_order"] = nlohmann::json::array();
  for (const fem::NormError& e : r.errors) {
    j["errors"][e.name] = {{"error", e.error}, {"exact", e.exact},
                           {"relative", e.exact > 0 ? nlohmann::json(e.error / e.exact) : nlohmann::json(nullptr)}};
    // How it was computed: the rule is error_quadrature; the exact solution's derivatives, and the estimated error
    // of finite-difference ones.
    if (!e.derivatives.empty()) j["errors"][e.name]["derivatives"] = e.derivatives;
    if (e.derivative_error > 0.0) j["errors"][e.name]["derivative_error"] = e.derivative_error;
    j["error_order"].push_back(e.name);
  }
}

fem::SolverOptions solver_options(const std::string& solver, const std::string& petsc_options, const std::string& partition,
                                  std::vector<Eigen::SparseMatrix<double>> hierarchy) {
  fem::SolverOptions options;
  options.kind = fem::parse_solver(solver);
  options.petsc_options = petsc_options;
  if (!petsc_options.empty() && !fem::uses_petsc(options.kind)) {
    throw InputError("--petsc-options: only with --solver petsc or mg");
  }
  if (!partition.empty()) {
    if (!fem::uses_petsc(options.kind)) throw InputError("--partition: only with --solver petsc or mg");
    options.partition = fem::partition_name(fem::parse_partition(partition));
  }
  if (options.kind == fem::SolverKind::Multigrid) {
    options.hierarchy = std::make_shared<const std::vector<Eigen::SparseMatrix<double>>>(std::move(hierarchy));
  }
  return options;
}

bool solver_uses_petsc(const std::string& solver, const std::string& basis) {
  if (solver == "petsc") return true;
  if (solver != "mg") return false;
  // mg on a backend that is not nested is refused before anything runs (io::refined_geometry): no session for it
  // (an MPI session keeps Open MPI's allocations past the refusal). An unknown backend is named by the run itself.
  for (const basis::Backend& b : basis::backends()) {
    if (b.name == basis) return b.nested;
  }
  return false;
}

int run_solver_program(const std::string& program, bool petsc, char** argv, bool& quiet, int& threads,
                       const std::function<int()>& body) {
  return run_program(program, [&] {
    std::optional<fem::ParallelSession> session;
    if (petsc) {
      int args = 1;
      session.emplace(args, argv);
      if (fem::rank() > 0) {
        quiet = true;
        std::cerr.setstate(std::ios::failbit);
      }
      const int ranks = fem::ranks();
      if (ranks > 1 && threads == 0) threads = std::max(1, static_cast<int>(std::thread::hardware_concurrency()) / ranks);
    }
    const int code = run_program(program, body);
    fem::barrier();
    return code;
  });
}

namespace {

// The memory of the solve and the output for this many elements, against what is available.
void check_size(const ProblemProgram& run, const Discretisation& d, int components, double elements, const std::string& what) {
  const int local = components * (d.degree + 1) * (d.degree + 1);
  fem::check_memory(fem::poisson_memory(components * elements, local) + run.output_bytes_per_element * elements,
                    run.max_memory * 1024.0 * 1024.0 * 1024.0, what, "each --refine or --presubdivide step needs four times more");
}

}  // namespace

nlohmann::json run_problem_program(const ProblemProgram& run) {
  const auto t_start = std::chrono::steady_clock::now();
  const auto log = [&](const std::string& text) {
    if (!run.quiet) std::cerr << run.program << ": " << text << std::endl;
  };
  if (fem::rank() == 0) {
    check_writable(run.json);  // before the work, not after it
    for (const std::string& path : run.output_paths) check_writable(path);
  }
  if (run.threads > 0) fem::set_num_threads(run.threads);
  Progress progress(run.program, run.quiet);
  const Discretisation d = make_discretisation(run.discretisation);
  {
    std::ostringstream what;
    what << "this run (about " << std::setprecision(3) << predicted_elements(run.discretisation, d) << " elements)";
    check_size(run, d, run.components, predicted_elements(run.discretisation, d), what.str());
  }
  basis::BackendFacts facts;
  basis::Refinement refined = progress.phase("refinement", [&] {
    return refined_geometry(
        run.discretisation, d, facts,
        [&](Index elements, Index dofs) {
          check_size(run, d, run.components, static_cast<double>(std::max(elements, dofs)),
                     "this run (" + std::to_string(elements) + " elements, " + std::to_string(dofs) + " dofs)");
        },
        run.solver == "mg");
  });
  for (const std::string& note : facts.notes) log(note);
  const basis::Geometry& geometry = refined.geometry;
  nlohmann::json j = run.run_info;
  j.update(discretisation_report(run.discretisation, d, refined, facts));
  const std::shared_ptr<const fem::Problem> problem = run.problem(geometry, facts, j);
  const std::unique_ptr<quadrature::RuleProvider> rules = make_rules(run.discretisation, d);
  const fem::SolverOptions solver = solver_options(run.solver, run.petsc_options, run.partition, std::move(refined.steps));
  fem::ProblemSolver p(geometry, *rules, problem, solver);
  // The problem's checks come first (setup: the data; assembly: the constraints): an error is the only line.
  progress.phase("setup and pattern", [&] { p.setup(); });
  progress.phase("assembly", [&] { p.assemble(); });
  log("solving " + problem->name() + " on " + std::to_string(problem->components() * geometry.space().num_dofs()) +
      " dofs, " + std::to_string(geometry.space().num_elements()) + " elements, " + std::to_string(fem::num_threads()) +
      " threads");
  progress.phase("factorisation and solve", [&] { p.solve(); });
  progress.phase("error norms", [&] { p.errors(); });
  const fem::ProblemResult& r = p.result();
  report_problem_result(j, r, rules->name(), solver);
  for (const auto& [what, how] : r.choices) log(what + ": " + how);
  std::ostringstream summary;
  summary << std::setprecision(4) << "assembly " << r.assembly_seconds << " s, solve " << r.solve_seconds << " s ("
          << r.solver << ")";
  for (const fem::NormError& e : r.errors) summary << ", " << e.name << " error " << e.error;
  log(summary.str());
  if (run.output) progress.phase("output", [&] { run.output(geometry, r, j); });
  j["total_seconds"] = std::chrono::duration<double>(std::chrono::steady_clock::now() - t_start).count();
  j["phase_seconds"] = progress.json();
  if (run.timer_table) progress.print_table();
  if (writes(run.json) && fem::rank() == 0) {
    write_json(run.json, j);
    log("wrote " + run.json);
  }
  return j;
}

}  // namespace iga::io
