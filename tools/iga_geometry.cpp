// iga-geometry: look at or export the geometry a control net defines, for every basis backend, before solving
// on it: the limit surface as ParaView .vtu, the Bézier patches as BezierView .bv, and a JSON report with the
// element and patch counts. Thin: parses options and calls the library.
//
// .bv per backend:
//   bspline     every element, by Bézier extraction (degree p × p)
//   cc          the regular elements (polynomial bi-3 pieces: their BB coefficients are recovered exactly by
//               interpolation at the 4 × 4 points (i/3, j/3)); elements at extraordinary vertices are not
//               polynomial and are skipped — counted in the JSON ("bv_skipped") and said on stderr; the .vtu
//               writes them as interpolating Bézier cells (or samples them with --vtu-format linear).
//   polyhedral  every patch of every configuration (paper's group names); --degree-raise writes all as bi-3.
//   halfbox     the regular elements as cubic triangles (kind 3); elements at extraordinary faces are not
//               polynomial and are skipped ("bv_skipped").
// Each backend makes its patches (basis/registry.hpp, Backend::bezier_patches); this program only writes them.
#include <CLI/CLI.hpp>
#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>
#include <iostream>
#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "basis/registry.hpp"
#include "core/error.hpp"
#include "fem/memory.hpp"
#include "io/bv.hpp"
#include "io/discretisation.hpp"
#include "io/program.hpp"
#include "io/report.hpp"
#include "io/net_writer.hpp"
#include "io/vtu_output.hpp"
#include "io/vtu_writer.hpp"
#include "mesh/obj_reader.hpp"
#include "mesh/obj_writer.hpp"
#include "mesh/three_valent.hpp"

using iga::Index;

namespace {

struct Options {
  std::string basis = "polyhedral", mesh, vtu, bv, json, three_valent, obj, vtu_format = "bezier", net_vtu;
  int presubdivide = 0, degree = 3, samples = 4, vtu_degree = 6;
  std::string cc_boundary = "natural", cc_corners;
  bool degree_raise = false, quiet = false;
  std::vector<std::string> given;  ///< backend options given on the command line (names without dashes)
  nlohmann::json run_info;         ///< io::run_info: version, revision, every effective setting
};

// A triangle of basis/registry.hpp (b_ijk with i, then j, descending: (d00), (d−1,1,0), (d−1,0,1), …, (00d))
// in the row order of io/bv.hpp.
Eigen::MatrixXd to_bv_triangle(int degree, const Eigen::MatrixXd& points) {
  if (points.rows() != iga::io::triangle_size(degree)) {
    throw iga::NumericalError("--bv: a triangular patch of degree " + std::to_string(degree) + " has " +
                              std::to_string(points.rows()) + " points");
  }
  Eigen::MatrixXd out(points.rows(), points.cols());
  Eigen::Index r = 0;
  for (int i = degree; i >= 0; --i) {
    for (int j = degree - i; j >= 0; --j) out.row(iga::io::triangle_index(degree, j, degree - i - j)) = points.row(r++);
  }
  return out;
}

// --three-valent dual|trisect: a three-valent net from a triangle mesh (thesis Appendix B), written as OBJ,
// with its face sizes in the report.
int make_three_valent(const Options& o) {
  if (o.obj.empty()) throw iga::InputError("--three-valent needs --obj FILE for the net");
  const iga::mesh::PolyMesh triangles = iga::mesh::read_obj(o.mesh);
  iga::mesh::PolyMesh net;
  try {
    net = o.three_valent == "dual" ? iga::mesh::dual_net(triangles) : iga::mesh::trisect_net(triangles);
  } catch (const iga::InputError& e) {
    throw iga::InputError(o.mesh, 0, e.what());
  }
  if (iga::io::writes(o.obj)) iga::mesh::write_obj(net, o.obj);
  nlohmann::json j = o.run_info;
  j["three_valent"] = o.three_valent;
  j["mesh"] = o.mesh;
  j["obj"] = o.obj;
  j["net_vertices"] = net.num_vertices();
  j["net_faces"] = net.num_faces();
  std::map<std::string, long long> sizes;
  for (Index f = 0; f < net.num_faces(); ++f) ++sizes[std::to_string(net.face_size(f))];
  j["faces_per_size"] = sizes;
  if (!o.quiet) {
    std::cerr << "iga-geometry: wrote " << o.obj << " (" << net.num_vertices() << " vertices, " << net.num_faces()
              << " faces)" << std::endl;
  }
  if (iga::io::writes(o.json)) iga::io::write_json(o.json, j);
  return 0;
}

int run(const Options& o) {
  for (const std::string* path : {&o.json, &o.vtu, &o.bv, &o.obj}) iga::io::check_writable(*path);  // before the work
  if (!o.three_valent.empty()) return make_three_valent(o);
  auto log = [&](const std::string& s) {
    if (!o.quiet) std::cerr << "iga-geometry: " << s << std::endl;
  };
  const iga::basis::Backend& backend = iga::basis::backend(o.basis);
  iga::basis::check_options(backend, o.given);
  iga::basis::BackendOptions bo;
  bo.net_name = o.mesh;
  if (std::find(o.given.begin(), o.given.end(), "degree") != o.given.end()) bo.degree = o.degree;
  if (std::find(o.given.begin(), o.given.end(), "presubdivide") != o.given.end()) bo.presubdivide = o.presubdivide;
  bo.degree_raise = o.degree_raise;
  if (std::find(o.given.begin(), o.given.end(), "cc-boundary") != o.given.end()) bo.cc_boundary = o.cc_boundary;
  if (std::find(o.given.begin(), o.given.end(), "cc-corners") != o.given.end()) {
    bo.cc_corners = iga::io::parse_vertex_numbers("--cc-corners", o.cc_corners);
  }
  const iga::mesh::PolyMesh net = iga::mesh::read_obj(o.mesh);
  {
    // Size before work: --presubdivide multiplies the faces by four per step; the .vtu samples² points each.
    const double elements = static_cast<double>(net.num_faces()) * std::pow(4.0, bo.presubdivide == iga::basis::BackendOptions::kUnset ? 0 : bo.presubdivide);
    std::ostringstream what;
    what << "this geometry (about " << std::setprecision(3) << elements << " elements)";
    iga::fem::check_memory(1000.0 * elements + (!iga::io::writes(o.vtu) ? 0.0 : iga::fem::vtu_memory(elements, o.vtu_format == "linear" ? o.samples : o.vtu_degree + 1)), 0.0,
                           what.str(), "each --presubdivide step needs four times more; --vtu-samples costs its square per element");
  }
  iga::basis::BackendFacts facts;
  const iga::basis::Geometry geometry = iga::basis::make_geometry(backend, &net, bo, facts);
  for (const std::string& note : facts.notes) log(note);
  // A viewer may show a geometry no solver accepts, but says what is wrong with it (also with --quiet): the JSON's
  // "valid" and, once the files are written, a warning line (a write that fails on it says so in its one line).
  const std::string invalid = geometry.validity();
  std::vector<iga::io::BvPatch> patches;
  for (iga::basis::BezierPatch& p : backend.bezier_patches(geometry, bo, facts)) {
    if (p.triangle) {
      patches.push_back({p.group, true, p.degree_u, p.degree_u, to_bv_triangle(p.degree_u, p.points)});
    } else {
      patches.push_back({p.group, false, p.degree_u, p.degree_v, std::move(p.points)});
    }
  }
  nlohmann::json j = o.run_info;
  j["basis"] = o.basis;
  j["mesh"] = o.mesh;
  j["presubdivide"] = bo.presubdivide == iga::basis::BackendOptions::kUnset ? 0 : bo.presubdivide;
  j["net_vertices"] = net.num_vertices();
  j["net_faces"] = net.num_faces();
  j["elements"] = geometry.space().num_elements();
  j["valid"] = invalid.empty();
  if (!invalid.empty()) j["invalid_reason"] = invalid;
  j["degree"] = iga::basis::degree(backend, bo);
  j["bv_patches"] = static_cast<Index>(patches.size());
  j["bv_skipped"] = 0;
  for (const auto& [path, count] : facts.counts) j[nlohmann::json::json_pointer("/" + path)] = count;
  if (j["bv_skipped"].get<long long>() > 0) {
    log(std::to_string(j["bv_skipped"].get<long long>()) + " element(s) at extraordinary vertices or faces are not polynomial: not in the .bv (the .vtu samples them)");
  }
  if (iga::io::writes(o.vtu)) {
    if (geometry.space().num_elements() == 0) throw iga::InputError("the net produces no patch (every vertex and face touches the boundary): nothing to write to " + o.vtu);
    iga::io::VtuOutput output;
    output.format = o.vtu_format;
    output.samples = o.samples;
    output.degree = o.vtu_degree;
    const std::vector<std::string> files = iga::io::write_output(o.vtu, geometry, nullptr, output);
    j["vtu"] = o.vtu;
    j["vtu_output"] = output.settings();
    if (files.size() > 1) j["vtu_outline"] = files[1];
    for (const std::string& f : files) log("wrote " + f);
  }
  if (iga::io::writes(o.net_vtu)) {
    iga::io::write_control_net_vtu(o.net_vtu, geometry, &net);
    j["net_vtu"] = o.net_vtu;
    log("wrote " + o.net_vtu);
  }
  if (iga::io::writes(o.bv)) {
    iga::io::write_bv(o.bv, patches);
    j["bv"] = o.bv;
    log("wrote " + o.bv + " (" + std::to_string(patches.size()) + " patches)");
  }
  if (iga::io::writes(o.json)) {
    iga::io::write_json(o.json, j);
    log("wrote " + o.json);
  }
  if (!invalid.empty()) std::cerr << "iga-geometry: warning: " << invalid << "; iga-poisson refuses this geometry" << std::endl;
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"iga-geometry: export the geometry of a control net (VTU limit surface, BezierView .bv patches, JSON counts)"};
  Options o;
  std::vector<std::string> backend_list;
  for (const auto& b : iga::basis::backends()) backend_list.push_back(b.name);
  app.add_option("--basis", o.basis, "basis backend (" + iga::basis::backend_names() + ")")->check(CLI::IsMember(backend_list))->capture_default_str();
  app.add_option("--mesh", o.mesh, "Wavefront OBJ control net (a quad grid for bspline)")->required()->check(iga::io::input_file());
  app.add_option("--cc-boundary", o.cc_boundary, "cc: natural (OpenSubdiv's boundary rule) or clamped (one ring of ghost control points, drawn with --net)")->check(CLI::IsMember({"natural", "clamped"}))->capture_default_str();
  app.add_option("--cc-corners", o.cc_corners, "cc with --cc-boundary clamped: net vertices (from 1, comma-separated) the limit domain keeps as corners (README)")->check(iga::io::non_blank());
  app.add_option("--presubdivide", o.presubdivide, "Catmull-Clark steps applied to the net first (one makes any net with valences <= 8 admissible for polyhedral)")
      ->check(iga::io::whole_number(0, 6))->capture_default_str();
  app.add_option("--degree", o.degree, "bspline: degree per direction")->check(iga::io::whole_number(1, 12))->capture_default_str();
  app.add_flag("--degree-raise", o.degree_raise, "polyhedral: write every patch as bi-3 (regular bi-2 patches degree-raised)");
  app.add_option("--vtu", o.vtu, "ParaView output of the limit surface (no point data)")->check(iga::io::non_blank());
  app.add_option("--vtu-samples", o.samples, "--vtu-format linear: sample points per direction per element in the .vtu")->check(iga::io::whole_number(2, 64))->capture_default_str();
  app.add_option("--vtu-format", o.vtu_format, "bezier: one exact Bezier cell per polynomial element (an interpolating one of degree --vtu-degree at extraordinary vertices), points shared, plus <base>_outline.vtu with the element edges; linear: --vtu-samples linear cells per element")->check(CLI::IsMember(iga::io::vtu_formats()))->capture_default_str();
  app.add_option("--vtu-degree", o.vtu_degree, "--vtu-format bezier: degree of the cells of elements that are not polynomial")->check(iga::io::whole_number(1, 16))->capture_default_str();
  app.add_option("--net", o.net_vtu, "write the control net to this .vtu: the control points, and the --mesh faces whose corners are control points as polygons")->check(iga::io::non_blank());
  app.add_option("--bv", o.bv, "BezierView output (kind-5 tensor and kind-3 triangular patches)")->check(iga::io::non_blank());
  app.add_option("--json", o.json, "JSON report: element and patch counts (polyhedral: per configuration and valence, e.g. star5)")->check(iga::io::non_blank());
  app.add_option("--three-valent", o.three_valent, "make a three-valent net from the triangle mesh --mesh: dual (a vertex per triangle) or trisect (edges split in three, corners cut); written to --obj")
      ->check(CLI::IsMember({"dual", "trisect"}))
      // It writes a net, not a surface: the options of the surface would be ignored.
      ->excludes(app.get_option("--basis"))->excludes(app.get_option("--vtu"))->excludes(app.get_option("--bv"));
  app.add_option("--obj", o.obj, "with --three-valent: the OBJ file of the net")->check(iga::io::non_blank())
      ->needs(app.get_option("--three-valent"));
  iga::io::CommonOptions common{"iga-geometry"};
  iga::io::add_common_options(app, common);
  if (const auto code = iga::io::parse_command_line(app, argc, argv, common)) return *code;
  o.quiet = common.quiet;
  o.run_info = iga::io::run_info(app, common.program);
  for (const char* option : {"degree", "presubdivide", "degree-raise", "cc-boundary", "cc-corners"}) {
    if (app.count(std::string("--") + option) > 0) o.given.emplace_back(option);
  }
  return iga::io::run_program("iga-geometry", [&] { return run(o); });
}
