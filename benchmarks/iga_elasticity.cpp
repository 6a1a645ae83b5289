// iga-elasticity: plane linear elasticity −div σ(u) = b (plane strain or plane stress) with displacement conditions
// per component and tractions on named boundary parts; by default Kirsch's plate with a hole on the exact NURBS
// quarter plate. Thin: parses options and calls the library (pde/elasticity/input.hpp, io/problem_run.hpp).
#include <CLI/CLI.hpp>
#include <algorithm>
#include <cmath>
#include <iostream>
#include <nlohmann/json.hpp>

#include "core/error.hpp"
#include "fem/memory.hpp"
#include "fem/parallel.hpp"
#include "io/discretisation_options.hpp"
#include "io/problem_run.hpp"
#include "io/program.hpp"
#include "io/option_rules.hpp"
#include "io/report.hpp"
#include "io/vtk_file.hpp"
#include "io/vtu_output.hpp"
#include "pde/elasticity/input.hpp"

namespace {

struct Options {
  iga::io::ProblemProgram run{"iga-elasticity"};
  iga::pde::ElasticityInput input;
  std::string vtu = "result.vtu", json = "result.json", vtu_format = "bezier";
  int samples = 4, vtu_degree = 6, adaptive = -1;
};

int run(Options& o) {
  using namespace iga;
  if (o.adaptive >= 0) {
    throw UnsupportedError("--adaptive: elasticity has no error estimator yet (adaptive refinement is iga-poisson's); use --refine");
  }
  if (o.input.problem.empty() && o.input.body_force.empty() && o.input.exact.empty() && o.input.displacement.empty() &&
      o.input.traction.empty()) {
    o.input.problem = "kirsch";  // the default run
  }
  o.run.components = 2;
  const bool write_vtu = io::writes(o.vtu);
  io::VtuOutput vtu = io::VtuOutput::of(o.vtu_format, o.samples, o.vtu_degree);
  // 10 values per point
  if (write_vtu) o.run.output_bytes_per_element = 10.0 * fem::vtu_memory(1.0, vtu.points_per_direction());
  pde::Lame material;
  double nu_zz = 0.0;
  o.run.problem = [&](const basis::Geometry& geometry, const basis::BackendFacts&, nlohmann::json& report) {
    pde::ElasticityData data = pde::elasticity_data(o.input, geometry, report["problem"]);
    material = pde::lame(data.young, data.poisson, data.model);
    nu_zz = data.model == pde::PlaneModel::kStrain ? data.poisson : 0.0;
    return pde::make_elasticity(std::move(data));
  };
  if (write_vtu) o.run.output = [&](const basis::Geometry& geometry, const fem::ProblemResult& r, nlohmann::json& report) {
    // Displacement (a 3-vector for ParaView's Warp By Vector), stress (a symmetric tensor) and von Mises' stress.
    const auto field = [&](int which) { return pde::elasticity_sampler(geometry.space(), r.u, material, nu_zz, which); };
    vtu.fields = {{"displacement", 3, field(0)}, {"stress", 6, field(1)}, {"von_mises", 1, field(2)}};
    if (r.ranks > 1) vtu.pieces = {fem::rank(), r.ranks, r.element_owner};
    const std::vector<std::string> files = io::write_output(o.vtu, geometry, nullptr, vtu);
    report["vtu_output"] = vtu.settings();
    report["vtu"] = files[0];
    if (files.size() > 1) report["vtu_outline"] = files[1];
    if (!o.run.quiet) std::cerr << "iga-elasticity: wrote " << report["vtu"].get<std::string>() << std::endl;
  };
  o.run.json = o.json;
  o.run.output_paths = {o.vtu};
  io::run_problem_program(o.run);
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"iga-elasticity: plane linear elasticity −div σ(u) = b with isogeometric elements"};
  Options o;
  iga::io::add_discretisation_options(app, o.run.discretisation);
  app.add_option("--young", o.input.young, "Young's modulus E > 0")->check(iga::io::finite_number(0.0))->capture_default_str();
  app.add_option("--poisson-ratio", o.input.poisson, "Poisson's ratio ν in (−1, 0.5) (plane stress: (−1, 0.5])")->check(iga::io::finite_number(-1.0, 0.5))
      ->capture_default_str();
  app.add_option("--model", o.input.model, "strain (plane strain) or stress (plane stress)")
      ->check(CLI::IsMember({"strain", "stress"}))->capture_default_str();
  app.add_option("--problem", o.input.problem,
                 "built-in problem: kirsch (the infinite plate with a hole of radius 1 about the origin under tension "
                 "--tension along x, Kirsch's exact solution; default when no condition or expression is given)")
      ->check(CLI::IsMember(iga::pde::elasticity_problem_names()));
  app.add_option("--tension", o.input.tension, "--problem kirsch: the far-field tension T")->check(iga::io::finite_number(-INFINITY))
      ->capture_default_str();
  app.add_option("--body-force", o.input.body_force, "body force 'BX; BY' (expressions in x, y)")->check(iga::io::non_blank());
  app.add_option("--exact", o.input.exact, "exact displacement 'UX; UY': the error norms (L2, H1, energy) and the data conditions leave out")
      ->check(iga::io::non_blank());
  app.add_option("--displacement", o.input.displacement,
                 "'C; PARTS[; VALUE]': u_C = VALUE (default: --exact's component, else 0) on the comma-separated boundary "
                 "parts (bspline: v0,u1,v1,u0; cc: b<loop>.<segment>; or indices or all), C x or y; repeatable, one per component")
      ->check(iga::io::non_blank());
  app.add_option("--traction", o.input.traction,
                 "'PARTS[; TX; TY]': traction t = σn (expressions in x, y, nx, ny; default: --exact's) on the parts; "
                 "repeatable; parts without a condition are traction-free")
      ->check(iga::io::non_blank());
  app.add_option("--adaptive", o.adaptive, "not for elasticity yet (no error estimator): refused with a message")
      ->check(iga::io::whole_number(0, 200));
  iga::io::add_solver_options(app, o.run);
  iga::io::add_vtu_output_options(app, o.vtu, o.vtu_format, o.samples, o.vtu_degree, o.json,
                                  "displacement, stress (XX, YY, ZZ, XY, YZ, XZ), von_mises");
  if (const auto code = iga::io::parse_problem_program(app, argc, argv, o.run)) return *code;
  // Without --mesh and --geometry, a backend that has built-in geometries gives the plate with a hole.
  const auto& takes = iga::basis::backend(o.run.discretisation.basis).options;
  if (o.run.discretisation.mesh.empty() && !o.run.discretisation.count("geometry") &&
      std::find(takes.begin(), takes.end(), "geometry") != takes.end()) {
    o.run.discretisation.geometry = "plate-with-hole";
    o.run.discretisation.given.emplace_back("geometry");
  }
  return iga::io::run_solver_program("iga-elasticity", iga::io::solver_uses_petsc(o.run.solver, o.run.discretisation.basis), argv, o.run.quiet, o.run.threads,
                                     [&] { return run(o); });
}
