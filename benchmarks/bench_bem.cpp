// bench-bem: collocation BEM costs and conditioning versus the number of boundary dofs (benchmarks/README.md):
// assembly seconds per million matrix entries (H and G), LU and GMRES solve seconds, the condition estimate
// versus h for each degree, and the flux error, on the boundary of a geometry iga-bem takes.
#include <CLI/CLI.hpp>
#include <cstdio>
#include <iostream>
#include <nlohmann/json.hpp>
#include <optional>

#include "basis/curve/trace_space.hpp"
#include "basis/registry.hpp"
#include "bem/errors.hpp"
#include "bem/solve.hpp"
#include "core/error.hpp"
#include "fem/expression.hpp"
#include "fem/threads.hpp"
#include "io/program.hpp"
#include "io/report.hpp"
#include "mesh/obj_reader.hpp"

namespace {

using namespace iga;

struct Options {
  std::string mesh, basis = "bspline", exact = "exp(x)*cos(y)", json = "bench_bem.json";
  std::vector<int> degrees{2, 3, 4};
  int max_refine = 6, threads = 0;
  long long max_dofs = 2000, lu_max = 12000;
};

nlohmann::json one_case(const basis::CurveGeometry& curve, int p, int k, const Options& o,
                        const std::shared_ptr<const fem::Function>& exact, bool& stop) {
  bem::DiscretizationOptions d_opt;
  d_opt.degree = p;
  d_opt.refine = k;
  const bem::BoundaryDiscretization d(curve, std::vector<int>(static_cast<std::size_t>(curve.num_elements()), bem::kDirichlet), d_opt);
  const Index n = d.num_dofs();
  if (n > o.max_dofs) {
    stop = true;
    return nullptr;
  }
  const bem::Problem problem{exact, nullptr, exact};
  nlohmann::json row = {{"degree", p}, {"refine", k}, {"dofs", n}, {"elements", d.num_elements()}};
  double h = 0.0;  // largest BEM element length
  for (Index e = 0; e < d.num_elements(); ++e) {
    const bem::BemElement& b = d.element(e);
    h = std::max(h, curve.length(b.curve_element) * (b.b - b.a));
  }
  row["h"] = h;
  bem::SolveOptions so;
  if (n <= o.lu_max) {
    so.solver = bem::SolveOptions::Solver::LU;
    const bem::Solution s = bem::solve(d, problem, so);
    const double entries = 2.0 * static_cast<double>(n) * static_cast<double>(n);
    row["assembly_seconds"] = s.assembly_seconds;
    row["assembly_seconds_per_million_entries"] = s.assembly_seconds / (entries / 1e6);
    row["lu_seconds"] = s.solve_seconds;
    row["condition_estimate"] = s.condition_estimate;
    row["flux_l2_error"] = bem::flux_l2_error(d, s, *exact);
  }
  so.solver = bem::SolveOptions::Solver::GMRES;
  const bem::Solution g = bem::solve(d, problem, so);
  row["gmres_seconds"] = g.solve_seconds;
  row["gmres_iterations"] = g.gmres_iterations;
  if (!row.contains("assembly_seconds")) {
    row["assembly_seconds"] = g.assembly_seconds;
    row["assembly_seconds_per_million_entries"] = g.assembly_seconds / (2.0 * static_cast<double>(n) * static_cast<double>(n) / 1e6);
    row["flux_l2_error"] = bem::flux_l2_error(d, g, *exact);
  }
  return row;
}

int run(const Options& o) {
  if (o.threads > 0) fem::set_num_threads(o.threads);
  const basis::Backend& backend = basis::backend(o.basis);
  std::optional<mesh::PolyMesh> net;
  if (!o.mesh.empty()) net = mesh::read_obj(o.mesh);
  basis::BackendFacts facts;
  basis::BackendOptions bo;
  bo.net_name = o.mesh;
  const basis::Geometry geometry = basis::make_geometry(backend, net ? &*net : nullptr, bo, facts);
  const basis::BoundaryTrace trace = basis::trace_geometry(geometry);
  const auto exact = std::make_shared<fem::Expression>(o.exact, "--exact");
  nlohmann::json j = {{"program", "bench-bem"}, {"basis", o.basis}, {"mesh", o.mesh.empty() ? "default" : o.mesh},
                      {"exact", o.exact}, {"threads", fem::num_threads()}, {"curve_elements", trace.curve.num_elements()}};
  std::printf("| p | refine | dofs | h | assembly s | s / 1e6 entries | LU s | GMRES s (its) | condition | flux L2 error |\n");
  std::printf("|---|---|---|---|---|---|---|---|---|---|\n");
  for (int p : o.degrees) {
    for (int k = 0; k <= o.max_refine; ++k) {
      bool stop = false;
      const nlohmann::json row = one_case(trace.curve, p, k, o, exact, stop);
      if (stop) break;
      j["rows"].push_back(row);
      auto num = [&](const char* key) { return row.contains(key) ? row[key].get<double>() : std::nan(""); };
      std::printf("| %d | %d | %lld | %.3g | %.3g | %.3g | %.3g | %.3g (%d) | %.3g | %.3g |\n", p, k,
                  row["dofs"].get<long long>(), num("h"), num("assembly_seconds"),
                  num("assembly_seconds_per_million_entries"), num("lu_seconds"), num("gmres_seconds"),
                  row["gmres_iterations"].get<int>(), num("condition_estimate"), num("flux_l2_error"));
      std::fflush(stdout);
    }
  }
  if (o.json != "none") io::write_json(o.json, j);
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"bench-bem: collocation BEM assembly, LU/GMRES solve and condition number versus boundary dofs"};
  Options o;
  app.add_option("--mesh", o.mesh, "control net (default: the backend's embedded geometry)")->check(CLI::ExistingFile);
  app.add_option("--basis", o.basis, "geometry backend")->capture_default_str();
  app.add_option("--degrees", o.degrees, "BEM spline degrees")->capture_default_str();
  app.add_option("--max-refine", o.max_refine, "largest --refine (each curve element split into 2^K)")->check(CLI::Range(0, 16))->capture_default_str();
  app.add_option("--max-dofs", o.max_dofs, "stop a degree's sweep above this many dofs")->capture_default_str();
  app.add_option("--lu-max", o.lu_max, "LU (and the condition estimate) only up to this many dofs")->capture_default_str();
  app.add_option("--exact", o.exact, "harmonic u for the Dirichlet data and the flux error")->capture_default_str();
  app.add_option("--threads", o.threads, "threads (default: OpenMP's)")->check(iga::io::thread_count());
  app.add_option("--json", o.json, "JSON report ('none' to skip)")->capture_default_str();
  CLI11_PARSE(app, argc, argv);
  try {
    return run(o);
  } catch (const std::exception& e) {
    std::cerr << "bench-bem: error: " << e.what() << std::endl;
    return 1;
  }
}
