// iga-geometry: look at or export the geometry a control net defines, for every basis backend, before solving
// on it: the limit surface as ParaView .vtu, the Bézier patches as BezierView .bv, and a JSON report with the
// element and patch counts. Thin: parses options and calls the library.
//
// .bv per backend:
//   bspline     every element, by Bézier extraction (degree p × p)
//   cc          the regular elements (polynomial bi-3 pieces: their BB coefficients are recovered exactly by
//               interpolation at the 4 × 4 points (i/3, j/3)); elements at extraordinary vertices are not
//               polynomial and are skipped — counted in the JSON ("bv_skipped") and said on stderr; the .vtu
//               samples them.
//   polyhedral  every patch of every configuration (paper's group names); --degree-raise writes all as bi-3.
//               Masks so far: regular (bi-2, bezier.hpp) and star (star_cap.hpp). Configurations without a mask
//               in this build are an error naming them (never a surface with holes presented as complete).
#include <CLI/CLI.hpp>
#include <Eigen/Dense>
#include <iostream>
#include <map>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "basis/bspline/extraction.hpp"
#include "basis/bspline/patches.hpp"
#include "basis/catmull_clark/space.hpp"
#include "basis/polyhedral/bezier.hpp"
#include "basis/polyhedral/configuration.hpp"
#include "basis/polyhedral/masks.hpp"
#include "basis/polyhedral/space.hpp"
#include "core/error.hpp"
#include "io/bv.hpp"
#include "io/report.hpp"
#include "io/vtu_writer.hpp"
#include "mesh/obj_reader.hpp"

namespace {

using iga::Index;
namespace poly = iga::basis::polyhedral;

struct Options {
  std::string basis = "polyhedral", mesh, vtu, bv, json;
  int presubdivide = 0, degree = 3, samples = 5;
  bool degree_raise = false, quiet = false;
};

/// What the program produced: a geometry to sample, Bézier patches to write, and counts for the report.
struct Output {
  std::unique_ptr<iga::basis::Geometry> geometry;
  std::vector<iga::io::BvPatch> patches;
  Index skipped = 0;
  nlohmann::json report;
};

Eigen::MatrixXd as_points(const Eigen::MatrixXd& cp) {
  Eigen::MatrixXd p = Eigen::MatrixXd::Zero(cp.rows(), 3);
  p.leftCols(cp.cols()) = cp;
  return p;
}

Output bspline_output(const iga::mesh::PolyMesh& net, const Options& o) {
  using namespace iga::basis::bspline;
  Output out;
  out.geometry = std::make_unique<iga::basis::Geometry>(geometry_from_quad_grid(net, o.degree, o.mesh));
  const auto& space = dynamic_cast<const TensorSpace&>(out.geometry->space());
  const Eigen::MatrixXd cp = as_points(out.geometry->control_points());
  const auto cu = extraction_operators(space.knots_u());
  const auto cv = extraction_operators(space.knots_v());
  const int p = space.knots_u().degree(), q = space.knots_v().degree();
  for (Index ey = 0; ey < space.num_elements_v(); ++ey) {
    for (Index ex = 0; ex < space.num_elements_u(); ++ex) {
      // BB coefficient (a, b) = Σ_ij C_u(i, a) C_v(j, b) P_{(span_u − p + i) + n_u (span_v − q + j)}.
      const Index span_u = space.knots_u().interval_spans()[static_cast<std::size_t>(ex)];
      const Index span_v = space.knots_v().interval_spans()[static_cast<std::size_t>(ey)];
      const Eigen::MatrixXd& Cu = cu[static_cast<std::size_t>(ex)];
      const Eigen::MatrixXd& Cv = cv[static_cast<std::size_t>(ey)];
      iga::io::BvPatch patch{"Group 0 BSpline", p, q, Eigen::MatrixXd::Zero((p + 1) * (q + 1), 3)};
      for (int b = 0; b <= q; ++b) {
        for (int a = 0; a <= p; ++a) {
          for (int j = 0; j <= q; ++j) {
            for (int i = 0; i <= p; ++i) {
              const Index dof = (span_u - p + i) + space.num_basis_u() * (span_v - q + j);
              patch.points.row(b * (p + 1) + a) += Cu(i, a) * Cv(j, b) * cp.row(dof);
            }
          }
        }
      }
      out.patches.push_back(std::move(patch));
    }
  }
  out.report["elements"] = space.num_elements();
  out.report["degree"] = {p, q};
  return out;
}

Output cc_output(const iga::mesh::PolyMesh& net, const Options& o) {
  using namespace iga::basis;
  Output out;
  out.geometry = std::make_unique<Geometry>(catmull_clark::make_catmull_clark_geometry(net, o.mesh));
  const Space& space = out.geometry->space();
  // Bernstein–Vandermonde system at (i/3, j/3): exact for the bi-3 polynomial regular elements.
  Eigen::Matrix2Xd pts(2, 16);
  for (int j = 0; j < 4; ++j) {
    for (int i = 0; i < 4; ++i) pts.col(j * 4 + i) = Eigen::Vector2d(i / 3.0, j / 3.0);
  }
  const Eigen::MatrixXd vandermonde = poly::bernstein_tensor(3, 3, pts, 0, 0).transpose();  // points × coefficients
  const Eigen::PartialPivLU<Eigen::MatrixXd> lu(vandermonde);
  for (Index e = 0; e < space.num_elements(); ++e) {
    if (space.kind(e).family != Family::Regular) {
      ++out.skipped;
      continue;
    }
    GeometryValues gv;
    out.geometry->evaluate(e, pts, gv);
    out.patches.push_back({"Group 0 Regular", 3, 3, lu.solve(Eigen::MatrixXd(gv.x.transpose()))});
  }
  out.report["elements"] = space.num_elements();
  out.report["cc_global_steps"] = dynamic_cast<const catmull_clark::CatmullClarkSpace&>(space).refinement_steps();
  return out;
}

/// "star5", "ngon3", "polar6", "regular", "T0".
std::string site_name(const poly::ConfigurationSite& s) {
  std::string name = to_string(s.type);
  if (s.type == poly::Configuration::Star || s.type == poly::Configuration::NGon || s.type == poly::Configuration::Polar) {
    name += std::to_string(s.valence);
  }
  return name;
}

Output polyhedral_output(const iga::mesh::PolyMesh& net, const Options& o) {
  using namespace iga::basis;
  // The space classifies the net and refuses unsupported configurations and configurations without a mask
  // with one error, before anything is written; its geometry (bi-3) is what the .vtu samples.
  Geometry geometry = poly::make_polyhedral_geometry(net);
  const auto& space = dynamic_cast<const poly::PolyhedralSpace&>(geometry.space());
  Output out;
  std::map<std::string, std::pair<int, int>> per_configuration;  // name → (configurations, patches)
  for (const auto& s : space.sites()) {
    // The .bv gets the patches in the degrees the paper outputs (regular bi-2, polar (3,2)) unless raised.
    const poly::ConfigurationMask& mask = poly::native_mask(s.type, s.valence);
    Eigen::MatrixXd gathered(static_cast<Index>(s.gathered.size()), 3);
    for (std::size_t k = 0; k < s.gathered.size(); ++k) gathered.row(static_cast<Index>(k)) = net.point(s.gathered[k]).transpose();
    for (const poly::PatchMask& pm : mask.patches) {
      poly::BezierPatch patch{pm.degree_u, pm.degree_v, pm.coefficients * gathered};
      if (o.degree_raise) patch = poly::elevate(patch, 3, 3);
      out.patches.push_back({poly::bv_group_name(s.type), patch.degree_u, patch.degree_v, patch.coefficients});
    }
    auto& c = per_configuration[site_name(s)];
    ++c.first;
    c.second += static_cast<int>(mask.patches.size());
  }
  out.geometry = std::make_unique<Geometry>(std::move(geometry));
  nlohmann::json conf = nlohmann::json::object();
  for (const auto& [name, c] : per_configuration) conf[name] = {{"configurations", c.first}, {"patches", c.second}};
  out.report["configurations"] = conf;
  out.report["elements"] = static_cast<Index>(out.patches.size());
  return out;
}

int run(const Options& o) {
  auto log = [&](const std::string& s) {
    if (!o.quiet) std::cerr << "iga-geometry: " << s << std::endl;
  };
  iga::mesh::PolyMesh net = iga::mesh::read_obj(o.mesh);
  if (o.presubdivide > 0) {
    net = poly::presubdivide(net, o.presubdivide);
    log("applied " + std::to_string(o.presubdivide) + " Catmull-Clark step(s): " + std::to_string(net.num_vertices()) +
        " vertices, " + std::to_string(net.num_faces()) + " faces");
  }
  Output out = o.basis == "bspline" ? bspline_output(net, o) : o.basis == "cc" ? cc_output(net, o) : polyhedral_output(net, o);
  nlohmann::json& j = out.report;
  j["program"] = "iga-geometry";
  j["basis"] = o.basis;
  j["mesh"] = o.mesh;
  j["presubdivide"] = o.presubdivide;
  j["net_vertices"] = net.num_vertices();
  j["net_faces"] = net.num_faces();
  j["bv_patches"] = static_cast<Index>(out.patches.size());
  j["bv_skipped"] = out.skipped;
  if (out.skipped > 0) {
    log(std::to_string(out.skipped) + " element(s) at extraordinary vertices are not polynomial: not in the .bv (the .vtu samples them)");
  }
  if (!o.vtu.empty()) {
    if (!out.geometry) throw iga::InputError("the net produces no patch (every vertex and face touches the boundary): nothing to write to " + o.vtu);
    iga::io::VtuOptions vo;
    vo.samples = o.samples;
    iga::io::write_vtu(o.vtu, *out.geometry, Eigen::VectorXd::Zero(out.geometry->space().num_dofs()), vo);
    j["vtu"] = o.vtu;
    log("wrote " + o.vtu);
  }
  if (!o.bv.empty()) {
    iga::io::write_bv(o.bv, out.patches);
    j["bv"] = o.bv;
    log("wrote " + o.bv + " (" + std::to_string(out.patches.size()) + " patches)");
  }
  if (!o.json.empty()) {
    iga::io::write_json(o.json, j);
    log("wrote " + o.json);
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"iga-geometry: export the geometry of a control net (VTU limit surface, BezierView .bv patches, JSON counts)"};
  Options o;
  app.add_option("--basis", o.basis, "basis backend")->check(CLI::IsMember({"bspline", "cc", "polyhedral"}))->capture_default_str();
  app.add_option("--mesh", o.mesh, "Wavefront OBJ control net (a quad grid for bspline)")->required()->check(CLI::ExistingFile);
  app.add_option("--presubdivide", o.presubdivide, "Catmull-Clark steps applied to the net first (one makes any net with valences <= 8 admissible for polyhedral)")
      ->check(CLI::Range(0, 6))->capture_default_str();
  app.add_option("--degree", o.degree, "bspline: degree per direction")->check(CLI::Range(1, 12))->capture_default_str();
  app.add_flag("--degree-raise", o.degree_raise, "polyhedral: write every patch as bi-3 (regular bi-2 patches degree-raised)");
  app.add_option("--vtu", o.vtu, "ParaView output of the limit surface (point data u = 0)");
  app.add_option("--vtu-samples", o.samples, "sample points per direction per element in the .vtu")->check(CLI::Range(2, 64))->capture_default_str();
  app.add_option("--bv", o.bv, "BezierView output (kind-5 patches)");
  app.add_option("--json", o.json, "JSON report: element and patch counts (polyhedral: per configuration and valence, e.g. star5)");
  app.add_flag("--quiet", o.quiet, "no progress on stderr");
  CLI11_PARSE(app, argc, argv);
  try {
    return run(o);
  } catch (const std::exception& e) {
    std::cerr << "iga-geometry: error: " << e.what() << std::endl;
    return 1;
  }
}
