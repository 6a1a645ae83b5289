// bench-halfbox: how fast the half-box spline backend evaluates and assembles, beside Catmull–Clark measured in
// the same run. Reports, as JSON on stdout (or --json FILE):
//  - evaluation: points per second of batched calls (values + first derivatives, --points per call, random
//    points of the reference triangle / square, fixed seed) for half_box::evaluate_regular, evaluate_irregular(n)
//    for n = 3, 5, 7, 8, 12, and for Catmull–Clark's regular and extraordinary elements (CatmullClarkSpace on
//    square_evs.obj, as bench-cc-evaluator) and Stam's evaluator alone per valence; the time per point of each
//    EF valence relative to the regular patch (the goal: at most 2), median and range over --repeat rounds;
//  - poisson: fem::solve_poisson of the "sine" problem at about 10^5 elements, half-box on the dual net of
//    --tri-mesh (tri_square.obj, tiles:4:10) and Catmull–Clark on --quad-mesh (square_evs.obj, gauss:4):
//    dofs, elements, quadrature points, assembly and solve seconds, threads, L2 error.
// --quick: small sizes (the ctest).
#include <CLI/CLI.hpp>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <iostream>
#include <map>
#include <nlohmann/json.hpp>
#include <random>
#include <string>
#include <vector>

#include "basis/catmull_clark/space.hpp"
#include "basis/catmull_clark/stam.hpp"
#include "basis/half_box/irregular_patch.hpp"
#include "basis/half_box/regular_patch.hpp"
#include "basis/registry.hpp"
#include "fem/poisson.hpp"
#include "fem/problems.hpp"
#include "fem/threads.hpp"
#include "io/program.hpp"
#include "io/report.hpp"
#include "mesh/obj_reader.hpp"
#include "mesh/three_valent.hpp"
#include "quadrature/rule_provider.hpp"

namespace {
using Clock = std::chrono::steady_clock;
using iga::Index;

struct Options {
  std::string json, tri_mesh = "data/meshes/tri_square.obj", quad_mesh = "data/meshes/square_evs.obj";
  bool quick = false, quiet = false;
  long calls = 50000;   ///< calls per evaluation measurement
  int points = 64;      ///< points per call
  int repeat = 5;       ///< runs per evaluation measurement (the fastest is reported)
  int halfbox_refine = 5, cc_refine = 5, threads = 0;
  unsigned seed = 20261201;
};

// Points per second of f(call) over `calls` calls with `q` points each, the fastest of `repeat` runs (the
// machine is shared: the fastest run is the one least disturbed).
template <class F>
double rate(F&& f, long calls, long q, int repeat) {
  double best = 0;
  for (int r = 0; r < repeat; ++r) {
    const auto t0 = Clock::now();
    for (long c = 0; c < calls; ++c) f(c);
    const double s = std::chrono::duration<double>(Clock::now() - t0).count();
    best = std::max(best, static_cast<double>(calls * q) / s);
  }
  return best;
}

// `count` batches of q uniform random points of the reference triangle (triangle = true: {u, v >= 0,
// u + v <= 1}, the square's points reflected at u + v = 1) or of [0,1]².
std::vector<Eigen::Matrix2Xd> random_batches(int count, int q, bool triangle, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> d(0.0, 1.0);
  std::vector<Eigen::Matrix2Xd> out(static_cast<std::size_t>(count), Eigen::Matrix2Xd(2, q));
  for (auto& b : out) {
    for (int p = 0; p < q; ++p) {
      double u = d(rng), v = d(rng);
      if (triangle && u + v > 1.0) {
        u = 1.0 - u;
        v = 1.0 - v;
      }
      b(0, p) = u;
      b(1, p) = v;
    }
  }
  return out;
}

constexpr int kBatches = 64;  // distinct point batches, cycled through
const int kValences[] = {3, 5, 7, 8, 12};

// Regular and EF patches measured in turns (regular, then each valence, `repeat` rounds), so that the ratio of
// each round compares runs seconds apart on the shared machine; rates are the fastest round, ratios the median
// round.
nlohmann::json half_box_evaluation(const Options& o) {
  using namespace iga::basis;
  const auto pts = random_batches(kBatches, o.points, true, o.seed);
  auto batch = [&](long c) -> const Eigen::Matrix2Xd& { return pts[static_cast<std::size_t>(c % kBatches)]; };
  BasisValues out;
  for (int n : kValences) half_box::evaluate_irregular(n, batch(0), 1, out);  // build the cached structures
  std::vector<double> regular;
  std::map<int, std::vector<double>> ef, ratio;
  for (int r = 0; r < o.repeat; ++r) {
    regular.push_back(rate([&](long c) { half_box::evaluate_regular(batch(c), 1, out); }, o.calls, o.points, 1));
    for (int n : kValences) {
      ef[n].push_back(rate([&](long c) { half_box::evaluate_irregular(n, batch(c), 1, out); }, o.calls, o.points, 1));
      ratio[n].push_back(regular.back() / ef[n].back());
    }
  }
  auto best = [](const std::vector<double>& v) { return *std::max_element(v.begin(), v.end()); };
  auto median = [](std::vector<double> v) {
    std::sort(v.begin(), v.end());
    const std::size_t m = v.size() / 2;
    return v.size() % 2 ? v[m] : 0.5 * (v[m - 1] + v[m]);
  };
  nlohmann::json j;
  j["regular"] = best(regular);
  for (int n : kValences) {
    j["irregular"][std::to_string(n)] = best(ef[n]);
    j["ef_time_over_regular"][std::to_string(n)] = median(ratio[n]);
    j["ef_time_over_regular_range"][std::to_string(n)] = {*std::min_element(ratio[n].begin(), ratio[n].end()),
                                                          best(ratio[n])};
  }
  return j;
}

nlohmann::json cc_evaluation(const Options& o) {
  using namespace iga::basis;
  const auto pts = random_batches(kBatches, o.points, false, o.seed + 1);
  auto batch = [&](long c) -> const Eigen::Matrix2Xd& { return pts[static_cast<std::size_t>(c % kBatches)]; };
  BasisValues out;
  nlohmann::json j;
  for (int n : kValences) {
    const auto& stam = catmull_clark::stam_evaluator(n);
    j["stam"][std::to_string(n)] = rate([&](long c) { stam.evaluate(batch(c), 1, out); }, o.calls, o.points, o.repeat);
  }
  const std::string& mesh = o.quad_mesh;
  const catmull_clark::CatmullClarkSpace space(iga::mesh::read_obj(mesh), mesh, catmull_clark::IrregularMethod::kStam);
  std::vector<Index> irregular, regular;
  for (Index e = 0; e < space.num_elements(); ++e) {
    (space.kind(e).family == Family::Irregular ? irregular : regular).push_back(e);
  }
  auto element_rate = [&](const std::vector<Index>& elements) {
    return rate([&](long c) { space.evaluate(elements[static_cast<std::size_t>(c) % elements.size()], batch(c), 1, out); },
                o.calls, o.points, o.repeat);
  };
  j["regular_element"] = element_rate(regular);
  j["ev_element"] = element_rate(irregular);
  j["ev_time_over_regular"] = j["regular_element"].get<double>() / j["ev_element"].get<double>();
  j["mesh"] = mesh;
  return j;
}

// fem::solve_poisson of the sine problem on `net` refined `steps` times by the backend.
nlohmann::json poisson(const std::string& basis, const iga::mesh::PolyMesh& net, int steps, const std::string& quadrature) {
  using namespace iga;
  basis::BackendFacts facts;
  const auto t0 = Clock::now();
  const basis::Refinement refined = basis::make_refined_geometry(basis::backend(basis), &net, {}, steps, facts);
  const double build = std::chrono::duration<double>(Clock::now() - t0).count();
  const fem::ManufacturedProblem mp = fem::manufactured_problem("sine");
  fem::PoissonProblem problem;
  problem.source = mp.source;
  problem.exact = mp.exact;
  problem.dirichlet = mp.exact;
  const auto rules = quadrature::make_rule_provider(quadrature, 4);
  const fem::PoissonResult r = fem::solve_poisson(refined.geometry, *rules, problem);
  nlohmann::json j = {{"basis", basis}, {"refine", steps}, {"quadrature", rules->name()}, {"dofs", r.dofs},
                      {"elements", r.elements}, {"quadrature_points", r.quadrature_points},
                      {"build_seconds", build}, {"pattern_seconds", r.pattern_seconds},
                      {"assembly_seconds", r.assembly_seconds}, {"solve_seconds", r.solve_seconds},
                      {"solver", r.solver}, {"threads", fem::num_threads()}, {"domain_measure", r.domain_measure}};
  if (r.errors) j["l2_error"] = r.errors->l2;
  return j;
}

int run(const Options& o) {
  using namespace iga;
  auto log = [&](const std::string& s) {
    if (!o.quiet) std::cerr << "bench-halfbox: " << s << std::endl;
  };
  if (o.threads > 0) fem::set_num_threads(o.threads);
  nlohmann::json report = {{"program", "bench-halfbox"}, {"quick", o.quick}, {"points_per_call", o.points},
                           {"calls", o.calls}, {"repeat", o.repeat}, {"derivatives", 1}, {"seed", o.seed}};
  log("half-box evaluation (" + std::to_string(o.calls) + " calls of " + std::to_string(o.points) + " points each)");
  report["halfbox_points_per_second"] = half_box_evaluation(o);
  log("Catmull–Clark evaluation");
  report["cc_points_per_second"] = cc_evaluation(o);
  bool within = true;
  for (const auto& [n, ratio] : report["halfbox_points_per_second"]["ef_time_over_regular"].items()) {
    within = within && ratio.get<double>() <= 2.0;
  }
  report["ef_within_2x_of_regular"] = within;

  const std::string &tri = o.tri_mesh, &quads = o.quad_mesh;
  log("half-box Poisson: dual of " + tri + ", " + std::to_string(o.halfbox_refine) + " refinement(s)");
  report["poisson"]["halfbox"] = poisson("halfbox", mesh::dual_net(mesh::read_obj(tri)), o.halfbox_refine, "tiles:4:10");
  report["poisson"]["halfbox"]["mesh"] = "dual of " + tri;
  log("Catmull–Clark Poisson: " + quads + ", " + std::to_string(o.cc_refine) + " refinement(s)");
  report["poisson"]["cc"] = poisson("cc", mesh::read_obj(quads), o.cc_refine, "gauss:4");
  report["poisson"]["cc"]["mesh"] = quads;
  std::cout << report.dump(2) << std::endl;
  if (!o.json.empty()) io::write_json(o.json, report);
  return 0;
}
}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"bench-halfbox: evaluation and Poisson assembly speed of half-box splines beside Catmull–Clark"};
  Options o;
  app.add_flag("--quick", o.quick, "small sizes: 2000 calls, 1 run, half-box refine 1, Catmull–Clark refine 1");
  app.add_option("--calls", o.calls, "calls per evaluation measurement")
      ->check(CLI::Range(1L, 1000000000L))->capture_default_str();
  app.add_option("--repeat", o.repeat, "rounds per evaluation measurement: the fastest rate and the median EF/regular time ratio are reported")
      ->check(CLI::Range(1, 100))->capture_default_str();
  app.add_option("--points", o.points, "points per call")->check(CLI::Range(1, 100000))->capture_default_str();
  app.add_option("--halfbox-refine", o.halfbox_refine, "refinements of the dual of tri_square.obj (128 · 4^K elements)")
      ->check(CLI::Range(0, 8))->capture_default_str();
  app.add_option("--cc-refine", o.cc_refine, "refinements of square_evs.obj (144 · 4^K elements)")
      ->check(CLI::Range(0, 8))->capture_default_str();
  app.add_option("--threads", o.threads, "threads for assembly (default: OpenMP's)")->check(iga::io::thread_count());
  app.add_option("--seed", o.seed, "seed of the random evaluation points")->capture_default_str();
  app.add_option("--tri-mesh", o.tri_mesh, "triangle mesh whose dual net the half-box Poisson run uses")
      ->check(CLI::ExistingFile)->capture_default_str();
  app.add_option("--quad-mesh", o.quad_mesh, "Catmull–Clark net of the evaluation and Poisson runs")
      ->check(CLI::ExistingFile)->capture_default_str();
  app.add_option("--json", o.json, "write the report here too");
  app.add_flag("--quiet", o.quiet, "no progress on stderr");
  CLI11_PARSE(app, argc, argv);
  if (o.quick) {
    if (app.count("--calls") == 0) o.calls = 2000;
    if (app.count("--repeat") == 0) o.repeat = 1;
    if (app.count("--halfbox-refine") == 0) o.halfbox_refine = 1;
    if (app.count("--cc-refine") == 0) o.cc_refine = 1;
  }
  try {
    return run(o);
  } catch (const std::exception& e) {
    std::cerr << "bench-halfbox: error: " << e.what() << std::endl;
    return 1;
  }
}
