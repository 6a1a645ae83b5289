#pragma once
// The command-line options of a solver program's discretisation (io/discretisation.hpp), the same words in every
// program: --mesh, --basis, --degree, --refine, --refine-intervals, --coarse-split, --geometry, --cc-boundary, --cc-enrich,
// --cc-corners, --grade-evs, --presubdivide, --fit-to, --quadrature; and a PDE program's solver options. Header-only: programs link CLI11 themselves (io/program.hpp).
#include <CLI/CLI.hpp>

#include <optional>
#include <string>
#include <vector>

#include "io/discretisation.hpp"
#include "io/problem_run.hpp"
#include "io/option_rules.hpp"
#include "io/program.hpp"
#include "io/vtu_output.hpp"

namespace iga::io {

/// Adds the options to app, writing into o.
inline void add_discretisation_options(CLI::App& app, DiscretisationOptions& o) {
  app.add_option("--mesh", o.mesh, "Wavefront OBJ control net (a quad grid for bspline); default: the backend's built-in geometry")
      ->check(input_file());
  std::vector<std::string> backend_list;
  std::string backend_help = "basis backend:";
  for (const auto& b : basis::backends()) {
    backend_list.push_back(b.name);
    backend_help += " " + b.name + " (" + b.description + ");";
  }
  app.add_option("--basis", o.basis, backend_help)->check(CLI::IsMember(backend_list))->capture_default_str();
  app.add_option("--degree", o.degree, "polynomial degree per direction (bspline; cc is bicubic)")
      ->check(whole_number(1, 12))->capture_default_str();
  app.add_option("--refine-intervals", o.refine_intervals,
                 "bspline: each refinement step halves only these non-empty knot intervals (0-based, comma-separated, both directions)")
      ->check(non_blank());
  app.add_option("--coarse-split", o.coarse_split,
                 "bspline: U,V: before refining, split every knot interval of the patch into U equal parts along u and V "
                 "along v (knot insertion: the same geometry on a coarse mesh of chosen aspect ratio; e.g. 1,3 makes "
                 "the quarter annulus's elements about square)")
      ->check(non_blank());
  app.add_option("--refine", o.refine,
                 "uniform refinement steps, each splitting every element in four (default: 4 for bspline, 1 for cc, 0 for "
                 "polyhedral, where each step is a Catmull–Clark step of the net)")
      ->check(whole_number(0, 14));
  app.add_option("--geometry", o.geometry,
                 "bspline without --mesh: the built-in geometry, quarter-annulus (default, exact: NURBS), l-shape ([0,2]^2 "
                 "minus (1,2]^2, one patch with a C0 line from the reflex corner), square (the unit square), "
                 "plate-with-hole ([0,4]^2 minus the disc r < 1, exact: NURBS), the shell surfaces scordelis-lo-roof, "
                 "pinched-cylinder (an octant), pinched-hemisphere (a quarter; exact: NURBS; iga-shell), or a patch file "
                 "FILE.json (README, Patch files)")
      ->check(non_blank());
  app.add_option("--cc-boundary", o.cc_boundary,
                 "cc: natural (the limit boundary rule of OpenSubdiv: u_nn = 0 on the boundary, L2 rate 2.5) or clamped (one "
                 "ring of ghost control points: open knot vector in the normal direction, full order; it brings "
                 "--grade-evs by default, and in iga-poisson Nitsche's method)")
      ->check(CLI::IsMember({"natural", "clamped"}))->capture_default_str();
  app.add_option("--cc-enrich", o.cc_enrich,
                 "cc: none or quadratic (three functions per extraordinary vertex, quadratics in the physical coordinates "
                 "times a C7 cutoff, valence 5 and more and boundary EVs: restores the rates of the regular parts; uniform "
                 "refinement only)")
      ->check(CLI::IsMember({"none", "quadratic"}))->capture_default_str();
  app.add_option("--cc-corners", o.cc_corners,
                 "cc with --cc-boundary clamped: net vertices (numbered from 1 as in the OBJ's f lines, comma-separated) the "
                 "limit domain keeps as true corners: its boundary passes through each with the directions of the vertex's "
                 "two boundary edges (e.g. an L-shape's reflex corner); vertices with two or more faces")
      ->check(non_blank());
  app.add_option("--grade-evs", o.grade_evs,
                 "cc: after --refine, refine the elements at extraordinary vertices N more times (hierarchical, with the "
                 "neighbours admissibility class 2 needs): a priori grading toward the vertices, one solve; default: "
                 "--refine + 3 with --cc-boundary clamped (0: none; none with --cc-enrich quadratic, --adaptive, or on nets "
                 "without extraordinary vertices)")
      ->check(whole_number(0, 40));
  app.add_option("--presubdivide", o.presubdivide,
                 "polyhedral: Catmull–Clark steps applied to the net first (one makes any net with valences and face sizes "
                 "<= 8 admissible)")
      ->check(whole_number(0, 6));
  app.add_option("--fit-to", o.fit_to,
                 "any backend: fit the built geometry's control points so that its surface lies on 'cylinder; R; A0; A1; Y0; "
                 "Y1' (about the y axis, x = R sin a, z = R cos a) or 'sphere; R; LON0; LON1; LAT0; LAT1' (angles in "
                 "degrees; a range of 360 is periodic), before refinement: a net made on the shape becomes that shape "
                 "(basis::fit_to_surface; the distance left is in the report as fit_to; iga-shell's points given on the "
                 "shape may lie up to twice that far from the surface)")
      ->check(non_blank());
  app.add_option("--quadrature", o.quadrature,
                 "quadrature rule: gauss:P (P points per direction) or tiles:P:L (P×P Gauss on each tile of levels 1..L of "
                 "elements at extraordinary vertices); default gauss:degree+1");
}

/// After parsing: the backend options the user gave (only these reach the backend, which refuses the ones it does
/// not take).
inline void record_given_options(const CLI::App& app, DiscretisationOptions& o) {
  for (const char* option : {"degree", "presubdivide", "refine-intervals", "geometry", "cc-boundary", "cc-enrich",
                             "cc-corners", "coarse-split", "grade-evs"}) {
    if (app.count(std::string("--") + option) > 0) o.given.emplace_back(option);
  }
}

/// --partition of a program with --solver petsc or mg (io::solver_options).
inline void add_partition_option(CLI::App& app, std::string& partition) {
  app.add_option("--partition", partition,
                 "--solver petsc or mg on more than one rank: how the elements are parted, curve (a Hilbert curve through "
                 "the elements' centres, the default), ptscotch (PT-Scotch on the elements' side graph) or metis (METIS "
                 "on the whole element-dof graph, on every rank); the report's partition says the cut")
      ->check(CLI::IsMember({"curve", "ptscotch", "metis"}));
}

/// --solver, --partition, --petsc-options, --threads and --max-memory of a PDE program (io/problem_run.hpp).
inline void add_solver_options(CLI::App& app, ProblemProgram& run) {
  app.add_option("--solver", run.solver,
                 "cholmod, cg (Eigen, incomplete Cholesky), petsc (a PETSc KSP, CG + GAMG by default, on the ranks of "
                 "mpirun: each assembles its own part of the elements, --partition), or mg (PETSc CG + geometric multigrid on the "
                 "nested spaces of the --refine steps)")
      ->check(CLI::IsMember({"cholmod", "cg", "petsc", "mg"}))->capture_default_str();
  add_partition_option(app, run.partition);
  app.add_option("--petsc-options", run.petsc_options,
                 "--solver petsc or mg: PETSc options, e.g. '-pc_type hypre' or '-mg_levels_pc_type sor' (the "
                 "PETSC_OPTIONS environment is read too)")
      ->check(non_blank());
  app.add_option("--threads", run.threads, "threads for assembly (default: OpenMP's)")->check(thread_count());
  app.add_option("--max-memory", run.max_memory,
                 "GiB this run may use (default: what the system has available); a run predicted to need more is refused "
                 "before it starts")
      ->check(finite_number(0.001, 1e6));
}

/// --vtu, --vtu-format, --vtu-samples, --vtu-degree and --json of a PDE program (io/vtu_output.hpp); `fields`: what
/// --vtu's help lists as written (empty: nothing listed).
inline void add_vtu_output_options(CLI::App& app, std::string& vtu, std::string& vtu_format, int& samples, int& degree,
                                   std::string& json, const std::string& fields = "") {
  app.add_option("--vtu", vtu, "ParaView output file ('none' to skip)" + (fields.empty() ? "" : ": " + fields))
      ->capture_default_str();
  app.add_option("--vtu-format", vtu_format, "bezier (one Bézier cell per element, exact on polynomial and NURBS elements, "
                 "plus <base>_outline.vtu with the element edges) or linear (--vtu-samples linear cells per element)")
      ->check(CLI::IsMember(vtu_formats()))->capture_default_str();
  app.add_option("--vtu-samples", samples, "--vtu-format linear: sample points per direction per element")
      ->check(whole_number(2, 64))->capture_default_str();
  app.add_option("--vtu-degree", degree, "--vtu-format bezier: degree of the cells of elements that are not polynomial")
      ->check(whole_number(1, 16))->capture_default_str();
  app.add_option("--json", json, "JSON report file ('-': standard output, 'none' to skip)")->capture_default_str();
}

/// The rest of a PDE program's command line after its own options: the common options, parsing (a --config file
/// included), the option rules, then --quiet, the report's run_info and the discretisation options given into `run`.
/// A value when the program must exit with it (--help, --version, a usage error: already reported).
inline std::optional<int> parse_problem_program(CLI::App& app, int argc, char** argv, ProblemProgram& run) {
  CommonOptions common{run.program};
  add_common_options(app, common);
  if (const auto code = parse_command_line(app, argc, argv, common)) return code;
  if (const auto code = check_option_rules(app, common.program)) return code;
  run.quiet = common.quiet;
  run.run_info = iga::io::run_info(app, common.program);
  record_given_options(app, run.discretisation);
  return std::nullopt;
}

}  // namespace iga::io
