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
#include "io/discretisation_options.hpp"
#include "io/forecast.hpp"
#include "io/program.hpp"
#include "io/net_writer.hpp"
#include "io/option_rules.hpp"
#include "io/problem_run.hpp"
#include "io/progress.hpp"
#include "io/report.hpp"
#include "io/vtu_output.hpp"
#include "io/vtu_writer.hpp"
#include "quadrature/rule_provider.hpp"
#include "refine/adaptive.hpp"
#include "refine/uniform.hpp"

namespace {

struct Options {
  iga::io::DiscretisationOptions d;  ///< --basis, --mesh, --degree, --refine, ... (io/discretisation_options.hpp)
  std::string problem, source, dirichlet, neumann, neumann_boundary, neumann_where, exact;
  std::string petsc_options, partition;
  std::string solver = "cholmod", vtu = "result.vtu", json = "result.json";
  std::string mark = "doerfler", vtu_format = "bezier", net_vtu;
  int threads = 0, samples = 4;
  int adaptive = -1, admissibility = 2, vtu_degree = 6;
  long long max_dofs = 0;
  double theta = 0.5;
  double reaction = 0.0;
  std::string dirichlet_method = "strong";
  double nitsche_penalty = 0.0;  ///< 0: the local estimate
  double max_memory = 0.0;  ///< GiB; 0: what the system has available
  double max_seconds = 0.0;  ///< --adaptive steps and --study levels stop before one predicted to end past it; 0: none
  bool quiet = false, mean_zero = false;
  std::string study, degrees, study_output = "study", plots = "png,svg";  ///< --study K0:K1 and its options
  bool vtu_given = false, json_given = false;
  bool timer_table = true;  ///< the time per phase on stderr at the end (not for the levels of a study)
  nlohmann::json run_info;         ///< io::run_info: version, revision, every effective setting
};

using Log = std::function<void(const std::string&)>;
Log make_log(const Options& o) {
  return [quiet = o.quiet](const std::string& s) {
    if (!quiet) std::cerr << "iga-poisson: " << s << std::endl;
  };
}

// The backend, its options and the coarse net (io::Discretisation), and whether this run writes a .vtu.
struct Setup : iga::io::Discretisation {
  bool write_vtu = false;
};

Setup make_setup(const Options& o) {
  Setup s;
  static_cast<iga::io::Discretisation&>(s) = iga::io::make_discretisation(o.d);
  s.write_vtu = !o.vtu.empty() && o.vtu != "none";
  return s;
}

int refine_steps(const Options& o, const Setup& s) { return iga::io::refine_steps(o.d, s); }

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
  const int steps = refine_steps(o, s) + (o.d.count("presubdivide") ? o.d.presubdivide : 0);
  std::ostringstream what;
  what << "this run (about " << std::setprecision(3) << iga::io::predicted_elements(o.d, s) << " elements after " << steps
       << " refinement steps)";
  check_size(o, s, iga::io::predicted_elements(o.d, s), what.str());
}

iga::refine::Refinement make_geometry(const Options& o, const Setup& s, iga::basis::BackendFacts& facts) {
  return iga::io::refined_geometry(
      o.d, s, facts,
      [&](iga::Index elements, iga::Index dofs) {
        check_size(o, s, static_cast<double>(std::max(elements, dofs)),
                   "this run (" + std::to_string(elements) + " elements, " + std::to_string(dofs) + " dofs)");
      },
      o.solver == "mg");
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
    fem::check_problem_domain(mp, geometry, "--problem " + problem_name);
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

// A step's wall time (io::StepForecast: from the end of the step before, its refinement and output included) and
// the time predicted for the step after it (none for the last).
struct StepTimes {
  double wall = 0.0;
  std::optional<double> predicted_next;
};

// The adaptive loop's check after each step: the step's progress line with the forecast of the next, and the time
// limit (--max-seconds): the reason to stop before a step predicted to end past it, or once the time is spent.
iga::refine::StepCheck step_check(iga::io::StepForecast& forecast, std::vector<StepTimes>& times, const Log& log) {
  return [&forecast, &times, log, built = false](const iga::refine::AdaptiveStep& st,
                                                 const std::optional<iga::refine::NextStep>& next) mutable {
    forecast.done(static_cast<double>(st.dofs), built, forecast.elapsed());
    const std::string next_name = next ? std::to_string(next->step) : std::string();
    const bool builds = next && next->builds_level;
    times.push_back({forecast.last_seconds(), next ? std::optional<double>(forecast.predict(builds)) : std::nullopt});
    log("step " + std::to_string(st.step) + ": " + std::to_string(st.dofs) + " dofs, " + std::to_string(st.levels) +
        " levels, estimate " + std::to_string(st.estimate) +
        (st.energy_error ? ", energy error " + std::to_string(*st.energy_error) : std::string()) + "; " +
        forecast.progress(next_name, builds));
    built = builds;
    return next ? forecast.stop_reason(next_name, builds, forecast.elapsed()) : std::string();
  };
}

// --adaptive: solve → estimate → mark → refine, one .vtu per step and a .pvd series; r is the last step's result.
// Returns the report's "adaptive" object.
nlohmann::json solve_adaptive(const Options& o, const Setup& s, const iga::basis::Geometry& geometry,
                              const iga::quadrature::RuleProvider& rules, const iga::fem::PoissonProblem& problem,
                              const iga::fem::SolverOptions& solver, const iga::io::VtuOutput& vtu_output,
                              iga::fem::PoissonResult& r, std::optional<iga::basis::Geometry>& last,
                              iga::io::StepForecast& forecast, const Log& log) {
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
  std::vector<StepTimes> times;
  const refine::AdaptiveRun run =
      refine::adaptive_solve(geometry, rules, problem, solver, ao, on_step, step_check(forecast, times, log));
  const std::vector<refine::AdaptiveStep>& history = run.history;
  if (run.stopped != "steps") log("adaptive loop stopped after step " + std::to_string(history.back().step) + ": " + run.stopped);
  nlohmann::json adaptive_json = {{"steps", o.adaptive}, {"theta", o.theta}, {"marking", refine::to_string(ao.marking)},
                                  {"max_dofs", o.max_dofs}, {"admissibility", o.admissibility},
                                  {"max_seconds", o.max_seconds}, {"stopped", run.stopped}};
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
    const StepTimes& t = times.at(static_cast<std::size_t>(st.step));
    adaptive_json["history"].back()["wall_seconds"] = t.wall;
    adaptive_json["history"].back()["predicted_next_seconds"] = t.predicted_next ? nlohmann::json(*t.predicted_next) : nlohmann::json(nullptr);
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
  j.update(iga::io::discretisation_report(o.d, s, refined, facts));
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
  if (!r.error_derivatives.empty()) j["error_derivatives"] = r.error_derivatives;  // of the exact gradient in H1
  iga::io::report_solve(j, r, solver);
  j["dirichlet_edges"] = r.dirichlet_edges;
  j["neumann_edges"] = r.neumann_edges;
  j["mean_zero"] = r.mean_zero;
  j["nitsche_penalty"] = r.nitsche_penalty > 0.0 ? nlohmann::json(r.nitsche_penalty) : nlohmann::json(nullptr);
  if (r.mean_zero) {
    // The pure-Neumann data's solvability ∫f + ∫g = 0 (fem/compatibility.hpp): what was judged and what was done.
    const iga::fem::Compatibility& c = r.compatibility;
    j["compatibility_defect"] = r.compatibility_defect;
    j["compatibility"] = c.word();
    j["compatibility_relative"] = c.relative();
    j["compatibility_integrals"] = {{"source", c.finer.source}, {"neumann", c.finer.neumann},
                                    {"source_abs", c.finer.source_abs}, {"neumann_abs", c.finer.neumann_abs},
                                    {"quadrature_error", c.quadrature_error()}};
  }
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
  // Every output path before the work (a study checks its own files): refused now, not after the solve.
  if (fem::rank() == 0) {
    io::check_writable(o.json);
    io::check_writable(o.vtu);
    io::check_writable(o.net_vtu);
  }
  io::Progress progress("iga-poisson", o.quiet);
  io::StepForecast forecast(o.max_seconds);  // the time limit counts from here
  const Setup s = make_setup(o);
  check_predicted_size(o, s);
  basis::BackendFacts facts;
  refine::Refinement refined = progress.phase("refinement", [&] { return make_geometry(o, s, facts); });
  for (const std::string& note : facts.notes) log(note);
  const basis::Geometry& geometry = refined.geometry;
  if (geometry.orientation() < 0) log("note: the planar net is oriented clockwise (det J < 0); solved as it is (the same solution)");
  std::string problem_name;
  const fem::PoissonProblem problem = make_problem(o, geometry, problem_name);
  const std::unique_ptr<quadrature::RuleProvider> rules = iga::io::make_rules(o.d, s);
  const fem::SolverOptions solver = io::solver_options(o.solver, o.petsc_options, o.partition, std::move(refined.steps));

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
      return solve_adaptive(o, s, geometry, *rules, problem, solver, vtu_output, r, last, forecast, log);
    });
  } else {
    r = solve_in_phases(geometry, *rules, problem, solver, progress);
  }
  if (r.mean_zero && r.compatibility.verdict() == fem::Compatibility::Verdict::kWarned && fem::rank() == 0) {
    std::cerr << "iga-poisson: warning: " << r.compatibility.warning() << std::endl;
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
  const std::vector<std::string>& takes = iga::basis::backend(o.d.basis).options;
  if (!o.degrees.empty() && std::find(takes.begin(), takes.end(), "degree") == takes.end()) {
    throw iga::InputError("--degrees: --basis " + o.d.basis + " has a fixed degree");
  }
  if (!o.source.empty() && o.exact.empty()) {
    throw iga::InputError("--study needs an exact solution for its error norms: give --exact with --source (or --problem)");
  }
  so.output = o.study_output;
  if (o.json_given) iga::io::check_writable(o.json);  // the study's files before its levels run
  if (iga::io::writes(so.output)) iga::io::check_writable(so.output + ".csv");
  so.plots = o.plots;
  so.vtu = o.vtu_given ? o.vtu : std::string();
  so.json = o.json_given ? o.json : std::string();
  so.quiet = o.quiet;
  so.max_seconds = o.max_seconds;
  auto level = [&o](int degree, int refine, const std::string& vtu) {
    Options lo = o;
    lo.d.refine = refine;
    if (degree > 0) {
      lo.d.degree = degree;
      if (!lo.d.count("degree")) lo.d.given.emplace_back("degree");
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

// Defaults that depend on the basis, before the option rules and the report's settings see them: without
// --dirichlet-method, the conditions are imposed weakly where the backend prefers it (basis::Backend::
// prefers_weak_dirichlet; cc with the clamped rule), strongly otherwise; --adaptive refines by its estimator, so no
// a priori grading (--grade-evs) by default.
void resolve_backend_defaults(CLI::App& app, Options& o) {
  if (app.count("--dirichlet-method") == 0) {
    const iga::basis::Backend& backend = iga::basis::backend(o.d.basis);
    const bool weak = backend.prefers_weak_dirichlet && backend.prefers_weak_dirichlet(iga::io::backend_options(o.d));
    o.dirichlet_method = weak ? "nitsche" : "strong";
    app.get_option("--dirichlet-method")->default_str(o.dirichlet_method);
  }
  if (o.adaptive >= 0 && app.count("--grade-evs") == 0) o.d.grade_evs = 0;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"iga-poisson: solve -Δu + c u = f (Laplace–Beltrami on surfaces) with isogeometric elements"};
  Options o;
  iga::io::add_discretisation_options(app, o.d);
  app.add_option("--adaptive", o.adaptive, "adaptive refinement: STEPS rounds of solve, estimate (residual estimator), mark, refine locally (bspline: THB; the --refine steps come first); one .vtu per step plus a .pvd series")->check(iga::io::whole_number(0, 200));
  app.add_option("--theta", o.theta, "--adaptive: marking parameter in (0, 1]")->check(iga::io::finite_number(1e-6, 1.0))->capture_default_str();
  app.add_option("--mark", o.mark, "--adaptive: doerfler (bulk) or max")->check(CLI::IsMember({"doerfler", "max"}))->capture_default_str();
  app.add_option("--max-dofs", o.max_dofs, "--adaptive: stop after the first solve with at least this many dofs (0: no limit)")->check(iga::io::whole_number(0, 1000000000000LL));
  app.add_option("--admissibility", o.admissibility, "--adaptive: class m of admissible meshes (>= 2; 0 refines exactly the marked elements)")->check(CLI::IsMember({0, 2, 3, 4, 5, 6}))->capture_default_str();
  std::string names;
  for (const auto& n : iga::fem::manufactured_problem_names()) names += (names.empty() ? "" : ", ") + n;
  app.add_option("--problem", o.problem, "built-in manufactured problem (" + names + "); default sine when no --source/--exact")->check(iga::io::non_blank());
  app.add_option("--source", o.source, "f(x,y,z) in -Δu + c u = f (muparser expression)")->check(iga::io::non_blank());
  app.add_option("--dirichlet", o.dirichlet, "u on the Dirichlet boundary, g(x,y,z); default: --exact, else 0")->check(iga::io::non_blank());
  app.add_option("--neumann", o.neumann, "∂u/∂n on the Neumann parts, g(x,y,z,nx,ny,nz)")->check(iga::io::non_blank());
  app.add_option("--neumann-boundary", o.neumann_boundary, "comma-separated boundary parts with Neumann data (bspline: v0,u1,v1,u0; cc: b<loop>.<segment> between corners; or indices)")->check(iga::io::non_blank());
  app.add_option("--neumann-where", o.neumann_where, "boundary edges whose midpoint makes this expression > 0 get Neumann data, e.g. 'x > 0.999'")->check(iga::io::non_blank());
  app.add_option("--dirichlet-method", o.dirichlet_method, "strong (L2 projection onto the boundary traces, eliminated) or nitsche (weak, symmetric Nitsche: needs no trace space; for --cc-boundary clamped at boundary extraordinary vertices); default: nitsche for cc with --cc-boundary clamped, strong otherwise")->check(CLI::IsMember({"strong", "nitsche"}));
  app.add_option("--nitsche-penalty", o.nitsche_penalty, "--dirichlet-method nitsche: a fixed penalty γ in γ/h (h the side length); 0: each element's own from its local eigenvalue estimate (coercive by construction)")->check(iga::io::finite_number(0.0))->capture_default_str();
  app.add_flag("--mean-zero", o.mean_zero, "without Dirichlet boundary and reaction (closed surfaces): the solution with mean zero");
  app.add_option("--exact", o.exact, "exact solution u(x,y,z): enables L2 and H1 error norms")->check(iga::io::non_blank());
  app.add_option("--reaction", o.reaction, "c >= 0 in -Δu + c u = f")->check(iga::io::finite_number(0))->capture_default_str();
  app.add_option("--solver", o.solver, "cholmod, cg (Eigen, incomplete Cholesky), petsc (a PETSc KSP, CG + GAMG by default, on the ranks of mpirun: each assembles its own part of the elements, --partition), or mg (PETSc CG + geometric multigrid on the nested spaces of the --refine steps, and of the adaptive steps with --adaptive)")->capture_default_str();
  iga::io::add_partition_option(app, o.partition);
  app.add_option("--petsc-options", o.petsc_options, "--solver petsc or mg: PETSc options, e.g. '-pc_type hypre' or '-ksp_type preonly -pc_type lu -pc_factor_mat_solver_type mumps' (the PETSC_OPTIONS environment is read too)")->check(iga::io::non_blank());
  app.add_option("--threads", o.threads, "threads for assembly (default: OpenMP's)")->check(iga::io::thread_count());
  app.add_option("--vtu", o.vtu, "ParaView output file ('none' to skip)")->capture_default_str();
  app.add_option("--vtu-samples", o.samples, "--vtu-format linear: sample points per direction per element in the .vtu")->check(iga::io::whole_number(2, 64))->capture_default_str();
  app.add_option("--vtu-format", o.vtu_format, "bezier: one exact Bezier cell per polynomial element (an interpolating one of degree --vtu-degree at extraordinary vertices), points shared, plus <base>_outline.vtu with the element edges; linear: --vtu-samples linear cells per element")->check(CLI::IsMember(iga::io::vtu_formats()))->capture_default_str();
  app.add_option("--vtu-degree", o.vtu_degree, "--vtu-format bezier: degree of the cells of elements that are not polynomial")->check(iga::io::whole_number(1, 16))->capture_default_str();
  app.add_option("--net", o.net_vtu, "write the control net to this .vtu: the control points, and the --mesh faces whose corners are control points as polygons")->check(iga::io::non_blank());
  app.add_option("--json", o.json, "JSON report file ('none' to skip)")->capture_default_str();
  app.add_option("--max-seconds", o.max_seconds, "--adaptive and --study: a time limit in seconds (default 0: none); before each step (level) its time is predicted from the steps done, and one predicted to end past the limit is not started: the report and output are those of the last complete step, the report's \"stopped\" and one line on stderr say why (exit 0)")->check(iga::io::finite_number(0.0, 1e9))->capture_default_str();
  app.add_option("--max-memory", o.max_memory, "GiB this run may use (default: what the system has available); a run predicted to need more is refused before it starts")->check(iga::io::finite_number(0.001, 1e6));
  app.add_option("--study", o.study, "convergence study over refinement levels K0:K1 (at least 3), each solved in this process: a table with rates on stderr, PREFIX.csv, PREFIX.json, plots; with --vtu a .vtu per level and a .pvd")
      ->check(CLI::Validator([](std::string& t) { return iga::bench::check_levels(t); }, "K0:K1"));
  app.add_option("--degrees", o.degrees, "--study, bspline: one series per degree, e.g. 2,3,4")
      ->check(CLI::Validator([](std::string& t) { return iga::bench::check_degrees(t); }, "P,P,..."));
  app.add_option("--study-output", o.study_output, "--study: PREFIX of PREFIX.csv, PREFIX.json and the plots PREFIX_dofs.png/.svg, PREFIX_seconds.png/.svg ('none': no files)")
      ->check(iga::io::non_blank())->capture_default_str();
  app.add_option("--plots", o.plots, "--study: plot formats png,svg, png or svg (matplotlib, through /usr/bin/python3), or none")
      ->check(CLI::Validator(
          [](std::string& t) {
            return t == "png,svg" || t == "png" || t == "svg" || t == "none" ? std::string() : "'" + t + "' is not png,svg, png, svg or none";
          },
          "png,svg|png|svg|none"))
      ->capture_default_str();
  iga::io::CommonOptions common{"iga-poisson"};
  iga::io::add_common_options(app, common);
  if (const auto code = iga::io::parse_command_line(app, argc, argv, common)) return *code;
  iga::io::record_given_options(app, o.d);
  resolve_backend_defaults(app, o);
  if (const auto code = iga::io::check_option_rules(app, common.program)) return *code;
  o.quiet = common.quiet;
  o.run_info = iga::io::run_info(app, common.program);
  o.vtu_given = app.count("--vtu") > 0;
  o.json_given = app.count("--json") > 0;
  // --solver petsc: on the ranks of mpirun (one without it), rank 0 speaking for all.
  return iga::io::run_solver_program("iga-poisson", iga::io::solver_uses_petsc(o.solver, o.d.basis), argv, o.quiet, o.threads, [&] {
    if (iga::fem::ranks() > 1 && (o.adaptive >= 0 || !o.study.empty())) {
      throw iga::UnsupportedError(std::string(o.adaptive >= 0 ? "--adaptive" : "--study") +
                                  " with --solver " + o.solver + " on more than one rank: not supported yet, each step's estimate, marking and refinement would run on the "
                                  "whole space on every rank and every rank would write its files (run it on one rank)");
    }
    return o.study.empty() ? run(o) : study(o);
  });
}
