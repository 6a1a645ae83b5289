// iga-poisson: Poisson/Laplace on planar domains (Laplace–Beltrami on surfaces), -Δu + c u = f, with
// strong Dirichlet and natural Neumann conditions. Thin: parses options and calls the library.
#include <CLI/CLI.hpp>
#include <chrono>
#include <cmath>
#include <iomanip>
#include <iostream>
#include <algorithm>
#include <nlohmann/json.hpp>
#include <optional>
#include <sstream>

#include "basis/registry.hpp"
#include "core/error.hpp"
#include "fem/expression.hpp"
#include "fem/memory.hpp"
#include "fem/poisson.hpp"
#include "fem/problems.hpp"
#include "fem/threads.hpp"
#include "io/program.hpp"
#include "io/report.hpp"
#include "io/net_writer.hpp"
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
  std::string quadrature, solver = "cholmod", vtu = "result.vtu", json = "result.json", refine_intervals;
  std::string geometry, mark = "doerfler", vtu_format = "bezier", net_vtu;
  int degree = 3, refine = -1, threads = 0, samples = 4, presubdivide = 0;
  int adaptive = -1, admissibility = 2, vtu_degree = 6;
  long long max_dofs = 0;
  double theta = 0.5;
  double reaction = 0.0;
  double max_memory = 0.0;  ///< GiB; 0: what the system has available
  bool quiet = false, mean_zero = false;
  std::vector<std::string> given;  ///< backend options given on the command line (names without dashes)
  bool count(const std::string& option) const { return std::find(given.begin(), given.end(), option) != given.end(); }
};

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

int run(const Options& o) {
  using namespace iga;
  const auto t_start = std::chrono::steady_clock::now();
  auto log = [&](const std::string& s) {
    if (!o.quiet) std::cerr << "iga-poisson: " << s << std::endl;
  };
  if (o.threads > 0) fem::set_num_threads(o.threads);
  // The backend from the registry: its options, defaults and construction (no backend policy here).
  const basis::Backend& backend = basis::backend(o.basis);
  basis::check_options(backend, o.given);
  basis::BackendOptions bo;
  if (o.count("degree")) bo.degree = o.degree;
  if (o.count("presubdivide")) bo.presubdivide = o.presubdivide;
  if (o.count("geometry")) bo.geometry = o.geometry;
  bo.net_name = o.mesh;
  const int degree = basis::degree(backend, bo);
  const int refine_steps = o.refine >= 0 ? o.refine : backend.default_refine;
  basis::BackendFacts facts;
  std::optional<mesh::PolyMesh> net;
  if (!o.mesh.empty()) net = mesh::read_obj(o.mesh);
  // Size before work: the elements the refinement will make (each step splits every element in four), and the
  // memory of the solve and the output, against what is available.
  const bool write_vtu = !o.vtu.empty() && o.vtu != "none";
  const double max_bytes = o.max_memory * 1024.0 * 1024.0 * 1024.0;
  auto check_size = [&](double elements, const std::string& what) {
    fem::check_memory(fem::poisson_memory(elements, (degree + 1) * (degree + 1)) +
                          (write_vtu ? fem::vtu_memory(elements, o.vtu_format == "linear" ? o.samples : o.vtu_degree + 1) : 0.0),
                      max_bytes, what,
                      "each --refine or --presubdivide step needs four times more" +
                          (write_vtu && o.vtu_format == "linear" ? "; --vtu-samples " + std::to_string(o.samples) + " writes " +
                                           std::to_string(o.samples * o.samples) + " points per element"
                                     : std::string()));
  };
  {
    const int pre = o.count("presubdivide") ? o.presubdivide : 0;
    const double coarse = net ? static_cast<double>(net->num_faces()) : 1.0;
    const double predicted = coarse * std::pow(4.0, refine_steps + pre);
    std::ostringstream what;
    what << "this run (about " << std::setprecision(3) << predicted << " elements after " << refine_steps + pre << " refinement steps)";
    check_size(predicted, what.str());
  }
  // --refine-intervals: each step halves only the listed knot intervals, in both directions (refine-and-smooth).
  const std::vector<Index> intervals = parse_intervals(o.refine_intervals);
  refine::Refinement refined =
      basis::make_refined_geometry(backend, net ? &*net : nullptr, bo, intervals.empty() ? refine_steps : 0, facts);
  for (int s = 0; !intervals.empty() && s < refine_steps; ++s) {
    refined = refine::refine_smooth_tensor(refined.geometry, intervals, intervals);
  }
  for (const std::string& note : facts.notes) log(note);
  const basis::Geometry& geometry = refined.geometry;
  check_size(static_cast<double>(std::max(geometry.space().num_elements(), geometry.space().num_dofs())),
             "this run (" + std::to_string(geometry.space().num_elements()) + " elements, " +
                 std::to_string(geometry.space().num_dofs()) + " dofs)");
  const bool surface = geometry.dim() == 3;
  if (geometry.orientation() < 0) log("note: the planar net is oriented clockwise (det J < 0); solved as it is (the same solution)");
  const auto names = geometry.space().boundary_part_names();

  // The problem: a built-in manufactured one, expressions, or both (expressions override).
  fem::PoissonProblem problem;
  problem.reaction = o.reaction;
  std::string problem_name = o.problem;
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
  std::shared_ptr<const fem::Function> builtin_exact;
  if (!problem_name.empty()) {
    if (surface) throw UnsupportedError("--problem " + problem_name + ": built-in problems are for planar domains; give --source and --exact for surfaces");
    const fem::ManufacturedProblem mp = fem::manufactured_problem(problem_name, o.reaction);
    problem.source = mp.source;
    problem.exact = mp.exact;
    problem.dirichlet = mp.exact;
    builtin_exact = mp.exact;
  }
  if (!o.source.empty()) problem.source = std::make_shared<fem::Expression>(o.source, "--source");
  if (!o.exact.empty()) {
    auto exact = std::make_shared<fem::Expression>(o.exact, "--exact");
    exact->set_fd_step(fem::finite_difference_step(geometry));  // its gradient: the H1 error, Neumann data
    problem.exact = exact;
    if (o.dirichlet.empty()) problem.dirichlet = problem.exact;
  }
  if (!o.dirichlet.empty()) problem.dirichlet = std::make_shared<fem::Expression>(o.dirichlet, "--dirichlet");
  fem::select_neumann(problem, o.neumann, o.neumann_boundary, o.neumann_where, names);
  problem.mean_zero = o.mean_zero;
  std::unique_ptr<quadrature::RuleProvider> rules;
  try {
    rules = quadrature::make_rule_provider(o.quadrature.empty() ? backend.default_quadrature(degree) : o.quadrature, degree + 1);
  } catch (const InputError& e) {
    throw InputError("--quadrature: " + std::string(e.what()));
  }
  if (rules->name().rfind("gauss:", 0) == 0 && std::stoi(rules->name().substr(6)) < degree + 1) {
    // Fewer Gauss points than degree + 1 per direction integrate neither the stiffness nor the boundary mass of
    // degree-p functions exactly even on affine elements, and leave the latter singular: not an answer to report.
    throw InputError("--quadrature " + o.quadrature + ": " + rules->name().substr(6) + " points per direction are fewer than degree + 1 = " +
                     std::to_string(degree + 1) + " (the least that integrates the matrices of degree-" +
                     std::to_string(degree) + " functions exactly on affine elements)");
  }
  const fem::SolverOptions solver{fem::parse_solver(o.solver)};

  log("solving on " + std::to_string(geometry.space().num_dofs()) + " dofs, " +
      std::to_string(geometry.space().num_elements()) + " elements, " + std::to_string(fem::num_threads()) + " threads");
  // --adaptive: solve → estimate → mark → refine, one .vtu per step and a .pvd series; the report's top-level
  // figures are the last step's.
  fem::PoissonResult r;
  io::VtuOutput vtu_output;
  vtu_output.format = o.vtu_format;
  vtu_output.samples = o.samples;
  vtu_output.degree = o.vtu_degree;
  vtu_output.exact = problem.exact;
  std::optional<basis::Geometry> final_geometry;
  nlohmann::json adaptive_json;
  if (o.adaptive >= 0) {
    refine::AdaptiveOptions ao;
    ao.steps = o.adaptive;
    ao.theta = o.theta;
    ao.marking = refine::parse_marking(o.mark);
    ao.max_dofs = o.max_dofs;
    ao.admissibility = o.admissibility;
    const std::string base = o.vtu.size() > 4 && o.vtu.substr(o.vtu.size() - 4) == ".vtu" ? o.vtu.substr(0, o.vtu.size() - 4) : o.vtu;
    std::vector<io::SeriesEntry> series;
    auto on_step = [&](const refine::AdaptiveStep& s, const basis::Geometry& g, const fem::PoissonResult& res, const fem::Estimate& est) {
      log("step " + std::to_string(s.step) + ": " + std::to_string(s.dofs) + " dofs, " + std::to_string(s.levels) +
          " levels, estimate " + std::to_string(s.estimate) +
          (s.energy_error ? ", energy error " + std::to_string(*s.energy_error) : std::string()));
      r = res;
      final_geometry = g;
      if (write_vtu) {
        char name[32];
        std::snprintf(name, sizeof name, "_step%03d.vtu", s.step);
        const std::string file = base + name;
        io::write_output(file, g, &res.u, vtu_output, {{"indicator", est.indicators}});
        const std::size_t slash = file.find_last_of('/');
        series.push_back({static_cast<double>(s.step), slash == std::string::npos ? file : file.substr(slash + 1)});
        io::write_pvd(base + ".pvd", series);
      }
    };
    const refine::AdaptiveRun run = refine::adaptive_solve(geometry, *rules, problem, solver, ao, on_step);
    const std::vector<refine::AdaptiveStep>& history = run.history;
    if (run.stopped != "steps") log("adaptive loop stopped after step " + std::to_string(history.back().step) + ": " + run.stopped);
    adaptive_json = {{"steps", o.adaptive}, {"theta", o.theta}, {"marking", refine::to_string(ao.marking)},
                     {"max_dofs", o.max_dofs}, {"admissibility", o.admissibility}, {"stopped", run.stopped}};
    if (write_vtu) adaptive_json["pvd"] = base + ".pvd";
    for (const refine::AdaptiveStep& s : history) {
      auto opt = [](const std::optional<double>& v) { return v ? nlohmann::json(*v) : nlohmann::json(nullptr); };
      adaptive_json["history"].push_back(
          {{"step", s.step}, {"dofs", s.dofs}, {"elements", s.elements}, {"levels", s.levels},
           {"quadrature_points", s.quadrature_points}, {"estimate", s.estimate}, {"energy_error", opt(s.energy_error)},
           {"l2_error", opt(s.l2_error)}, {"efficiency_index", opt(s.efficiency)}, {"marked", s.marked},
           {"added_for_admissibility", s.added},
           {"seconds", {{"setup", s.setup_seconds}, {"assembly", s.assembly_seconds}, {"solve", s.solve_seconds},
                        {"errors", s.error_seconds}, {"estimate", s.estimate_seconds}, {"mark", s.mark_seconds},
                        {"refine", s.refine_seconds}}}});
    }
  } else {
    r = fem::solve_poisson(geometry, *rules, problem, solver);
    final_geometry = geometry;
  }
  auto fmt = [](double v) {
    std::ostringstream s;
    s << std::setprecision(4) << v;
    return s.str();
  };
  log("assembly " + fmt(r.assembly_seconds) + " s, solve " + fmt(r.solve_seconds) + " s (" + r.solver + ")");

  nlohmann::json j;
  j["program"] = "iga-poisson";
  j["basis"] = o.basis;
  j["mesh"] = o.mesh.empty() ? "default:" + (o.geometry.empty() ? std::string("quarter-annulus") : o.geometry) : o.mesh;
  j["dimension"] = geometry.dim();
  j["orientation"] = geometry.orientation();
  j["degree"] = degree;
  j["refine"] = refine_steps;
  j["nested_refinement"] = refined.nested;
  if (o.adaptive >= 0) j["adaptive"] = adaptive_json;
  if (!o.refine_intervals.empty()) j["refine_intervals"] = o.refine_intervals;
  for (const auto& [path, count] : facts.counts) j[nlohmann::json::json_pointer("/" + path)] = count;
  j["problem"] = {{"name", problem_name.empty() ? nullptr : nlohmann::json(problem_name)},
                  {"source", o.source}, {"dirichlet", o.dirichlet}, {"neumann", o.neumann},
                  {"neumann_boundary", o.neumann_boundary}, {"neumann_where", o.neumann_where}, {"exact", o.exact},
                  {"reaction", o.reaction}, {"mean_zero", o.mean_zero}};
  j["dofs"] = r.dofs;
  j["free_dofs"] = r.free_dofs;
  j["dirichlet_dofs"] = r.dirichlet_dofs;
  j["elements"] = r.elements;
  j["quadrature"] = rules->name();
  j["quadrature_points"] = r.quadrature_points;
  j["domain_measure"] = r.domain_measure;
  j["threads"] = fem::num_threads();
  j["pattern_seconds"] = r.pattern_seconds;
  j["assembly_seconds"] = r.assembly_seconds;
  j["solve_seconds"] = r.solve_seconds;
  j["solver"] = r.solver;
  j["solver_iterations"] = r.solver_iterations;
  j["residual_norm"] = r.residual_norm;
  j["residual_tolerance"] = solver.max_residual;
  j["dirichlet_edges"] = r.dirichlet_edges;
  j["neumann_edges"] = r.neumann_edges;
  j["mean_zero"] = r.mean_zero;
  if (r.mean_zero) j["compatibility_defect"] = r.compatibility_defect;
  j["l2_error"] = nullptr;
  j["h1_error"] = nullptr;
  if (r.errors) {
    j["l2_error"] = r.errors->l2;
    j["h1_error"] = r.errors->h1;
    // Relative errors where the exact solution has a norm to compare with (u = 0 has none: the key is left out).
    if (r.errors->l2_exact > 0) j["l2_error_relative"] = r.errors->l2 / r.errors->l2_exact;
    if (r.errors->h1_exact > 0) j["h1_error_relative"] = r.errors->h1 / r.errors->h1_exact;
    log("L2 error " + fmt(r.errors->l2) + ", H1 seminorm error " + fmt(r.errors->h1));
  }
  if (write_vtu) j["vtu_output"] = vtu_output.settings();
  if (write_vtu && o.adaptive < 0) {
    const std::vector<std::string> files = io::write_output(o.vtu, geometry, &r.u, vtu_output);
    j["vtu"] = o.vtu;
    if (files.size() > 1) j["vtu_outline"] = files[1];
    for (const std::string& f : files) log("wrote " + f);
  } else if (write_vtu) {
    log("wrote " + adaptive_json["pvd"].get<std::string>() + " and its " + std::to_string(adaptive_json["history"].size()) + " .vtu files");
  }
  if (!o.net_vtu.empty()) {
    io::write_control_net_vtu(o.net_vtu, final_geometry ? *final_geometry : geometry, net ? &*net : nullptr);
    j["net_vtu"] = o.net_vtu;
    log("wrote " + o.net_vtu);
  }
  j["total_seconds"] = std::chrono::duration<double>(std::chrono::steady_clock::now() - t_start).count();
  if (!o.json.empty() && o.json != "none") {
    io::write_json(o.json, j);
    log("wrote " + o.json);
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"iga-poisson: solve -Δu + c u = f (Laplace–Beltrami on surfaces) with isogeometric elements"};
  Options o;
  app.add_option("--mesh", o.mesh, "Wavefront OBJ control net (a quad grid for bspline); default: the embedded quarter annulus")
      ->check(CLI::ExistingFile);
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
  app.add_option("--geometry", o.geometry, "bspline without --mesh: the built-in geometry, quarter-annulus (default) or l-shape ([0,2]^2 minus (1,2]^2, one patch with a C0 line from the reflex corner)")->check(iga::io::non_blank());
  app.add_option("--adaptive", o.adaptive, "adaptive refinement: STEPS rounds of solve, estimate (residual estimator), mark, refine locally (bspline: THB; the --refine steps come first); one .vtu per step plus a .pvd series")->check(iga::io::whole_number(0, 200));
  app.add_option("--theta", o.theta, "--adaptive: marking parameter in (0, 1]")->check(iga::io::finite_number(1e-6, 1.0))->capture_default_str();
  app.add_option("--mark", o.mark, "--adaptive: doerfler (bulk) or max")->check(CLI::IsMember({"doerfler", "max"}))->capture_default_str();
  app.add_option("--max-dofs", o.max_dofs, "--adaptive: stop after the first solve with at least this many dofs (0: no limit)")->check(iga::io::whole_number(0, 1000000000000LL));
  app.add_option("--admissibility", o.admissibility, "--adaptive: class m of admissible meshes (>= 2; 0 refines exactly the marked elements)")->check(CLI::IsMember({0, 2, 3, 4, 5, 6}))->capture_default_str();
  app.add_option("--presubdivide", o.presubdivide, "polyhedral: Catmull–Clark steps applied to the net first (one makes any net with valences and face sizes <= 8 admissible)")->check(iga::io::whole_number(0, 6));
  std::string names;
  for (const auto& n : iga::fem::manufactured_problem_names()) names += (names.empty() ? "" : ", ") + n;
  app.add_option("--problem", o.problem, "built-in manufactured problem (" + names + "); default sine when no --source/--exact")->check(iga::io::non_blank());
  app.add_option("--source", o.source, "f(x,y,z) in -Δu + c u = f (muparser expression)")->check(iga::io::non_blank());
  app.add_option("--dirichlet", o.dirichlet, "u on the Dirichlet boundary, g(x,y,z); default: --exact, else 0")->check(iga::io::non_blank());
  app.add_option("--neumann", o.neumann, "∂u/∂n on the Neumann parts, g(x,y,z,nx,ny,nz)")->check(iga::io::non_blank());
  app.add_option("--neumann-boundary", o.neumann_boundary, "comma-separated boundary parts with Neumann data (bspline: v0,u1,v1,u0; cc: b<loop>.<segment> between corners; or indices)")->check(iga::io::non_blank());
  app.add_option("--neumann-where", o.neumann_where, "boundary edges whose midpoint makes this expression > 0 get Neumann data, e.g. 'x > 0.999'")->check(iga::io::non_blank());
  app.add_flag("--mean-zero", o.mean_zero, "without Dirichlet boundary and reaction (closed surfaces): the solution with mean zero");
  app.add_option("--exact", o.exact, "exact solution u(x,y,z): enables L2 and H1 error norms")->check(iga::io::non_blank());
  app.add_option("--reaction", o.reaction, "c >= 0 in -Δu + c u = f")->check(iga::io::finite_number(0))->capture_default_str();
  app.add_option("--quadrature", o.quadrature, "quadrature rule: gauss:P (P points per direction) or tiles:P:L (P×P Gauss on each tile of levels 1..L of elements at extraordinary vertices); default gauss:degree+1");
  app.add_option("--solver", o.solver, "cholmod or cg")->capture_default_str();
  app.add_option("--threads", o.threads, "threads for assembly (default: OpenMP's)")->check(iga::io::thread_count());
  app.add_option("--vtu", o.vtu, "ParaView output file ('none' to skip)")->capture_default_str();
  app.add_option("--vtu-samples", o.samples, "--vtu-format linear: sample points per direction per element in the .vtu")->check(iga::io::whole_number(2, 64))->capture_default_str();
  app.add_option("--vtu-format", o.vtu_format, "bezier: one exact Bezier cell per polynomial element (an interpolating one of degree --vtu-degree at extraordinary vertices), points shared, plus <base>_outline.vtu with the element edges; linear: --vtu-samples linear cells per element")->check(CLI::IsMember(iga::io::vtu_formats()))->capture_default_str();
  app.add_option("--vtu-degree", o.vtu_degree, "--vtu-format bezier: degree of the cells of elements that are not polynomial")->check(iga::io::whole_number(1, 16))->capture_default_str();
  app.add_option("--net", o.net_vtu, "write the control net to this .vtu: the control points, and the --mesh faces whose corners are control points as polygons")->check(iga::io::non_blank());
  app.add_option("--json", o.json, "JSON report file ('none' to skip)")->capture_default_str();
  app.add_option("--max-memory", o.max_memory, "GiB this run may use (default: what the system has available); a run predicted to need more is refused before it starts")->check(iga::io::finite_number(0.001, 1e6));
  app.add_flag("--quiet", o.quiet, "no progress on stderr");
  if (const auto code = iga::io::parse_command_line(app, argc, argv, "iga-poisson")) return *code;
  for (const char* option : {"degree", "presubdivide", "refine-intervals", "geometry"}) {
    if (app.count(std::string("--") + option) > 0) o.given.emplace_back(option);
  }
  return iga::io::run_program("iga-poisson", [&] { return run(o); });
}
