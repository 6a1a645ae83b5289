// iga-biharmonic: the biharmonic equation Δ²u = f on planar domains (a Kirchhoff plate's D Δ²w = q with f = q/D),
// u given on the whole boundary, each boundary part clamped (∂u/∂n given) or simply supported (Δu given), on any
// space in H². Thin: parses options and calls the library (pde/biharmonic/input.hpp, io/problem_run.hpp).
#include <CLI/CLI.hpp>
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
#include "io/vtu_output.hpp"
#include "pde/biharmonic/input.hpp"

namespace {

struct Options {
  iga::io::ProblemProgram run{"iga-biharmonic"};
  iga::pde::BiharmonicInput input;
  std::string vtu = "result.vtu", json = "result.json", vtu_format = "bezier";
  int samples = 4, vtu_degree = 6, adaptive = -1;
};

int run(Options& o) {
  using namespace iga;
  if (o.adaptive >= 0) {
    throw UnsupportedError("--adaptive: the biharmonic equation has no error estimator yet (adaptive refinement is "
                           "iga-poisson's); use --refine");
  }
  const bool write_vtu = io::writes(o.vtu);
  io::VtuOutput vtu = io::VtuOutput::of(o.vtu_format, o.samples, o.vtu_degree);
  if (write_vtu) o.run.output_bytes_per_element = fem::vtu_memory(1.0, vtu.points_per_direction());
  std::shared_ptr<const fem::Function> exact;
  o.run.problem = [&](const basis::Geometry& geometry, const basis::BackendFacts&, nlohmann::json& report) {
    pde::BiharmonicData data = pde::biharmonic_data(o.input, geometry, report["problem"]);
    exact = data.exact;
    return pde::make_biharmonic(std::move(data));
  };
  if (write_vtu) o.run.output = [&](const basis::Geometry& geometry, const fem::ProblemResult& r, nlohmann::json& report) {
    vtu.exact = exact;
    if (r.ranks > 1) vtu.pieces = {fem::rank(), r.ranks, r.element_owner};
    const std::vector<std::string> files = io::write_output(o.vtu, geometry, &r.u, vtu);
    report["vtu_output"] = vtu.settings();
    report["vtu"] = files[0];
    if (files.size() > 1) report["vtu_outline"] = files[1];
    for (const std::string& f : files) {
      if (!o.run.quiet) std::cerr << "iga-biharmonic: wrote " << f << std::endl;
    }
  };
  o.run.json = o.json;
  o.run.output_paths = {o.vtu};
  io::run_problem_program(o.run);
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"iga-biharmonic: solve the biharmonic equation Δ²u = f (Kirchhoff plates) with C1 isogeometric elements"};
  Options o;
  iga::io::add_discretisation_options(app, o.run.discretisation);
  std::string names;
  for (const auto& n : iga::pde::biharmonic_problem_names()) names += (names.empty() ? "" : ", ") + n;
  app.add_option("--problem", o.input.problem,
                 "built-in problem (" + names + "): sine u = sin(πx) sin(πy) with its boundary data; plate f = 1, u = 0, "
                 "∂u/∂n = 0 or Δu = 0; default sine when no --source/--exact")
      ->check(CLI::IsMember(iga::pde::biharmonic_problem_names()));
  app.add_option("--source", o.input.source, "f(x,y) in Δ²u = f (muparser expression)")->check(iga::io::non_blank());
  app.add_option("--exact", o.input.exact, "exact solution u(x,y): the boundary data (unless given) and the error norms L2, H1, H2, Laplacian")
      ->check(iga::io::non_blank());
  app.add_option("--value", o.input.value, "u on the whole boundary, g(x,y); default: --exact, else 0")->check(iga::io::non_blank());
  app.add_option("--slope", o.input.slope, "∂u/∂n (outward) on the clamped parts, h(x,y,nx,ny); default: from --exact, else 0")
      ->check(iga::io::non_blank());
  app.add_option("--moment", o.input.moment, "Δu on the simply supported parts, m(x,y); default: from --exact, else 0")
      ->check(iga::io::non_blank());
  app.add_option("--simply-supported", o.input.simply_supported,
                 "boundary parts that are simply supported (u and Δu given), comma-separated names (bspline: v0,u1,v1,u0; "
                 "cc: b<loop>.<segment>), indices, or all; the others are clamped (u and ∂u/∂n given)")
      ->check(iga::io::non_blank());
  app.add_option("--nitsche-penalty", o.input.nitsche_penalty,
                 "the clamped condition's Nitsche penalty γ in γ/h (h the side length); 0: each element's own from its local "
                 "eigenvalue estimate (coercive by construction)")
      ->check(iga::io::finite_number(0.0))->capture_default_str();
  app.add_option("--adaptive", o.adaptive, "not for this equation yet (no error estimator): refused with a message")
      ->check(iga::io::whole_number(0, 200));
  iga::io::add_solver_options(app, o.run);
  iga::io::add_vtu_output_options(app, o.vtu, o.vtu_format, o.samples, o.vtu_degree, o.json);
  if (const auto code = iga::io::parse_problem_program(app, argc, argv, o.run)) return *code;
  return iga::io::run_solver_program("iga-biharmonic", iga::io::solver_uses_petsc(o.run.solver, o.run.discretisation.basis), argv, o.run.quiet, o.run.threads,
                                     [&] { return run(o); });
}
