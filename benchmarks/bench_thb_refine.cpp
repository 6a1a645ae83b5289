// bench-thb-refine: what one local refinement of a THB space costs against the cells it marks and against the
// cells the mesh has (issue 34, item 2). A degree-p patch on [0, 1]² (or, with --mesh, hierarchical Catmull–Clark
// on that net with the clamped rule: levels made cell by cell) refined uniformly K times (4^K elements per root),
// then the M elements nearest the corner (0, 0) (Catmull–Clark: the first M in key order, a Z-order patch of the
// first face) marked and refined with admissibility class 2; timed: the
// refinement as the adaptive loop runs it (closure, incremental build from the previous space, prolongation) and,
// for comparison, a whole build of the same refined cells and its prolongation. Median of --repeat runs. JSON on
// stdout (and --json FILE).
#include <CLI/CLI.hpp>
#include <algorithm>
#include <chrono>
#include <iostream>
#include <nlohmann/json.hpp>
#include <vector>

#include "basis/catmull_clark/levels.hpp"
#include "basis/hierarchical/refine.hpp"
#include "basis/thb/dyadic_levels.hpp"
#include "core/error.hpp"
#include "io/report.hpp"
#include "mesh/obj_reader.hpp"

namespace {

using namespace iga;
using basis::hierarchical::HierarchicalSpace;

double seconds_since(std::chrono::steady_clock::time_point t) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

// The m elements whose centres are nearest the corner (0, 0) (the patch is [0, 1]², uniform), or (other
// hierarchies, whose uniform meshes number their cells in Z-order per root) the m with the smallest keys.
std::vector<Index> near_corner(const HierarchicalSpace& s, Index m) {
  const auto* h = dynamic_cast<const basis::thb::DyadicBsplineLevels*>(&s.hierarchy());
  std::vector<std::pair<double, Index>> d;
  d.reserve(static_cast<std::size_t>(s.num_elements()));
  for (Index e = 0; e < s.num_elements(); ++e) {
    if (h == nullptr) {
      d.emplace_back(static_cast<double>(s.cell(e)), e);
      continue;
    }
    const Eigen::Vector4d box = h->cell_box(s.level(e), s.cell(e));  // u0, u1, v0, v1
    d.emplace_back(std::hypot(box(0) + box(1), box(2) + box(3)), e);
  }
  std::nth_element(d.begin(), d.begin() + (m - 1), d.end());
  std::vector<Index> out;
  for (Index i = 0; i < m; ++i) out.push_back(d[static_cast<std::size_t>(i)].second);
  return out;
}

nlohmann::json measure(const HierarchicalSpace& base, Index m, int repeat) {
  const std::vector<Index> marked = near_corner(base, m);
  std::vector<double> refine, whole, prolong, whole_prolong;
  Index added = 0, dofs = 0;
  bool incremental = false;
  for (int r = 0; r < repeat; ++r) {
    auto t = std::chrono::steady_clock::now();
    const auto result = basis::hierarchical::refine_marked(base, marked, 2);
    refine.push_back(seconds_since(t));
    t = std::chrono::steady_clock::now();
    const Eigen::SparseMatrix<double> p = result.space->prolongation_from(base);
    prolong.push_back(seconds_since(t));
    t = std::chrono::steady_clock::now();
    const HierarchicalSpace again(base.hierarchy_ptr(), result.space->refined());
    whole.push_back(seconds_since(t));
    t = std::chrono::steady_clock::now();
    const Eigen::SparseMatrix<double> q = again.prolongation_from(base);
    whole_prolong.push_back(seconds_since(t));
    if (q.nonZeros() != p.nonZeros() || again.num_dofs() != result.space->num_dofs()) {
      throw NumericalError("bench-thb-refine: the incremental and the whole build differ");
    }
    added = result.marked + result.added;
    dofs = result.space->num_dofs();
    incremental = result.space->built_from(base);
  }
  return {{"elements", base.num_elements()}, {"marked", m}, {"refined_cells", added}, {"dofs", dofs},
          {"incremental", incremental}, {"refine_seconds", median(refine)}, {"prolongation_seconds", median(prolong)},
          {"whole_build_seconds", median(whole)}, {"whole_prolongation_seconds", median(whole_prolong)}};
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"bench-thb-refine: the cost of a local THB refinement against marked and total cells"};
  int degree = 2, min_refine = 6, max_refine = 9, repeat = 3;
  std::vector<Index> marks{1, 10, 100, 1000, 10000};
  std::string json, mesh;
  app.add_option("--degree", degree)->capture_default_str()->check(CLI::Range(1, 6));
  app.add_option("--mesh", mesh, "a Catmull–Clark control net (OBJ): hierarchical Catmull–Clark with the clamped rule "
                 "instead of THB (--degree does not apply)")->check(CLI::ExistingFile);
  app.add_option("--min-refine", min_refine, "uniform refinements of the smallest base mesh (4^K elements)")
      ->capture_default_str()->check(CLI::Range(1, 12));
  app.add_option("--max-refine", max_refine, "... of the largest")->capture_default_str()->check(CLI::Range(1, 12));
  app.add_option("--marked", marks, "marked elements per measurement (those above a quarter of the mesh skipped)")
      ->capture_default_str()->check(CLI::PositiveNumber);
  app.add_option("--repeat", repeat, "runs per measurement (the median counts)")->capture_default_str()->check(CLI::PositiveNumber);
  app.add_option("--json", json, "write the report here too");
  CLI11_PARSE(app, argc, argv);
  try {
    using namespace iga;
    if (min_refine > max_refine) throw InputError("--min-refine " + std::to_string(min_refine) + " is above --max-refine " + std::to_string(max_refine));
    std::shared_ptr<const HierarchicalSpace> space;
    nlohmann::json report = {{"program", "bench-thb-refine"}, {"admissibility", 2}, {"repeat", repeat}};
    if (mesh.empty()) {
      std::vector<double> knots(static_cast<std::size_t>(degree + 1), 0.0);
      knots.insert(knots.end(), static_cast<std::size_t>(degree + 1), 1.0);
      const basis::bspline::KnotVector k(degree, knots);
      space = basis::thb::coarse_thb_space(k, k);
      report["basis"] = "thb";
      report["degree"] = degree;
    } else {
      if (app.count("--degree") > 0) throw InputError("--degree does not apply to --mesh (Catmull–Clark is bicubic)");
      space = basis::catmull_clark::coarse_hierarchical_space(std::make_shared<const basis::catmull_clark::CatmullClarkSpace>(
          mesh::read_obj(mesh), mesh, basis::catmull_clark::IrregularMethod::kStam,
          basis::catmull_clark::BoundaryRule::kClamped));
      report["basis"] = "cc";
      report["mesh"] = mesh;
    }
    for (int r = 0; r < min_refine; ++r) space = basis::hierarchical::refine_all(*space).space;
    for (int r = min_refine; r <= max_refine; ++r) {
      for (Index m : marks) {
        if (4 * m > space->num_elements()) continue;
        report["runs"].push_back(measure(*space, m, repeat));
        std::cerr << report["runs"].back().dump() << "\n";
      }
      if (r < max_refine) space = basis::hierarchical::refine_all(*space).space;
    }
    io::write_json("-", report);
    if (!json.empty()) io::write_json(json, report);
  } catch (const std::exception& e) {
    std::cerr << "bench-thb-refine: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
