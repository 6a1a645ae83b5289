// bench-cc-evaluator: how fast the Catmull–Clark elements are evaluated. Reports, as JSON on stdout (or
// --json FILE), points per second for Stam's evaluator per valence and for whole irregular and regular
// elements of a net (both irregular methods), batched as quadrature does (one rule's points per call).
#include <CLI/CLI.hpp>
#include <chrono>
#include <iostream>
#include <nlohmann/json.hpp>
#include <random>

#include "basis/catmull_clark/space.hpp"
#include "io/report.hpp"
#include "mesh/obj_reader.hpp"
#include "quadrature/per_tile.hpp"

namespace {
using Clock = std::chrono::steady_clock;

// Points per second of f(batch) over `batches` calls with `q` points each.
template <class F>
double rate(F&& f, long batches, long q) {
  const auto t0 = Clock::now();
  for (long b = 0; b < batches; ++b) f(b);
  const double s = std::chrono::duration<double>(Clock::now() - t0).count();
  return static_cast<double>(batches * q) / s;
}
}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"bench-cc-evaluator: evaluation speed of Catmull–Clark elements"};
  std::string mesh, json;
  int levels = 8, derivatives = 1;
  long batches = 20000;
  app.add_option("--mesh", mesh, "control net whose elements are timed")->required()->check(CLI::ExistingFile);
  app.add_option("--levels", levels, "tile levels of the batch (tiles:4:L rule)")->capture_default_str();
  app.add_option("--derivatives", derivatives, "0, 1 or 2")->check(CLI::Range(0, 2))->capture_default_str();
  app.add_option("--batches", batches, "batches per measurement")->capture_default_str();
  app.add_option("--json", json, "write the report here too");
  CLI11_PARSE(app, argc, argv);
  try {
    using namespace iga;
    const quadrature::Rule rule = quadrature::tiled_rule(4, levels);
    const long q = rule.size();
    nlohmann::json report = {{"program", "bench-cc-evaluator"}, {"points_per_batch", q}, {"derivatives", derivatives}};
    basis::BasisValues out;
    for (int n = 3; n <= 8; ++n) {
      const auto& stam = basis::catmull_clark::stam_evaluator(n);
      report["stam_points_per_second"][std::to_string(n)] =
          rate([&](long) { stam.evaluate(rule.points, derivatives, out); }, batches, q);
    }
    const mesh::PolyMesh net = mesh::read_obj(mesh);
    for (auto method : {basis::catmull_clark::IrregularMethod::kStam, basis::catmull_clark::IrregularMethod::kSubdivision}) {
      const basis::catmull_clark::CatmullClarkSpace space(net, mesh, method);
      std::vector<Index> irregular, regular;
      for (Index e = 0; e < space.num_elements(); ++e) {
        (space.kind(e).family == basis::Family::Irregular ? irregular : regular).push_back(e);
      }
      const std::string key = method == basis::catmull_clark::IrregularMethod::kStam ? "stam" : "subdivision";
      if (!irregular.empty()) {
        report["element_points_per_second"]["irregular_" + key] = rate(
            [&](long b) { space.evaluate(irregular[static_cast<std::size_t>(b) % irregular.size()], rule.points, derivatives, out); },
            batches, q);
      }
      if (!regular.empty() && key == "stam") {
        report["element_points_per_second"]["regular"] = rate(
            [&](long b) { space.evaluate(regular[static_cast<std::size_t>(b) % regular.size()], rule.points, derivatives, out); },
            batches, q);
      }
    }
    std::cout << report.dump(2) << std::endl;
    if (!json.empty()) io::write_json(json, report);
    return 0;
  } catch (const std::exception& e) {
    std::cerr << "bench-cc-evaluator: error: " << e.what() << std::endl;
    return 1;
  }
}
