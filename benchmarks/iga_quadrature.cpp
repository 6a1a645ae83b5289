// iga-quadrature: the area of a planar Catmull–Clark net or the volume enclosed by a closed one, exactly
// (geometric series) or with a quadrature rule, with the number of points spent around extraordinary
// vertices and the error against the exact value. Thin: parses options and calls the library.
#include <CLI/CLI.hpp>
#include <iomanip>
#include <iostream>
#include <nlohmann/json.hpp>

#include "basis/catmull_clark/space.hpp"
#include "core/error.hpp"
#include "fem/assembler.hpp"
#include "io/report.hpp"
#include "mesh/obj_reader.hpp"
#include "quadrature/exact/geometry_integrals.hpp"
#include "quadrature/rule_provider.hpp"

namespace {

// ∫ over the parameter domain of the area element (planar) or of z (x_u y_v - y_u x_v) (volume).
double integrate(const iga::basis::Geometry& g, const iga::quadrature::RuleProvider& rules, bool volume) {
  const iga::fem::Assembler assembler(g, rules);
  return assembler.integrate(1, [&](const iga::fem::ElementContext& c, Eigen::Ref<Eigen::VectorXd> out) {
    if (!volume) {
      out(0) = c.weight.sum();
      return;
    }
    double s = 0;
    for (Eigen::Index k = 0; k < c.rule->size(); ++k) {
      const Eigen::Vector3d xu = c.geo.xu.col(k), xv = c.geo.xv.col(k);
      s += c.rule->weights(k) * c.geo.x(2, k) * (xu(0) * xv(1) - xu(1) * xv(0));
    }
    out(0) = s;
  })(0);
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"iga-quadrature: area or enclosed volume of a Catmull–Clark surface, exactly or by quadrature"};
  std::string mesh, quantity = "area", method = "exact", json;
  app.add_option("--mesh", mesh, "control net (OBJ)")->required()->check(CLI::ExistingFile);
  app.add_option("--quantity", quantity, "area (planar net) or volume (closed net)")->check(CLI::IsMember({"area", "volume"}))->capture_default_str();
  app.add_option("--method", method, "exact, tiles:P:L, macro:R[:L] or fitted")->capture_default_str();
  app.add_option("--json", json, "JSON report file");
  CLI11_PARSE(app, argc, argv);
  try {
    using namespace iga;
    const basis::Geometry g = basis::catmull_clark::make_catmull_clark_geometry(mesh::read_obj(mesh), mesh);
    const bool volume = quantity == "volume";
    if (!volume && g.dim() != 2) throw InputError(mesh, 0, "--quantity area needs a planar net (all z = 0)");
    if (volume && !g.space().boundary_edges().empty()) throw InputError(mesh, 0, "--quantity volume needs a closed net");
    const double exact = volume ? quadrature::exact::exact_volume(g) : quadrature::exact::exact_area(g);
    nlohmann::json report = {{"program", "iga-quadrature"}, {"mesh", mesh}, {"quantity", quantity}, {"method", method},
                             {"elements", g.space().num_elements()}, {"exact", exact}};
    Index irregular = 0, ev_points = 0;
    double value = exact;
    if (method != "exact") {
      const auto rules = quadrature::make_rule_provider(method, 4);
      value = integrate(g, *rules, volume);
      for (Index e = 0; e < g.space().num_elements(); ++e) {
        const basis::ElementKind k = g.space().kind(e);
        if (k.family == basis::Family::Irregular) {
          ++irregular;
          ev_points += rules->rule(k).size();
        }
      }
      report["error"] = value - exact;
      report["relative_error"] = (value - exact) / exact;
      report["points_around_evs"] = ev_points;
      report["points_per_irregular_element"] = irregular ? ev_points / irregular : 0;
    } else {
      for (Index e = 0; e < g.space().num_elements(); ++e) irregular += g.space().kind(e).family == basis::Family::Irregular;
      report["points_around_evs"] = 0;
    }
    report["irregular_elements"] = irregular;
    report["value"] = value;
    std::cout << std::setprecision(17) << quantity << " " << value;
    if (method != "exact") std::cout << "  (error " << std::setprecision(3) << value - exact << ", " << ev_points << " points around EVs)";
    std::cout << std::endl;
    if (!json.empty()) io::write_json(json, report);
    return 0;
  } catch (const std::exception& e) {
    std::cerr << "iga-quadrature: error: " << e.what() << std::endl;
    return 1;
  }
}
