// Registration of the Catmull–Clark subdivision-spline backend (basis/registry.hpp).
#include <Eigen/Dense>
#include <memory>

#include "basis/catmull_clark/corners.hpp"
#include "basis/catmull_clark/ev_enrichment.hpp"
#include "basis/catmull_clark/levels.hpp"
#include "basis/catmull_clark/space.hpp"
#include "basis/hierarchical/refine.hpp"
#include "basis/catmull_clark/topology.hpp"
#include "basis/polyhedral/bezier.hpp"
#include "basis/hierarchical/geometry_refinement.hpp"
#include "basis/registry.hpp"
#include "core/error.hpp"

namespace iga::basis {
namespace {

using catmull_clark::CatmullClarkSpace;
using catmull_clark::EnrichedSpace;
using hierarchical::HierarchicalSpace;

const CatmullClarkSpace& cc_of(const Geometry& g) {
  const auto* cc = dynamic_cast<const CatmullClarkSpace*>(&g.space());
  if (!cc) throw InputError("a '" + g.space().name() + "' space is not a Catmull–Clark space");
  return *cc;
}

Geometry from_net(const mesh::PolyMesh& net, const BackendOptions& o, BackendFacts& facts) {
  const auto rule = o.cc_boundary.empty() ? catmull_clark::BoundaryRule::kNatural : catmull_clark::boundary_rule(o.cc_boundary);
  Geometry g = catmull_clark::with_corners(catmull_clark::make_catmull_clark_geometry(net, o.net_name, rule),
                                           o.cc_corners, o.net_name);
  const int steps = cc_of(g).refinement_steps();
  facts.counts["cc_global_steps"] = steps;
  if (steps > 0) {
    facts.notes.push_back("the net has non-quad faces or faces touching several extraordinary vertices: applied " +
                          std::to_string(steps) + " global Catmull–Clark step(s) first");
  }
  if (!catmull_clark::enrichment_option(o.cc_enrich)) return g;
  std::vector<catmull_clark::EnrichmentCentre> centres = catmull_clark::extraordinary_centres(g);
  facts.counts["cc_enriched_vertices"] = static_cast<long long>(centres.size());
  if (centres.empty()) facts.notes.push_back("--cc-enrich quadratic: the net has no extraordinary vertex, nothing to enrich");
  return catmull_clark::enriched_geometry(g, std::move(centres));
}

// Block-diagonal prolongation: the base's, then the identity on the enrichment dofs (the same functions).
Eigen::SparseMatrix<double> with_identity(const Eigen::SparseMatrix<double>& p, Index extra) {
  Eigen::SparseMatrix<double> out = p;
  out.conservativeResize(p.rows() + extra, p.cols() + extra);
  for (Index k = 0; k < extra; ++k) out.insert(p.rows() + k, p.cols() + k) = 1.0;
  out.makeCompressed();
  return out;
}

// The hierarchical space of a geometry: its own, or (a Catmull–Clark space) the space as level 0 with the
// permutation from the net's vertices to the hierarchical dofs.
std::shared_ptr<const HierarchicalSpace> hierarchical_of(const Geometry& g, Eigen::SparseMatrix<double>* to_h) {
  if (auto h = std::dynamic_pointer_cast<const HierarchicalSpace>(g.space_ptr())) return h;
  std::shared_ptr<const CatmullClarkSpace> cc(g.space_ptr(), &cc_of(g));
  auto h = catmull_clark::coarse_hierarchical_space(cc);
  *to_h = hierarchical::level0_permutation(*h, cc->num_dofs());
  return h;
}

void refuse_enriched(const Geometry& geometry) {
  if (dynamic_cast<const EnrichedSpace*>(&geometry.space())) {
    // InputError, not UnsupportedError (which the adaptive loop reads as "no deeper level"): the option pair is
    // refused before anything is refined.
    throw InputError("--cc-enrich quadratic with local refinement (--adaptive, --grade-evs): the enriched space has no "
                     "hierarchical form; use uniform refinement (--refine)");
  }
}

// Hierarchical (truncated) refinement of the marked elements (thesis §4.2.5): a Catmull–Clark space becomes
// level 0 first; the control points are prolongated.
Refinement refine_hierarchical(const Geometry& geometry, std::span<const Index> marked, int admissibility,
                               BackendFacts& facts, bool with_prolongation) {
  refuse_enriched(geometry);
  Eigen::SparseMatrix<double> to_h;
  const auto coarse = hierarchical_of(geometry, &to_h);
  return hierarchical::refine_marked_geometry(geometry, coarse, to_h, marked, admissibility, facts, with_prolongation);
}

// Grading toward the extraordinary vertices (the irregular elements), planned on the cells and built once.
Refinement refine_graded(const Geometry& geometry, int levels, const std::function<int(int)>& rings, int admissibility,
                         BackendFacts& facts, bool keep_steps) {
  refuse_enriched(geometry);
  Eigen::SparseMatrix<double> to_h;
  const auto coarse = hierarchical_of(geometry, &to_h);
  return hierarchical::refine_graded_geometry(geometry, coarse, to_h, levels, rings, admissibility, facts, keep_steps);
}

// `steps` subdivisions of the control net (OpenSubdiv topology); every refined net has quads only, each
// touching at most one extraordinary vertex, so no global step is needed again. A hierarchical space: every
// element split, `steps` times.
Refinement refine_net(const Geometry& geometry, int steps, BackendFacts& facts) {
  if (const auto* en = dynamic_cast<const EnrichedSpace*>(&geometry.space())) {
    Refinement r = refine_net(Geometry(en->base(), en->base_points()), steps, facts);
    const Index extra = en->num_dofs() - en->base()->num_dofs();
    return {catmull_clark::enriched_geometry(r.geometry, en->centres()), with_identity(r.prolongation, extra), true};
  }
  if (std::dynamic_pointer_cast<const HierarchicalSpace>(geometry.space_ptr())) {
    return hierarchical::refine_all_geometry(geometry, steps, facts);
  }
  catmull_clark::SpaceRefinement r = catmull_clark::refine_space(cc_of(geometry), steps);
  if (r.space->refinement_steps() != 0) throw NumericalError("refined Catmull–Clark net needed another global step");
  Eigen::MatrixXd cp = r.prolongation * geometry.control_points();
  return {Geometry(std::move(r.space), std::move(cp)), std::move(r.prolongation), true};
}

// The regular elements are bi-3 polynomials: their BB coefficients are recovered exactly by interpolation at
// the 4 × 4 points (i/3, j/3). Elements at extraordinary vertices are not polynomial (counted as bv_skipped).
std::vector<BezierPatch> regular_patches(const Geometry& geometry, const BackendOptions&, BackendFacts& facts) {
  const Space& space = geometry.space();
  Eigen::Matrix2Xd pts(2, 16);
  for (int j = 0; j < 4; ++j) {
    for (int i = 0; i < 4; ++i) pts.col(j * 4 + i) = Eigen::Vector2d(i / 3.0, j / 3.0);
  }
  const Eigen::MatrixXd vandermonde = polyhedral::bernstein_tensor(3, 3, pts, 0, 0).transpose();
  const Eigen::PartialPivLU<Eigen::MatrixXd> lu(vandermonde);
  std::vector<BezierPatch> patches;
  long long skipped = 0;
  GeometryValues gv;
  BasisValues bv;
  for (Index e = 0; e < space.num_elements(); ++e) {
    if (space.kind(e).family != Family::Regular) {
      ++skipped;
      continue;
    }
    // Only the points are needed: no Jacobian check at the interpolation points, which include the element's
    // corners (where a boundary corner of the domain may have a degenerate Jacobian).
    space.evaluate(e, pts, 1, bv);
    geometry.evaluate(e, bv, gv, false);
    patches.push_back({"Group 0 Regular", false, 3, 3, lu.solve(Eigen::MatrixXd(gv.x.transpose()))});
  }
  facts.counts["bv_skipped"] = skipped;
  return patches;
}

}  // namespace

Backend catmull_clark_backend() {
  Backend b;
  b.name = "cc";
  b.description = "Catmull–Clark subdivision splines on any control net (exact evaluation at extraordinary vertices)";
  b.default_degree = 3;
  b.default_refine = 1;
  b.options = {"cc-boundary", "cc-enrich", "cc-corners", "grade-evs"};
  b.from_net = from_net;
  b.refine = refine_net;
  b.refine_marked = refine_hierarchical;
  b.refine_graded = refine_graded;
  b.default_quadrature = [](int) { return std::string("gauss:4"); };
  // With the clamped rule, what reaches an accuracy fastest on square_evs.obj (valences 3, 5, 6; README,
  // --grade-evs): Nitsche's method, graded toward the extraordinary vertices. The rule itself stays the user's
  // choice: it moves the domain's boundary near boundary extraordinary vertices (square_evs.obj: by up to 0.013).
  // Natural-rule levels are whole nets (slow), and the enriched space has no hierarchical form: neither is graded.
  b.prefers_weak_dirichlet = [](const BackendOptions& o) { return o.cc_boundary == "clamped"; };
  b.default_grading = [](const BackendOptions& o, int refine) {
    return o.cc_boundary == "clamped" && o.cc_enrich != "quadratic" ? refine + 3 : 0;
  };
  b.bezier_patches = regular_patches;
  return b;
}

}  // namespace iga::basis
