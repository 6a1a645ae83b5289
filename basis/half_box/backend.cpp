// Registration of the half-box spline backend (basis/registry.hpp). Refinement is one subdivision step of the
// net per level; the spaces are nested (closed nets and nets with a receding boundary alike), with the
// prolongation of the steps on the dofs.
#include <cmath>
#include <memory>

#include "basis/half_box/regular_patch.hpp"
#include "basis/half_box/space.hpp"
#include "basis/half_box/subdivision.hpp"
#include "basis/registry.hpp"
#include "core/error.hpp"

namespace iga::basis {
namespace {

using half_box::HalfBoxSpace;

const HalfBoxSpace& half_box_of(const Geometry& g) {
  const auto* s = dynamic_cast<const HalfBoxSpace*>(&g.space());
  if (!s) throw InputError("a '" + g.space().name() + "' space is not a half-box space");
  return *s;
}

Geometry from_net(const mesh::PolyMesh& net, const BackendOptions& o, BackendFacts& facts) {
  Geometry g = half_box::make_half_box_geometry(net, o.net_name);
  const int steps = half_box_of(g).refinement_steps();
  facts.counts["halfbox_separation_steps"] = steps;
  if (steps > 0) {
    facts.notes.push_back("two extraordinary faces meet at a vertex of the net: applied one half-box subdivision step first");
  }
  facts.counts["halfbox_boundary_sides"] = static_cast<long long>(g.space().boundary_edges().size());
  if (!half_box_of(g).control_net().is_closed()) {
    facts.notes.push_back("the net has a boundary: the domain is the union of the complete patches (it recedes from the "
                          "net's outer layer; the thesis's boundary-interpolating rule is not implemented)");
  }
  if (half_box_of(g).reduced()) {
    facts.notes.push_back("the net's half-box functions are linearly dependent (a net of even faces only): one function is left out");
  }
  return g;
}

// One subdivision step (closed nets: subdivide; nets with a boundary: subdivide_local, which keeps the
// patches of the receding boundary and so the domain) and its prolongation on the dofs: the coarse dof
// coefficients as vertex coefficients (E), the step's vertex prolongation, the fine space's reduction to its
// dofs (HalfBoxSpace::from_vertices). The fine patches lie inside the coarse ones and their points come from
// the coarse patches' points, so every fine patch point's row sums to one on the coarse patch points
// (checked): the spaces are nested.
Refinement one_step(const Geometry& geometry) {
  const HalfBoxSpace& coarse = half_box_of(geometry);
  const mesh::PolyMesh& net = coarse.control_net();
  half_box::NetSubdivision step = net.is_closed() ? half_box::subdivide(net) : half_box::subdivide_local(net);
  auto fine = std::make_shared<const HalfBoxSpace>(step.net, "refined net");
  if (fine->refinement_steps() != 0) throw NumericalError("refined half-box net needed another separation step");
  std::vector<char> coarse_point(static_cast<std::size_t>(net.num_vertices()), 0);
  std::vector<Eigen::Triplet<double>> e_entries;
  for (Index d = 0; d < coarse.num_dofs(); ++d) {
    e_entries.emplace_back(coarse.vertex(d), d, 1.0);
    coarse_point[static_cast<std::size_t>(coarse.vertex(d))] = 1;
  }
  if (coarse.reduced()) coarse_point[static_cast<std::size_t>(coarse.removed_vertex())] = 1;
  Eigen::SparseMatrix<double> e(net.num_vertices(), coarse.num_dofs());
  e.setFromTriplets(e_entries.begin(), e_entries.end());
  const Eigen::SparseMatrix<double, Eigen::RowMajor> pv = step.prolongation;
  auto check_row = [&](Index v) {
    double sum = 0.0;
    for (Eigen::SparseMatrix<double, Eigen::RowMajor>::InnerIterator it(pv, v); it; ++it) {
      if (coarse_point[static_cast<std::size_t>(it.col())]) sum += it.value();
    }
    if (std::abs(sum - 1.0) > 1e-12) {
      throw NumericalError("half-box refinement: fine net vertex " + std::to_string(v + 1) + " depends on net vertices of no coarse patch");
    }
  };
  for (Index d = 0; d < fine->num_dofs(); ++d) check_row(fine->vertex(d));
  if (fine->reduced()) check_row(fine->removed_vertex());
  Eigen::SparseMatrix<double> pe = step.prolongation * e;
  Eigen::SparseMatrix<double> p = fine->from_vertices() * pe;
  p.prune(0.0);
  Eigen::MatrixXd cp = p * geometry.control_points();
  return {Geometry(fine, std::move(cp)), std::move(p), true};
}

Refinement refine(const Geometry& geometry, int steps, BackendFacts& facts) {
  facts.counts["halfbox_net_steps"] += steps;
  Refinement out = one_step(geometry);
  for (int s = 1; s < steps; ++s) {
    Refinement next = one_step(out.geometry);
    Eigen::SparseMatrix<double> composed = next.prolongation * out.prolongation;
    out.geometry = next.geometry;
    out.prolongation.swap(composed);
  }
  return out;
}

// Regular elements are cubic Bézier triangles: c = bezier_matrix() · P with P the 13 patch points (through
// patch_map when the space left a function out). EF elements are not polynomial (counted as bv_skipped).
std::vector<BezierPatch> regular_triangles(const Geometry& geometry, const BackendOptions&, BackendFacts& facts) {
  const HalfBoxSpace& space = half_box_of(geometry);
  std::vector<BezierPatch> patches;
  long long skipped = 0;
  Eigen::MatrixXd local;
  for (Index e = 0; e < space.num_elements(); ++e) {
    if (space.kind(e).family != Family::Regular) {
      ++skipped;
      continue;
    }
    const auto dofs = space.dofs(e);
    local = Eigen::MatrixXd::Zero(static_cast<Index>(dofs.size()), 3);
    for (std::size_t k = 0; k < dofs.size(); ++k) {
      local.row(static_cast<Index>(k)).head(geometry.dim()) = geometry.control_points().row(dofs[k]);
    }
    patches.push_back({"Group 0 HalfBox", true, 3, 3, half_box::bezier_matrix() * (space.patch_map(e) * local)});
  }
  facts.counts["bv_skipped"] = skipped;
  return patches;
}

}  // namespace

Backend half_box_backend() {
  Backend b;
  b.name = "halfbox";
  b.description = "half-box splines on a three-valent net (triangular elements, exact evaluation at extraordinary faces)";
  b.default_degree = 3;
  b.default_refine = 1;
  // The net is built first, so --refine counts the steps after the one that separates extraordinary faces.
  b.nested = true;
  b.from_net = from_net;
  b.refine = refine;
  // Tiles of 20 layers: the plain-Gauss corner piece of an EF element has area 2^-41 and its sides into the
  // EF corner a last piece of 2^-20 (boundary integrals converge like 2^-L there; see PerTile::side_rule).
  b.default_quadrature = [](int) { return std::string("tiles:4:20"); };
  b.bezier_patches = regular_triangles;
  return b;
}

}  // namespace iga::basis
