// iga-shell: the linear Kirchhoff–Love shell on a surface in 3D (a NURBS patch file, a built-in surface, or a net of
// any surface backend), with loads and supports by boundary part and point; by default Scordelis and Lo's roof. A
// model is naturally a --config file of these options. Thin: parses options and calls the library
// (pde/shell/input.hpp, io/problem_run.hpp).
#include <CLI/CLI.hpp>
#include <algorithm>
#include <cmath>
#include <iostream>
#include <nlohmann/json.hpp>

#include "basis/locate.hpp"
#include "core/error.hpp"
#include "fem/memory.hpp"
#include "fem/parallel.hpp"
#include "io/discretisation_options.hpp"
#include "io/option_rules.hpp"
#include "io/problem_run.hpp"
#include "io/program.hpp"
#include "io/report.hpp"
#include "io/vtk_file.hpp"
#include "io/vtu_output.hpp"
#include "pde/shell/input.hpp"
#include "pde/shell/output.hpp"

namespace {

struct Options {
  iga::io::ProblemProgram run{"iga-shell"};
  iga::pde::ShellInput input;
  std::string vtu = "result.vtu", json = "result.json", vtu_format = "bezier";
  int samples = 4, vtu_degree = 6, adaptive = -1;
};

// The displacement at each point of the set-up, with its reference where there is one, into report["points"].
nlohmann::json point_report(const iga::basis::Geometry& geometry, const Eigen::VectorXd& u,
                            const std::vector<iga::pde::ShellPoint>& points,
                            const std::vector<iga::basis::LocatedPoint>& located, const std::string& program, bool quiet) {
  nlohmann::json out = nlohmann::json::array();
  for (std::size_t k = 0; k < points.size(); ++k) {
    const iga::pde::ShellPoint& p = points[k];
    const Eigen::Vector3d d = iga::pde::shell_displacement(geometry.space(), u, located[k].element, located[k].uv);
    nlohmann::json j = {{"name", p.name}, {"at", {p.at(0), p.at(1), p.at(2)}}, {"element", located[k].element},
                        {"distance_from_surface", located[k].distance}, {"displacement", {d(0), d(1), d(2)}}};
    std::ostringstream line;
    line << program << ": " << p.name << ": displacement (" << d(0) << ", " << d(1) << ", " << d(2) << ")";
    if (p.component >= 0) {
      const double ratio = d(p.component) / p.reference;
      j["reference"] = {{"component", std::string(1, "xyz"[p.component])}, {"value", p.reference}, {"source", p.source},
                        {"relative_difference", ratio - 1}};
      line << ", " << "xyz"[p.component] << " against the reference " << p.reference << ": " << 100 * (ratio - 1) << " %";
    }
    if (!quiet && iga::fem::rank() == 0) std::cerr << line.str() << std::endl;
    out.push_back(j);
  }
  return out;
}

int run(Options& o) {
  using namespace iga;
  if (o.adaptive >= 0) {
    throw UnsupportedError("--adaptive: the shell has no error estimator yet (adaptive refinement is iga-poisson's); use --refine");
  }
  o.run.components = 3;
  const bool write_vtu = io::writes(o.vtu);
  io::VtuOutput vtu = io::VtuOutput::of(o.vtu_format, o.samples, o.vtu_degree);
  // 17 values per point
  if (write_vtu) o.run.output_bytes_per_element = 17.0 * fem::vtu_memory(1.0, vtu.points_per_direction());
  pde::ShellSetUp setup;
  std::vector<basis::LocatedPoint> located;
  o.run.problem = [&](const basis::Geometry& geometry, const basis::BackendFacts& facts, nlohmann::json& report) {
    setup = pde::shell_setup(o.input, geometry, report["problem"]);
    // Points given on the shape a net was fitted to lie up to the fit's distance from the net's surface (sampled:
    // twice it is allowed); the report gives each point's distance.
    setup.data.point_allowance = std::max(0.0, 2 * facts.fit_distance);
    for (const pde::ShellPoint& p : setup.points) {
      located.push_back(basis::locate_point(geometry, p.at, "--point " + p.name, 1e-6, setup.data.point_allowance));
    }
    return pde::make_shell(setup.data);
  };
  o.run.output = [&](const basis::Geometry& geometry, const fem::ProblemResult& r, nlohmann::json& report) {
    // The shell's warnings (not thin against its curvature or its elements) are in the log; with --quiet, alone.
    for (const auto& [what, how] : r.choices) {
      if (o.run.quiet && what.rfind("warning", 0) == 0 && fem::rank() == 0) std::cerr << "iga-shell: " << what << ": " << how << std::endl;
    }
    report["points"] = point_report(geometry, r.u, setup.points, located, "iga-shell", o.run.quiet);
    if (!write_vtu) return;
    const auto field = [&](int which) { return pde::shell_sampler(geometry.space(), r.u, setup.data.material, which); };
    vtu.fields = {{"displacement", 3, field(0), 2}, {"membrane_forces", 6, field(1), 2},
                  {"bending_moments", 6, field(2), 2}, {"von_mises_top_bottom", 2, field(3), 2}};
    if (r.ranks > 1) vtu.pieces = {fem::rank(), r.ranks, r.element_owner};
    const std::vector<std::string> files = io::write_output(o.vtu, geometry, nullptr, vtu);
    report["vtu_output"] = vtu.settings();
    report["vtu"] = files[0];
    if (files.size() > 1) report["vtu_outline"] = files[1];
    if (!o.run.quiet) std::cerr << "iga-shell: wrote " << report["vtu"].get<std::string>() << std::endl;
  };
  o.run.json = o.json;
  o.run.output_paths = {o.vtu};
  io::run_problem_program(o.run);
  return 0;
}

void add_shell_options(CLI::App& app, iga::pde::ShellInput& in) {
  const auto finite = iga::io::finite_number(-INFINITY);
  app.add_option("--young", in.young, "Young's modulus E > 0 (default: the --problem's)")->check(finite);
  app.add_option("--poisson-ratio", in.poisson, "Poisson's ratio ν in (−1, 0.5] (default: the --problem's, else 0.3)")
      ->check(finite);
  app.add_option("--thickness", in.thickness, "the shell's thickness t > 0 (default: the --problem's)")->check(finite);
  app.add_option("--problem", in.problem,
                 "the shell obstacle course (README): scordelis-lo-roof (default without loads), pinched-cylinder, "
                 "pinched-hemisphere, on the built-in geometries of the same names; items given besides are added (an "
                 "--area-load replaces its own), and the reference values are then not reported")
      ->check(CLI::IsMember(iga::pde::shell_problem_names()));
  app.add_option("--area-load", in.area_load, "load per unit area 'FX; FY; FZ' (expressions in x, y, z)")
      ->check(iga::io::non_blank());
  app.add_option("--pressure", in.pressure, "pressure along the unit normal (an expression in x, y, z)")
      ->check(iga::io::non_blank());
  app.add_option("--line-load", in.line_load, "'PARTS; QX; QY; QZ': load per unit length on boundary parts; repeatable")
      ->check(iga::io::non_blank());
  app.add_option("--support", in.support,
                 "'C; PARTS[; HOLD]': hold component C (x, y, z) on the parts (bspline: v0,u1,v1,u0; cc: b<loop>.<segment>; "
                 "or indices or all): HOLD value (u_C = 0, default), slope (∂u_C/∂n = 0) or value+slope; repeatable")
      ->check(iga::io::non_blank());
  app.add_option("--symmetry", in.symmetry,
                 "'AXIS; PARTS': the parts lie on a symmetry plane normal to AXIS (u_AXIS = 0, the other components' "
                 "slopes 0); repeatable")
      ->check(iga::io::non_blank());
  app.add_option("--clamped", in.clamped, "'PARTS': clamped (all components and their slopes held); repeatable")
      ->check(iga::io::non_blank());
  app.add_option("--point-load", in.point_load, "'X, Y, Z; FX, FY, FZ': a force at a point of the surface; repeatable")
      ->check(iga::io::non_blank());
  app.add_option("--point-support", in.point_support, "'X, Y, Z; C': u_C = 0 at a point of the surface; repeatable")
      ->check(iga::io::non_blank());
  app.add_option("--point", in.point, "'NAME; X, Y, Z': report the displacement at a point of the surface; repeatable")
      ->check(iga::io::non_blank());
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"iga-shell: the linear Kirchhoff–Love shell with isogeometric elements, no rotational dofs"};
  Options o;
  iga::io::add_discretisation_options(app, o.run.discretisation);
  add_shell_options(app, o.input);
  app.add_option("--adaptive", o.adaptive, "not for shells yet (no error estimator): refused with a message")
      ->check(iga::io::whole_number(0, 200));
  iga::io::add_solver_options(app, o.run);
  iga::io::add_vtu_output_options(app, o.vtu, o.vtu_format, o.samples, o.vtu_degree, o.json,
                                  "displacement, membrane_forces and bending_moments (per unit length, XX, YY, ZZ, "
                                  "XY, YZ, XZ), von_mises_top_bottom");
  if (const auto code = iga::io::parse_problem_program(app, argc, argv, o.run)) return *code;
  // Without loads, the default problem; a problem without --mesh and --geometry is posed on its own surface.
  const iga::pde::ShellInput& in = o.input;
  if (in.problem.empty() && in.area_load.empty() && in.pressure.empty() && in.line_load.empty() && in.point_load.empty()) {
    o.input.problem = "scordelis-lo-roof";
  }
  const auto& takes = iga::basis::backend(o.run.discretisation.basis).options;
  if (!o.input.problem.empty() && o.run.discretisation.mesh.empty() && !o.run.discretisation.count("geometry") &&
      std::find(takes.begin(), takes.end(), "geometry") != takes.end()) {
    o.run.discretisation.geometry = iga::pde::shell_problem_geometry(o.input.problem);
    o.run.discretisation.given.emplace_back("geometry");
  }
  return iga::io::run_solver_program("iga-shell", iga::io::solver_uses_petsc(o.run.solver, o.run.discretisation.basis),
                                     argv, o.run.quiet, o.run.threads, [&] { return run(o); });
}
