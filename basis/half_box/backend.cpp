// Registration of the half-box spline backend (basis/registry.hpp). Closed nets refine by one subdivision step
// per level (nested, with the prolongation of the step); nets with a boundary are refined as nets and the
// space rebuilt (the receding boundary moves, so those spaces are not nested).
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
  return g;
}

// The net with the geometry's control points at the vertices that are dofs.
mesh::PolyMesh current_net(const Geometry& geometry) {
  const auto& space = half_box_of(geometry);
  return net_with_control_points(space.control_net(), geometry, [&](Index d) { return space.vertex(d); });
}

// Refinement of a net with a boundary: subdivision steps of the open net (the receding boundary stays).
mesh::PolyMesh refine_open_net(const mesh::PolyMesh& net, int steps, BackendFacts& facts) {
  facts.counts["halfbox_net_steps"] += steps;
  mesh::PolyMesh out = net;
  for (int s = 0; s < steps; ++s) out = out.is_closed() ? half_box::subdivide(out).net : half_box::subdivide_local(out).net;
  return out;
}

Refinement refine(const Geometry& geometry, int steps, BackendFacts& facts) {
  const HalfBoxSpace& space = half_box_of(geometry);
  if (!space.control_net().is_closed()) {
    Geometry fine = half_box::make_half_box_geometry(refine_open_net(current_net(geometry), steps, facts), "refined net");
    return {std::move(fine), Eigen::SparseMatrix<double>(), false};
  }
  // Closed: every vertex is a dof (in vertex order), so the step's prolongation acts on the coefficients.
  facts.counts["halfbox_net_steps"] += steps;
  mesh::PolyMesh net = space.control_net();
  Eigen::SparseMatrix<double> total;
  for (int s = 0; s < steps; ++s) {
    half_box::NetSubdivision step = half_box::subdivide(net);
    if (s == 0) {
      total = std::move(step.prolongation);
    } else {
      Eigen::SparseMatrix<double> composed = step.prolongation * total;
      total.swap(composed);
    }
    net = std::move(step.net);
  }
  auto fine = std::make_shared<const HalfBoxSpace>(net, "refined net");
  if (fine->num_dofs() != total.rows()) throw NumericalError("refined half-box net: dofs and prolongation disagree");
  Eigen::MatrixXd cp = total * geometry.control_points();
  return {Geometry(fine, std::move(cp)), std::move(total), true};
}

// Regular elements are cubic Bézier triangles: c = bezier_matrix() · P. EF elements are not polynomial
// (counted as bv_skipped).
std::vector<BezierPatch> regular_triangles(const Geometry& geometry, const BackendOptions&, BackendFacts& facts) {
  const Space& space = geometry.space();
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
    patches.push_back({"Group 0 HalfBox", true, 3, 3, half_box::bezier_matrix() * local});
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
  // Closed nets are nested (refine gives the prolongation); nets with a boundary are refined as nets and the
  // space rebuilt (nested = false in the Refinement). The net is built first, so --refine counts the steps
  // after the one that separates extraordinary faces.
  b.nested = false;
  b.from_net = from_net;
  b.refine = refine;
  b.default_quadrature = [](int) { return std::string("tiles:4:10"); };
  b.bezier_patches = regular_triangles;
  return b;
}

}  // namespace iga::basis
