// iga-quadrature: the area of a planar net's domain or the volume enclosed by a closed one, for any backend
// (--basis, default cc), exactly (geometric series at extraordinary vertices and faces) or with a quadrature
// rule, with the number of points spent on irregular elements and the error against the exact value. Thin:
// parses options and calls the library.
//
// --quantity mass | stiffness: the matrices ∫ φ_a φ_b and ∫ ∇φ_a·∇φ_b (gradient in the element's parameters
// (u, v), i.e. planar Poisson on the parameter domain) of the elements at extraordinary vertices, by the rule
// and exactly (quadrature/exact/irregular_integrals.hpp), with the max-abs and relative Frobenius error:
//   --valence N: the single irregular element of valence N (its 2n+8 Stam functions; no mesh);
//   --mesh NET:  every element of the net evaluated by Stam's method (interior EVs with a complete ring),
//                assembled over the net's dofs, so the comparison is of ring sums (where the folded macro
//                rules are exact; per element they are not). Elements at boundary EVs are left out (no exact
//                integrals for them).
#include <CLI/CLI.hpp>
#include <iomanip>
#include <memory>
#include <vector>
#include <iostream>
#include <nlohmann/json.hpp>

#include "basis/catmull_clark/space.hpp"
#include "basis/registry.hpp"
#include "basis/catmull_clark/stam.hpp"
#include "core/error.hpp"
#include "fem/assembler.hpp"
#include "io/program.hpp"
#include "io/report.hpp"
#include "mesh/obj_reader.hpp"
#include "quadrature/exact/geometry_integrals.hpp"
#include "quadrature/exact/irregular_integrals.hpp"
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

// One Stam-evaluated element: its valence, its evaluator, the map from its dofs to Stam's local points
// (identity for --valence) and the dofs' indices in the compared matrix.
struct StamElement {
  int valence = 0;
  const iga::basis::catmull_clark::StamEvaluator* stam = nullptr;
  Eigen::MatrixXd map;  // (2n+8) × dofs
  std::vector<Eigen::Index> dofs;
};

struct MatrixComparison {
  Eigen::MatrixXd exact, by_rule;
  long elements = 0, points = 0;
};

// Exact and quadrature element matrices (mass: values; stiffness: parametric gradients), summed into one
// matrix over the elements.
MatrixComparison compare_matrices(const std::vector<StamElement>& elements, Eigen::Index size, bool stiffness,
                                  const iga::quadrature::RuleProvider* rules) {
  MatrixComparison out;
  out.exact = Eigen::MatrixXd::Zero(size, size);
  out.by_rule = Eigen::MatrixXd::Zero(size, size);
  for (const StamElement& el : elements) {
    const auto& ex = iga::quadrature::exact::irregular_integrals(el.valence);
    const Eigen::MatrixXd local = stiffness ? Eigen::MatrixXd(ex.d[0][0] + ex.d[1][1]) : ex.phi_phi;
    const Eigen::MatrixXd exact = el.map.transpose() * local * el.map;
    Eigen::MatrixXd quad = exact;
    if (rules != nullptr) {
      iga::basis::ElementKind kind;
      kind.family = iga::basis::Family::Irregular;
      kind.scheme = iga::basis::Scheme::CatmullClark;
      kind.valence = el.valence;
      const iga::quadrature::Rule& rule = rules->rule(kind);
      iga::basis::BasisValues bv;
      el.stam->evaluate(rule.points, stiffness ? 1 : 0, bv);
      const Eigen::VectorXd& w = rule.weights;
      const Eigen::MatrixXd local_q = stiffness ? Eigen::MatrixXd(bv.du * w.asDiagonal() * bv.du.transpose() +
                                                                  bv.dv * w.asDiagonal() * bv.dv.transpose())
                                                : Eigen::MatrixXd(bv.value * w.asDiagonal() * bv.value.transpose());
      quad = el.map.transpose() * local_q * el.map;
      out.points += rule.size();
    }
    for (std::size_t i = 0; i < el.dofs.size(); ++i) {
      for (std::size_t j = 0; j < el.dofs.size(); ++j) {
        const auto a = static_cast<Eigen::Index>(i), b = static_cast<Eigen::Index>(j);
        out.exact(el.dofs[i], el.dofs[j]) += exact(a, b);
        out.by_rule(el.dofs[i], el.dofs[j]) += quad(a, b);
      }
    }
    ++out.elements;
  }
  return out;
}

// The Stam elements of --valence N (one element) or of a net (all elements evaluated by Stam's method).
std::vector<StamElement> stam_elements(const std::string& mesh, int valence, Eigen::Index& size) {
  using namespace iga;
  std::vector<StamElement> out;
  if (mesh.empty()) {
    StamElement el;
    el.valence = valence;
    el.stam = &basis::catmull_clark::stam_evaluator(valence);
    const int p = 2 * valence + 8;
    el.map = Eigen::MatrixXd::Identity(p, p);
    for (int i = 0; i < p; ++i) el.dofs.push_back(i);
    size = p;
    out.push_back(std::move(el));
    return out;
  }
  const basis::catmull_clark::CatmullClarkSpace space(mesh::read_obj(mesh), mesh);
  std::vector<Eigen::Index> compact(static_cast<std::size_t>(space.num_dofs()), -1);
  size = 0;
  for (Index e = 0; e < space.num_elements(); ++e) {
    if (space.stam(e) == nullptr) continue;
    StamElement el;
    el.valence = space.kind(e).valence;
    el.stam = &basis::catmull_clark::stam_evaluator(el.valence);  // the cached evaluator, outlives `space`
    el.map = space.stam_map(e);
    for (const Index d : space.dofs(e)) {
      auto& c = compact[static_cast<std::size_t>(d)];
      if (c < 0) c = size++;
      el.dofs.push_back(c);
    }
    out.push_back(std::move(el));
  }
  if (out.empty()) throw InputError(mesh, 0, "no element at an interior extraordinary vertex (evaluated by Stam's method)");
  return out;
}

int run_matrices(const std::string& mesh, int valence, const std::string& quantity, const std::string& method,
                 const std::string& json, nlohmann::json report, bool quiet) {
  using namespace iga;
  if (mesh.empty() == (valence == 0)) throw InputError("--quantity " + quantity + " needs exactly one of --mesh and --valence");
  if (valence != 0 && (valence < 3 || valence > 16)) throw InputError("--valence must be 3..16, got " + std::to_string(valence));
  Eigen::Index size = 0;
  const std::vector<StamElement> elements = stam_elements(mesh, valence, size);
  std::unique_ptr<quadrature::RuleProvider> rules;
  if (method != "exact") rules = quadrature::make_rule_provider(method, 4);
  const MatrixComparison c = compare_matrices(elements, size, quantity == "stiffness", rules.get());
  const double max_abs = (c.by_rule - c.exact).cwiseAbs().maxCoeff();
  const double rel = (c.by_rule - c.exact).norm() / c.exact.norm();
  report.update({{"quantity", quantity}, {"method", method},
                 {"irregular_elements", c.elements}, {"matrix_size", size},
                 {"exact_frobenius", c.exact.norm()}, {"max_abs_error", max_abs},
                 {"relative_frobenius_error", rel}, {"relative_error", rel},
                 {"points_around_evs", c.points},
                 {"points_per_irregular_element", c.elements ? c.points / c.elements : 0}});
  if (mesh.empty()) {
    report["valence"] = valence;
  } else {
    report["mesh"] = mesh;
  }
  if (io::writes(json)) io::write_json(json, report);
  if (!quiet) {
    std::cerr << "iga-quadrature: " << quantity << " matrix " << size << " x " << size << " over " << c.elements
              << " element(s): max-abs error " << std::setprecision(3) << max_abs << ", relative Frobenius error " << rel
              << ", " << c.points << " points around EVs" << std::endl;
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"iga-quadrature: area or enclosed volume of a Catmull–Clark surface, or the mass/stiffness matrix "
               "at extraordinary vertices, exactly or by quadrature"};
  std::string mesh, quantity = "area", method = "exact", json, basis = "cc";
  int valence = 0;
  std::vector<std::string> backend_list;
  for (const auto& b : iga::basis::backends()) backend_list.push_back(b.name);
  app.add_option("--basis", basis, "area/volume: basis backend (" + iga::basis::backend_names() + ")")
      ->check(CLI::IsMember(backend_list))->capture_default_str();
  app.add_option("--mesh", mesh, "control net (OBJ); required for area and volume")->check(iga::io::input_file());
  app.add_option("--valence", valence, "mass/stiffness: the single irregular element of this valence (3..16), no mesh");
  app.add_option("--quantity", quantity, "area (planar net), volume (closed net), mass or stiffness (matrices at EVs)")
      ->check(CLI::IsMember({"area", "volume", "mass", "stiffness"}))->capture_default_str();
  app.add_option("--method", method, "exact, gauss:P, tiles:P:L, macro:R[:L] or fitted[:SPACE][:DIR]")->check(iga::io::non_blank())->capture_default_str();
  app.add_option("--json", json, "JSON report file ('-': standard output; default or 'none': no report)")->check(iga::io::non_blank());
  iga::io::CommonOptions common{"iga-quadrature"};
  iga::io::add_common_options(app, common);
  if (const auto code = iga::io::parse_command_line(app, argc, argv, common)) return *code;
  const nlohmann::json info = iga::io::run_info(app, common.program);
  return iga::io::run_program("iga-quadrature", [&] {
    using namespace iga;
    io::check_writable(json);  // before the work
    if (quantity == "mass" || quantity == "stiffness") {
      if (app.count("--basis")) throw InputError("--basis is for --quantity area or volume (the matrices are of Catmull–Clark elements)");
      return run_matrices(mesh, valence, quantity, method, json, info, common.quiet);
    }
    if (mesh.empty()) throw InputError("--quantity " + quantity + " needs --mesh");
    if (valence != 0) throw InputError("--valence is only for --quantity mass or stiffness");
    const basis::Backend& backend = basis::backend(basis);
    basis::BackendOptions options;
    options.net_name = mesh;
    basis::BackendFacts facts;
    const mesh::PolyMesh net = mesh::read_obj(mesh);
    const basis::Geometry g = basis::make_geometry(backend, &net, options, facts);
    // Notes go out with the result, so that a run that fails says one line only.
    std::vector<std::string> notes = facts.notes;
    const int degree = basis::degree(backend, options);
    const bool volume = quantity == "volume";
    if (!volume && g.dim() != 2) throw InputError(mesh, 0, "--quantity area needs a planar net (all z = 0)");
    if (volume && !g.space().boundary_edges().empty()) throw InputError(mesh, 0, "--quantity volume needs a closed net");
    double exact = volume ? quadrature::exact::exact_volume(g, degree) : quadrature::exact::exact_area(g, degree);
    // Orientation: the rules integrate |det J| (area) but the series the signed integrals; a clockwise net
    // (det J < 0) or a closed net with inward normals is reported with the positive measure and a note.
    const bool reversed = volume ? exact < 0 : g.orientation() < 0;
    if (reversed) {
      notes.push_back("note: " + mesh +
                      (volume ? ": the normals point inward (faces listed clockwise seen from outside); the enclosed volume is reported positive"
                              : ": the net is oriented clockwise (det J < 0); the area is reported positive"));
      exact = -exact;
    }
    nlohmann::json report = info;
    report.update({{"basis", basis}, {"mesh", mesh}, {"quantity", quantity}, {"method", method},
                   {"elements", g.space().num_elements()}, {"exact", exact}, {"reversed_orientation", reversed}});
    Index irregular = 0, ev_points = 0;
    double value = exact;
    if (method != "exact") {
      const auto rules = quadrature::make_rule_provider(method, 4);
      value = integrate(g, *rules, volume);
      if (volume && reversed) value = -value;
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
    if (io::writes(json)) io::write_json(json, report);
    if (!common.quiet) {
      for (const std::string& note : notes) std::cerr << "iga-quadrature: " << note << std::endl;
      std::cerr << "iga-quadrature: " << std::setprecision(17) << quantity << " " << value;
      if (method != "exact") std::cerr << "  (error " << std::setprecision(3) << value - exact << ", " << ev_points << " points around EVs)";
      std::cerr << std::endl;
    }
    return 0;
  });
}
