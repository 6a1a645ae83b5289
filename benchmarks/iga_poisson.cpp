// iga-poisson: Poisson/Laplace on planar domains (Laplace–Beltrami on surfaces), -Δu + c u = f, with
// strong Dirichlet and natural Neumann conditions. Thin: parses options and calls the library.
#include <CLI/CLI.hpp>
#include <chrono>
#include <cmath>
#include <functional>
#include <iomanip>
#include <iostream>
#include <algorithm>
#include <nlohmann/json.hpp>
#include <optional>
#include <sstream>
#include <thread>

#include "basis/registry.hpp"
#include "benchmarks/study.hpp"
#include "core/error.hpp"
#include "fem/convergence.hpp"
#include "fem/expression.hpp"
#include "fem/memory.hpp"
#include "fem/parallel.hpp"
#include "fem/poisson.hpp"
#include "fem/problems.hpp"
#include "fem/threads.hpp"
#include "io/program.hpp"
#include "io/net_writer.hpp"
#include "io/progress.hpp"
#include "io/report.hpp"
#include "io/vtu_output.hpp"
#include "io/vtu_writer.hpp"
#include "mesh/obj_reader.hpp"
#include "quadrature/rule_provider.hpp"
#include "refine/adaptive.hpp"
#include "refine/refine_smooth.hpp"
#include "refine/uniform.hpp"

namespace {

struct Options {
  std::string mesh, basis = "bspline", problem, source, dirichlet, neumann, neumann_boundary, neumann_where, exact;
  std::string petsc_options;
  std::string quadrature, solver = "cholmod", vtu = "result.vtu", json = "result.json", refine_intervals;
  std::string geometry, mark = "doerfler", vtu_format = "bezier", net_vtu, cc_boundary = "natural", cc_enrich = "none";
  int degree = 3, refine = -1, threads = 0, samples = 4, presubdivide = 0;
  int adaptive = -1, admissibility = 2, vtu_degree = 6;
  long long max_dofs = 0;
  double theta = 0.5;
  double reaction = 0.0;
  std::string dirichlet_method = "strong";
  double nitsche_penalty = 0.0;  ///< 0: the local estimate
  double max_memory = 0.0;  ///< GiB; 0: what the system has available
  bool quiet = false, mean_zero = false;
  std::string study, degrees, study_output = "study", plots = "png,svg";  ///< --study K0:K1 and its options
  bool vtu_given = false, json_given = false;
  bool timer_table = true;  ///< the time per phase on stderr at the end (not for the levels of a study)
  std::vector<std::string> given;  ///< backend options given on the command line (names without dashes)
  nlohmann::json run_info;         ///< io::run_info: version, revision, every effective setting
  bool count(const std::string& option) const { return std::find(given.begin(), given.end(), option) != given.end(); }
};

using Log = std::function<void(const std::string&)>;
Log make_log(const Options& o) {
  return [quiet = o.quiet](const std::string& s) {
    if (!quiet) std::cerr << "iga-poisson: " << s << std::endl;
  };
}

std::vector<iga::Index> parse_intervals(const std::string& list) {
  std::vector<iga::Index> intervals;
  std::stringstream ss(list);
  std::string item;
  while (std::getline(ss, item, ',')) {
    try {
      std::size_t used = 0;
      const long v = std::stol(item, &used);
      if (used != item.size() || v < 0) throw std::invalid_argument(item);
      intervals.push_back(v);
    } catch (const std::exception&) {
      throw iga::InputError("--refine-intervals: '" + item + "' is not a 0-based interval index");
    }
  }
  return intervals;
}

// The backend, its options and the coarse net: what every run (and every level of a study) starts from.
struct Setup {
  const iga::basis::Backend* backend = nullptr;
  iga::basis::BackendOptions bo;
  int degree = 0;
  std::optional<iga::mesh::PolyMesh> net;
  bool write_vtu = false;
};

Setup make_setup(const Options& o) {
  using namespace iga;
  Setup s;
  // The backend from the registry: its options, defaults and construction (no backend policy here).
  s.backend = &basis::backend(o.basis);
  basis::check_options(*s.backend, o.given);
  if (o.count("degree")) s.bo.degree = o.degree;
  if (o.count("presubdivide")) s.bo.presubdivide = o.presubdivide;
  if (o.count("geometry")) s.bo.geometry = o.geometry;
  if (o.count("cc-boundary")) s.bo.cc_boundary = o.cc_boundary;
  if (o.count("cc-enrich")) s.bo.cc_enrich = o.cc_enrich;
  s.bo.net_name = o.mesh;
  s.degree = basis::degree(*s.backend, s.bo);
  if (!o.mesh.empty()) s.net = mesh::read_obj(o.mesh);
  s.write_vtu = !o.vtu.empty() && o.vtu != "none";
  return s;
}

int refine_steps(const Options& o, const Setup& s) { return o.refine >= 0 ? o.refine : s.backend->default_refine; }

// Size before work: the memory of the solve and the output for this many elements, against what is available.
void check_size(const Options& o, const Setup& s, double elements, const std::string& what) {
  iga::fem::check_memory(iga::fem::poisson_memory(elements, (s.degree + 1) * (s.degree + 1)) +
                             (s.write_vtu ? iga::fem::vtu_memory(elements, o.vtu_format == "linear" ? o.samples : o.vtu_degree + 1) : 0.0),
                         o.max_memory * 1024.0 * 1024.0 * 1024.0, what,
                         "each --refine or --presubdivide step needs four times more" +
                             (s.write_vtu && o.vtu_format == "linear" ? "; --vtu-samples " + std::to_string(o.samples) + " writes " +
                                                std::to_string(o.samples * o.samples) + " points per element"
                                          : std::string()));
}

// The elements the refinement will make (each step splits every element in four), checked before it is made.
void check_predicted_size(const Options& o, const Setup& s) {
  const int steps = refine_steps(o, s) + (o.count("presubdivide") ? o.presubdivide : 0);
  const double predicted = (s.net ? static_cast<double>(s.net->num_faces()) : 1.0) * std::pow(4.0, steps);
  std::ostringstream what;
  what << "this run (about " << std::setprecision(3) << predicted << " elements after " << steps << " refinement steps)";
  check_size(o, s, predicted, what.str());
}

iga::refine::Refinement make_geometry(const Options& o, const Setup& s, iga::basis::BackendFacts& facts) {
  using namespace iga;
  // --refine-intervals: each step halves only the listed knot intervals, in both directions (refine-and-smooth).
  const std::vector<Index> intervals = parse_intervals(o.refine_intervals);
  const int steps = refine_steps(o, s);
  refine::Refinement refined =
      basis::make_refined_geometry(*s.backend, s.net ? &*s.net : nullptr, s.bo, intervals.empty() ? steps : 0, facts);
  for (int k = 0; !intervals.empty() && k < steps; ++k) {
    refined = refine::refine_smooth_tensor(refined.geometry, intervals, intervals);
  }
  const basis::Space& space = refined.geometry.space();
  check_size(o, s, static_cast<double>(std::max(space.num_elements(), space.num_dofs())),
             "this run (" + std::to_string(space.num_elements()) + " elements, " + std::to_string(space.num_dofs()) + " dofs)");
  return refined;
}

// The problem: a built-in manufactured one, or expressions. problem_name: the built-in one's name, or "".
iga::fem::PoissonProblem make_problem(const Options& o, const iga::basis::Geometry& geometry, std::string& problem_name) {
  using namespace iga;
  fem::PoissonProblem problem;
  problem.reaction = o.reaction;
  problem_name = o.problem;
  // A built-in problem's source, exact solution and Dirichlet data belong together: replacing one of them would
  // report errors against a function that no longer solves the problem.
  if (!o.problem.empty() && (!o.source.empty() || !o.exact.empty() || !o.dirichlet.empty())) {
    throw InputError("--problem " + o.problem + " brings its own source, exact solution and Dirichlet data: give "
                     "either --problem or --source/--exact/--dirichlet, not both");
  }
  if (problem_name.empty() && o.source.empty() && o.exact.empty()) {
    if (!o.dirichlet.empty()) {
      throw InputError("--dirichlet without --source: give the source (and --exact for error norms), or use --problem");
    }
    problem_name = "sine";
  }
  if (!problem_name.empty()) {
    if (geometry.dim() == 3) throw UnsupportedError("--problem " + problem_name + ": built-in problems are for planar domains; give --source and --exact for surfaces");
    const fem::ManufacturedProblem mp = fem::manufactured_problem(problem_name, o.reaction);
    problem.source = mp.source;
    problem.exact = mp.exact;
    problem.dirichlet = mp.exact;
  }
  if (!o.source.empty()) problem.source = std::make_shared<fem::Expression>(o.source, "--source");
  if (!o.exact.empty()) {
    auto exact = std::make_shared<fem::Expression>(o.exact, "--exact");
    exact->set_fd_step(fem::finite_difference_step(geometry));  // its gradient: the H1 error, Neumann data
    problem.exact = exact;
    if (o.dirichlet.empty()) problem.dirichlet = problem.exact;
  }
  if (!o.dirichlet.empty()) problem.dirichlet = std::make_shared<fem::Expression>(o.dirichlet, "--dirichlet");
  fem::select_neumann(problem, o.neumann, o.neumann_boundary, o.neumann_where, geometry.space().boundary_part_names());
  problem.mean_zero = o.mean_zero;
  problem.dirichlet_method = fem::dirichlet_method(o.dirichlet_method);
  problem.nitsche_penalty = o.nitsche_penalty;
  return problem;
}

std::unique_ptr<iga::quadrature::RuleProvider> make_rules(const Options& o, const Setup& s) {
  using namespace iga;
  std::unique_ptr<quadrature::RuleProvider> rules;
  try {
    rules = quadrature::make_rule_provider(o.quadrature.empty() ? s.backend->default_quadrature(s.degree) : o.quadrature, s.degree + 1);
  } catch (const InputError& e) {
    throw InputError("--quadrature: " + std::string(e.what()));
  }
  if (rules->name().rfind("gauss:", 0) == 0 && std::stoi(rules->name().substr(6)) < s.degree + 1) {
    // Fewer Gauss points than degree + 1 per direction integrate neither the stiffness nor the boundary mass of
    // degree-p functions exactly even on affine elements, and leave the latter singular: not an answer to report.
    throw InputError("--quadrature " + o.quadrature + ": " + rules->name().substr(6) + " points per direction are fewer than degree + 1 = " +
                     std::to_string(s.degree + 1) + " (the least that integrates the matrices of degree-" +
                     std::to_string(s.degree) + " functions exactly on affine elements)");
  }
  return rules;
}

// The adaptive loop's convergence over its steps (fem::ConvergenceTable with h = N^(-1/2), N the dofs): per step the
// rate of the estimate and, with an exact solution, of the energy error, and the least-squares rate over all steps;
// optimal for degree p is p (e ~ N^(-p/2)). The table goes to the log.
nlohmann::json adaptive_rates(const std::vector<iga::refine::AdaptiveStep>& history, const Log& log) {
  using iga::fem::ConvergenceTable;
  const bool energy = std::all_of(history.begin(), history.end(), [](const auto& st) { return st.energy_error.has_value(); });
  ConvergenceTable table(energy ? std::vector<std::string>{"estimate", "energy"} : std::vector<std::string>{"estimate"});
  for (const iga::refine::AdaptiveStep& st : history) {
    std::vector<double> errors{st.estimate};
    if (energy) errors.push_back(*st.energy_error);
    table.add_row({st.step, st.dofs, st.elements, 1.0 / std::sqrt(static_cast<double>(st.dofs)), errors,
                   st.setup_seconds + st.assembly_seconds + st.solve_seconds + st.estimate_seconds + st.refine_seconds});
  }
  nlohmann::json j = {{"against", "N^(-1/2), N = dofs: e ~ N^(-r/2), optimal r = degree"}};
  for (std::size_t n = 0; n < table.norms().size(); ++n) {
    nlohmann::json rates = nlohmann::json::array();
    for (const auto& r : table.rates(n)) rates.push_back(r ? nlohmann::json(*r) : nlohmann::json(nullptr));
    const std::string key = table.norms()[n] == "energy" ? "energy_error" : "estimate";
    j["rates"][key] = rates;
    const auto fitted = table.fitted_rate(n);
    j["fitted_rates"][key] = fitted ? nlohmann::json(*fitted) : nlohmann::json(nullptr);
  }
  log("adaptive convergence over the steps (h = N^(-1/2), N = dofs):\n" + table.text());
  return j;
}

// --adaptive: solve → estimate → mark → refine, one .vtu per step and a .pvd series; r is the last step's result.
// Returns the report's "adaptive" object.
nlohmann::json solve_adaptive(const Options& o, const Setup& s, const iga::basis::Geometry& geometry,
                              const iga::quadrature::RuleProvider& rules, const iga::fem::PoissonProblem& problem,
                              const iga::fem::SolverOptions& solver, const iga::io::VtuOutput& vtu_output,
                              iga::fem::PoissonResult& r, std::optional<iga::basis::Geometry>& last, const Log& log) {
  using namespace iga;
  refine::AdaptiveOptions ao;
  ao.steps = o.adaptive;
  ao.theta = o.theta;
  ao.marking = refine::parse_marking(o.mark);
  ao.max_dofs = o.max_dofs;
  ao.admissibility = o.admissibility;
  const std::string base = o.vtu.size() > 4 && o.vtu.substr(o.vtu.size() - 4) == ".vtu" ? o.vtu.substr(0, o.vtu.size() - 4) : o.vtu;
  std::vector<io::SeriesEntry> series;
  auto on_step = [&](const refine::AdaptiveStep& st, const basis::Geometry& g, const fem::PoissonResult& res, const fem::Estimate& est) {
    log("step " + std::to_string(st.step) + ": " + std::to_string(st.dofs) + " dofs, " + std::to_string(st.levels) +
        " levels, estimate " + std::to_string(st.estimate) +
        (st.energy_error ? ", energy error " + std::to_string(*st.energy_error) : std::string()));
    r = res;
    last = g;
    if (s.write_vtu) {
      char name[32];
      std::snprintf(name, sizeof name, "_step%03d.vtu", st.step);
      const std::string file = base + name;
      io::write_output(file, g, &res.u, vtu_output, {{"indicator", est.indicators}});
      const std::size_t slash = file.find_last_of('/');
      series.push_back({static_cast<double>(st.step), slash == std::string::npos ? file : file.substr(slash + 1)});
      io::write_pvd(base + ".pvd", series);
    }
  };
  const refine::AdaptiveRun run = refine::adaptive_solve(geometry, rules, problem, solver, ao, on_step);
  const std::vector<refine::AdaptiveStep>& history = run.history;
  if (run.stopped != "steps") log("adaptive loop stopped after step " + std::to_string(history.back().step) + ": " + run.stopped);
  nlohmann::json adaptive_json = {{"steps", o.adaptive}, {"theta", o.theta}, {"marking", refine::to_string(ao.marking)},
                                  {"max_dofs", o.max_dofs}, {"admissibility", o.admissibility}, {"stopped", run.stopped}};
  if (s.write_vtu) adaptive_json["pvd"] = base + ".pvd";
  for (const refine::AdaptiveStep& st : history) {
    auto opt = [](const std::optional<double>& v) { return v ? nlohmann::json(*v) : nlohmann::json(nullptr); };
    adaptive_json["history"].push_back(
        {{"step", st.step}, {"dofs", st.dofs}, {"elements", st.elements}, {"levels", st.levels},
         {"quadrature_points", st.quadrature_points}, {"estimate", st.estimate}, {"energy_error", opt(st.energy_error)},
         {"l2_error", opt(st.l2_error)}, {"efficiency_index", opt(st.efficiency)}, {"marked", st.marked},
         {"added_for_admissibility", st.added},
         {"seconds", {{"setup", st.setup_seconds}, {"assembly", st.assembly_seconds}, {"solve", st.solve_seconds},
                      {"errors", st.error_seconds}, {"estimate", st.estimate_seconds}, {"mark", st.mark_seconds},
                      {"refine", st.refine_seconds}}}});
  }
  adaptive_json["convergence"] = adaptive_rates(history, log);
  return adaptive_json;
}

// The report's settings: what ran (io::run_info: program, version, every option) and what was asked for (basis,
// mesh, degree, refinement, the problem's expressions, a built-in one's included).
nlohmann::json report_settings(const Options& o, const Setup& s, const iga::refine::Refinement& refined,
                               const iga::basis::BackendFacts& facts, const std::string& problem_name) {
  nlohmann::json j = o.run_info;
  std::pair<std::string, std::string> builtin_text;  // the built-in problem's exact solution and source as text
  if (!problem_name.empty()) {
    const iga::fem::ManufacturedProblem mp = iga::fem::manufactured_problem(problem_name, o.reaction);
    builtin_text = {mp.exact_expression, mp.source_expression};
  }
  j["basis"] = o.basis;
  j["mesh"] = o.mesh.empty() ? "default:" + (o.geometry.empty() ? std::string("quarter-annulus") : o.geometry) : o.mesh;
  j["dimension"] = refined.geometry.dim();
  j["orientation"] = refined.geometry.orientation();
  j["degree"] = s.degree;
  j["refine"] = refine_steps(o, s);
  j["nested_refinement"] = refined.nested;
  if (!o.refine_intervals.empty()) j["refine_intervals"] = o.refine_intervals;
  for (const auto& [path, count] : facts.counts) j[nlohmann::json::json_pointer("/" + path)] = count;
  j["problem"] = {{"name", problem_name.empty() ? nullptr : nlohmann::json(problem_name)},
                  {"source", o.source.empty() ? builtin_text.second : o.source},
                  {"dirichlet", o.dirichlet.empty() ? (o.exact.empty() ? builtin_text.first : o.exact) : o.dirichlet},
                  {"neumann", o.neumann}, {"neumann_boundary", o.neumann_boundary}, {"neumann_where", o.neumann_where},
                  {"exact", o.exact.empty() ? builtin_text.first : o.exact},
                  {"reaction", o.reaction}, {"mean_zero", o.mean_zero},
                  {"dirichlet_method", o.dirichlet_method}};
  return j;
}

// The report's results: the figures of the solve r (the last step's with --adaptive).
void report_results(nlohmann::json& j, const iga::fem::PoissonResult& r, const std::string& quadrature,
                    const iga::fem::SolverOptions& solver) {
  j["dofs"] = r.dofs;
  j["free_dofs"] = r.free_dofs;
  j["dirichlet_dofs"] = r.dirichlet_dofs;
  j["elements"] = r.elements;
  j["quadrature"] = quadrature;
  j["quadrature_points"] = r.quadrature_points;
  if (!r.error_quadrature.empty()) j["error_quadrature"] = r.error_quadrature;
  j["domain_measure"] = r.domain_measure;
  j["threads"] = iga::fem::num_threads();
  j["pattern_seconds"] = r.pattern_seconds;
  // A distributed run's phases end when the slowest rank's do.
  j["assembly_seconds"] = iga::fem::max_over_ranks(r.assembly_seconds);
  j["solve_seconds"] = r.solve_seconds;
  j["ranks"] = r.ranks;
  if (r.ranks > 1 || !r.elements_per_rank.empty()) {
    j["elements_per_rank"] = r.elements_per_rank;
    j["dofs_per_rank"] = r.dofs_per_rank;
  }
  if (!solver.petsc_options.empty()) j["petsc_options"] = solver.petsc_options;
  j["solver"] = r.solver;
  j["solver_iterations"] = r.solver_iterations;
  j["solver_ordering"] = r.solver_ordering;
  j["residual_norm"] = r.residual_norm;
  j["residual_tolerance"] = solver.max_residual;
  j["dirichlet_edges"] = r.dirichlet_edges;
  j["neumann_edges"] = r.neumann_edges;
  j["mean_zero"] = r.mean_zero;
  j["nitsche_penalty"] = r.nitsche_penalty > 0.0 ? nlohmann::json(r.nitsche_penalty) : nlohmann::json(nullptr);
  if (r.mean_zero) j["compatibility_defect"] = r.compatibility_defect;
  j["l2_error"] = nullptr;
  j["h1_error"] = nullptr;
  if (r.errors) {
    j["l2_error"] = r.errors->l2;
    j["h1_error"] = r.errors->h1;
    // Relative errors where the exact solution has a norm to compare with (u = 0 has none: the key is left out).
    if (r.errors->l2_exact > 0) j["l2_error_relative"] = r.errors->l2 / r.errors->l2_exact;
    if (r.errors->h1_exact > 0) j["h1_error_relative"] = r.errors->h1 / r.errors->h1_exact;
  }
}

std::string fmt(double v) {
  std::ostringstream s;
  s << std::setprecision(4) << v;
  return s.str();
}

// The pipeline's steps (fem::PoissonSolver) as phases, so a long one says so while it runs; the result is
// solve_poisson's.
iga::fem::PoissonResult solve_in_phases(const iga::basis::Geometry& geometry, const iga::quadrature::RuleProvider& rules,
                                        const iga::fem::PoissonProblem& problem, const iga::fem::SolverOptions& solver,
                                        iga::io::Progress& progress) {
  iga::fem::PoissonSolver p(geometry, rules, problem, solver);
  progress.phase("setup and pattern", [&] { p.setup(); });
  progress.phase("assembly", [&] { p.assemble(); });
  progress.phase("factorisation and solve", [&] { p.solve(); });
  progress.phase("error norms", [&] { p.errors(); });
  return p.result();
}

// One run: the geometry refined o.refine times, solved (or the adaptive loop), the .vtu; returns the report.
nlohmann::json solve_run(const Options& o) {
  using namespace iga;
  const auto t_start = std::chrono::steady_clock::now();
  const Log log = make_log(o);
  if (o.threads > 0) fem::set_num_threads(o.threads);
  io::Progress progress("iga-poisson", o.quiet);
  const Setup s = make_setup(o);
  check_predicted_size(o, s);
  basis::BackendFacts facts;
  const refine::Refinement refined = progress.phase("refinement", [&] { return make_geometry(o, s, facts); });
  for (const std::string& note : facts.notes) log(note);
  const basis::Geometry& geometry = refined.geometry;
  if (geometry.orientation() < 0) log("note: the planar net is oriented clockwise (det J < 0); solved as it is (the same solution)");
  std::string problem_name;
  const fem::PoissonProblem problem = make_problem(o, geometry, problem_name);
  const std::unique_ptr<quadrature::RuleProvider> rules = make_rules(o, s);
  fem::SolverOptions solver;
  solver.kind = fem::parse_solver(o.solver);
  solver.petsc_options = o.petsc_options;
  if (!o.petsc_options.empty() && solver.kind != fem::SolverKind::Petsc) {
    throw InputError("--petsc-options: only with --solver petsc");
  }

  log("solving on " + std::to_string(geometry.space().num_dofs()) + " dofs, " +
      std::to_string(geometry.space().num_elements()) + " elements, " + std::to_string(fem::num_threads()) + " threads");
  fem::PoissonResult r;
  nlohmann::json j = report_settings(o, s, refined, facts, problem_name);
  io::VtuOutput vtu_output;
  vtu_output.format = o.vtu_format;
  vtu_output.samples = o.samples;
  vtu_output.degree = o.vtu_degree;
  vtu_output.exact = problem.exact;
  std::optional<basis::Geometry> last;  // the adaptive loop's last geometry
  if (o.adaptive >= 0) {
    j["adaptive"] = progress.phase("adaptive loop", [&] {
      return solve_adaptive(o, s, geometry, *rules, problem, solver, vtu_output, r, last, log);
    });
  } else {
    r = solve_in_phases(geometry, *rules, problem, solver, progress);
  }
  log("assembly " + fmt(r.assembly_seconds) + " s, solve " + fmt(r.solve_seconds) + " s (" + r.solver + ")");
  report_results(j, r, rules->name(), solver);
  if (r.errors) log("L2 error " + fmt(r.errors->l2) + ", H1 seminorm error " + fmt(r.errors->h1));
  if (s.write_vtu) j["vtu_output"] = vtu_output.settings();
  if (s.write_vtu && o.adaptive < 0) {
    // A distributed run: each rank writes the cells of its own elements, rank 0 the .pvtu that names them.
    if (r.ranks > 1) vtu_output.pieces = {fem::rank(), r.ranks, r.element_owner};
    const std::vector<std::string> files =
        progress.phase("output", [&] { return io::write_output(o.vtu, geometry, &r.u, vtu_output); });
    j["vtu"] = files[0];
    if (files.size() > 1) j["vtu_outline"] = files[1];
    for (const std::string& f : files) log("wrote " + f);
  } else if (s.write_vtu) {
    log("wrote " + j["adaptive"]["pvd"].get<std::string>() + " and its " + std::to_string(j["adaptive"]["history"].size()) + " .vtu files");
  }
  if (io::writes(o.net_vtu) && fem::rank() == 0) {
    io::write_control_net_vtu(o.net_vtu, last ? *last : geometry, s.net ? &*s.net : nullptr);
    j["net_vtu"] = o.net_vtu;
    log("wrote " + o.net_vtu);
  }
  j["total_seconds"] = std::chrono::duration<double>(std::chrono::steady_clock::now() - t_start).count();
  j["phase_seconds"] = progress.json();
  if (o.timer_table) progress.print_table();
  return j;
}

int run(const Options& o) {
  const nlohmann::json j = solve_run(o);
  if (!o.json.empty() && o.json != "none" && iga::fem::rank() == 0) {
    iga::io::write_json(o.json, j);
    make_log(o)("wrote " + o.json);
  }
  return 0;
}

// --study K0:K1: every level is solve_run with --refine K (and --degree P of --degrees), so a level's report is
// the one a single run writes.
int study(const Options& o) {
  iga::bench::StudyOptions so;
  so.levels = iga::bench::parse_levels(o.study);
  if (!o.degrees.empty()) so.degrees = iga::bench::parse_degrees(o.degrees);
  const std::vector<std::string>& takes = iga::basis::backend(o.basis).options;
  if (!o.degrees.empty() && std::find(takes.begin(), takes.end(), "degree") == takes.end()) {
    throw iga::InputError("--degrees: --basis " + o.basis + " has a fixed degree");
  }
  if (!o.source.empty() && o.exact.empty()) {
    throw iga::InputError("--study needs an exact solution for its error norms: give --exact with --source (or --problem)");
  }
  so.output = o.study_output;
  so.plots = o.plots;
  so.vtu = o.vtu_given ? o.vtu : std::string();
  so.json = o.json_given ? o.json : std::string();
  so.quiet = o.quiet;
  auto level = [&o](int degree, int refine, const std::string& vtu) {
    Options lo = o;
    lo.refine = refine;
    if (degree > 0) {
      lo.degree = degree;
      if (!lo.count("degree")) lo.given.emplace_back("degree");
    }
    lo.vtu = vtu.empty() ? "none" : vtu;
    lo.json = "none";
    lo.timer_table = false;
    return lo;
  };
  iga::bench::StudyHooks hooks;
  hooks.check_size = [&](int degree, int refine) {
    const Options lo = level(degree, refine, o.vtu_given && o.vtu != "none" ? o.vtu : std::string());
    check_predicted_size(lo, make_setup(lo));
  };
  hooks.solve = [&](int degree, int refine, const std::string& vtu) { return solve_run(level(degree, refine, vtu)); };
  return iga::bench::run_study(so, hooks);
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"iga-poisson: solve -Δu + c u = f (Laplace–Beltrami on surfaces) with isogeometric elements"};
  Options o;
  app.add_option("--mesh", o.mesh, "Wavefront OBJ control net (a quad grid for bspline); default: the embedded quarter annulus")
      ->check(iga::io::input_file());
  std::vector<std::string> backend_list;
  std::string backend_help = "basis backend:";
  for (const auto& b : iga::basis::backends()) {
    backend_list.push_back(b.name);
    backend_help += " " + b.name + " (" + b.description + ");";
  }
  app.add_option("--basis", o.basis, backend_help)->check(CLI::IsMember(backend_list))->capture_default_str();
  app.add_option("--degree", o.degree, "polynomial degree per direction (bspline; cc is bicubic)")->check(iga::io::whole_number(1, 12))->capture_default_str();
  app.add_option("--refine-intervals", o.refine_intervals, "bspline: each refinement step halves only these non-empty knot intervals (0-based, comma-separated, both directions)");
  app.add_option("--refine", o.refine, "uniform refinement steps, each splitting every element in four (default: 4 for bspline, 1 for cc, 0 for polyhedral, where each step is a Catmull–Clark step of the net)")->check(iga::io::whole_number(0, 14));
  app.add_option("--geometry", o.geometry, "bspline without --mesh: the built-in geometry, quarter-annulus (default, exact: NURBS), l-shape ([0,2]^2 minus (1,2]^2, one patch with a C0 line from the reflex corner), square (the unit square), or a patch file FILE.json (README, Patch files)")->check(iga::io::non_blank());
  app.add_option("--adaptive", o.adaptive, "adaptive refinement: STEPS rounds of solve, estimate (residual estimator), mark, refine locally (bspline: THB; the --refine steps come first); one .vtu per step plus a .pvd series")->check(iga::io::whole_number(0, 200));
  app.add_option("--theta", o.theta, "--adaptive: marking parameter in (0, 1]")->check(iga::io::finite_number(1e-6, 1.0))->capture_default_str();
  app.add_option("--mark", o.mark, "--adaptive: doerfler (bulk) or max")->check(CLI::IsMember({"doerfler", "max"}))->capture_default_str();
  app.add_option("--max-dofs", o.max_dofs, "--adaptive: stop after the first solve with at least this many dofs (0: no limit)")->check(iga::io::whole_number(0, 1000000000000LL));
  app.add_option("--admissibility", o.admissibility, "--adaptive: class m of admissible meshes (>= 2; 0 refines exactly the marked elements)")->check(CLI::IsMember({0, 2, 3, 4, 5, 6}))->capture_default_str();
  app.add_option("--cc-boundary", o.cc_boundary, "cc: natural (the limit boundary rule of OpenSubdiv: u_nn = 0 on the boundary, L2 rate 2.5) or clamped (one ring of ghost control points: open knot vector in the normal direction, full order)")->check(CLI::IsMember({"natural", "clamped"}))->capture_default_str();
  app.add_option("--cc-enrich", o.cc_enrich, "cc: none or quadratic (three functions per extraordinary vertex, quadratics in the physical coordinates times a C7 cutoff, valence 5 and more and boundary EVs: restores the rates of the regular parts; uniform refinement only)")->check(CLI::IsMember({"none", "quadratic"}))->capture_default_str();
  app.add_option("--presubdivide", o.presubdivide, "polyhedral: Catmull–Clark steps applied to the net first (one makes any net with valences and face sizes <= 8 admissible)")->check(iga::io::whole_number(0, 6));
  std::string names;
  for (const auto& n : iga::fem::manufactured_problem_names()) names += (names.empty() ? "" : ", ") + n;
  app.add_option("--problem", o.problem, "built-in manufactured problem (" + names + "); default sine when no --source/--exact")->check(iga::io::non_blank());
  app.add_option("--source", o.source, "f(x,y,z) in -Δu + c u = f (muparser expression)")->check(iga::io::non_blank());
  app.add_option("--dirichlet", o.dirichlet, "u on the Dirichlet boundary, g(x,y,z); default: --exact, else 0")->check(iga::io::non_blank());
  app.add_option("--neumann", o.neumann, "∂u/∂n on the Neumann parts, g(x,y,z,nx,ny,nz)")->check(iga::io::non_blank());
  app.add_option("--neumann-boundary", o.neumann_boundary, "comma-separated boundary parts with Neumann data (bspline: v0,u1,v1,u0; cc: b<loop>.<segment> between corners; or indices)")->check(iga::io::non_blank());
  app.add_option("--neumann-where", o.neumann_where, "boundary edges whose midpoint makes this expression > 0 get Neumann data, e.g. 'x > 0.999'")->check(iga::io::non_blank());
  app.add_option("--dirichlet-method", o.dirichlet_method, "strong (L2 projection onto the boundary traces, eliminated) or nitsche (weak, symmetric Nitsche: needs no trace space; for --cc-boundary clamped at boundary extraordinary vertices)")->check(CLI::IsMember({"strong", "nitsche"}))->capture_default_str();
  app.add_option("--nitsche-penalty", o.nitsche_penalty, "--dirichlet-method nitsche: a fixed penalty γ in γ/h (h the side length); 0: each element's own from its local eigenvalue estimate (coercive by construction)")->check(iga::io::finite_number(0.0))->capture_default_str();
  app.add_flag("--mean-zero", o.mean_zero, "without Dirichlet boundary and reaction (closed surfaces): the solution with mean zero");
  app.add_option("--exact", o.exact, "exact solution u(x,y,z): enables L2 and H1 error norms")->check(iga::io::non_blank());
  app.add_option("--reaction", o.reaction, "c >= 0 in -Δu + c u = f")->check(iga::io::finite_number(0))->capture_default_str();
  app.add_option("--quadrature", o.quadrature, "quadrature rule: gauss:P (P points per direction) or tiles:P:L (P×P Gauss on each tile of levels 1..L of elements at extraordinary vertices); default gauss:degree+1");
  app.add_option("--solver", o.solver, "cholmod, cg (Eigen, incomplete Cholesky), or petsc (a PETSc KSP, CG + GAMG by default, on the ranks of mpirun: each assembles its own part of a METIS partition)")->capture_default_str();
  app.add_option("--petsc-options", o.petsc_options, "--solver petsc: PETSc options, e.g. '-pc_type hypre' or '-ksp_type preonly -pc_type lu -pc_factor_mat_solver_type mumps' (the PETSC_OPTIONS environment is read too)")->check(iga::io::non_blank());
  app.add_option("--threads", o.threads, "threads for assembly (default: OpenMP's)")->check(iga::io::thread_count());
  app.add_option("--vtu", o.vtu, "ParaView output file ('none' to skip)")->capture_default_str();
  app.add_option("--vtu-samples", o.samples, "--vtu-format linear: sample points per direction per element in the .vtu")->check(iga::io::whole_number(2, 64))->capture_default_str();
  app.add_option("--vtu-format", o.vtu_format, "bezier: one exact Bezier cell per polynomial element (an interpolating one of degree --vtu-degree at extraordinary vertices), points shared, plus <base>_outline.vtu with the element edges; linear: --vtu-samples linear cells per element")->check(CLI::IsMember(iga::io::vtu_formats()))->capture_default_str();
  app.add_option("--vtu-degree", o.vtu_degree, "--vtu-format bezier: degree of the cells of elements that are not polynomial")->check(iga::io::whole_number(1, 16))->capture_default_str();
  app.add_option("--net", o.net_vtu, "write the control net to this .vtu: the control points, and the --mesh faces whose corners are control points as polygons")->check(iga::io::non_blank());
  app.add_option("--json", o.json, "JSON report file ('none' to skip)")->capture_default_str();
  app.add_option("--max-memory", o.max_memory, "GiB this run may use (default: what the system has available); a run predicted to need more is refused before it starts")->check(iga::io::finite_number(0.001, 1e6));
  auto* study_option = app.add_option("--study", o.study, "convergence study over refinement levels K0:K1 (at least 3), each solved in this process: a table with rates on stderr, PREFIX.csv, PREFIX.json, plots; with --vtu a .vtu per level and a .pvd")
      ->check(CLI::Validator([](std::string& t) { return iga::bench::check_levels(t); }, "K0:K1"))
      ->excludes(app.get_option("--refine"))->excludes(app.get_option("--adaptive"));
  app.add_option("--degrees", o.degrees, "--study, bspline: one series per degree, e.g. 2,3,4")
      ->check(CLI::Validator([](std::string& t) { return iga::bench::check_degrees(t); }, "P,P,..."))
      ->needs(study_option)->excludes(app.get_option("--degree"));
  app.add_option("--study-output", o.study_output, "--study: PREFIX of PREFIX.csv, PREFIX.json and the plots PREFIX_dofs.png/.svg, PREFIX_seconds.png/.svg ('none': no files)")
      ->check(iga::io::non_blank())->needs(study_option)->capture_default_str();
  app.add_option("--plots", o.plots, "--study: plot formats png,svg, png or svg (matplotlib, through /usr/bin/python3), or none")
      ->check(CLI::Validator(
          [](std::string& t) {
            return t == "png,svg" || t == "png" || t == "svg" || t == "none" ? std::string() : "'" + t + "' is not png,svg, png, svg or none";
          },
          "png,svg|png|svg|none"))
      ->needs(study_option)->capture_default_str();
  iga::io::CommonOptions common{"iga-poisson"};
  iga::io::add_common_options(app, common);
  if (const auto code = iga::io::parse_command_line(app, argc, argv, common)) return *code;
  o.quiet = common.quiet;
  o.run_info = iga::io::run_info(app, common.program);
  for (const char* option : {"degree", "presubdivide", "refine-intervals", "geometry", "cc-boundary", "cc-enrich"}) {
    if (app.count(std::string("--") + option) > 0) o.given.emplace_back(option);
  }
  o.vtu_given = app.count("--vtu") > 0;
  o.json_given = app.count("--json") > 0;
  return iga::io::run_program("iga-poisson", [&] {
    // --solver petsc: PETSc on the ranks of mpirun (one without it). PETSc reads no command-line option of its
    // own (they come through --petsc-options and PETSC_OPTIONS); the other ranks stay silent, errors included.
    std::optional<iga::fem::ParallelSession> session;
    if (o.solver == "petsc") {
      int args = 1;
      session.emplace(args, argv);
      if (iga::fem::rank() > 0) {
        o.quiet = true;
        std::cerr.setstate(std::ios::failbit);
      }
      const int ranks = iga::fem::ranks();
      if (ranks > 1 && (o.adaptive >= 0 || !o.study.empty())) {
        throw iga::UnsupportedError(std::string(o.adaptive >= 0 ? "--adaptive" : "--study") +
                                    " with --solver petsc on more than one rank: not supported yet (run it on one rank)");
      }
      if (ranks > 1 && o.threads == 0) o.threads = std::max(1, static_cast<int>(std::thread::hardware_concurrency()) / ranks);
    }
    const int code = iga::io::run_program("iga-poisson", [&] { return o.study.empty() ? run(o) : study(o); });
    // mpirun ends the whole job at the first rank that exits non-zero: every rank waits here until rank 0 has
    // written its lines (its error line included).
    iga::fem::barrier();
    return code;
  });
}
