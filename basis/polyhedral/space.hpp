#pragma once
// The polyhedral bi-3 spline space (Peters, Lo, Karčiauskas, "Bi-cubic splines for polyhedral control
// nets"): one function per control-net vertex that some configuration gathers, elements = the output patches
// of every configuration of the net (classify(), configuration.hpp), each degree-raised to bi-3 and evaluated
// by Bernstein extraction: the local functions on a patch are Cᵀ B(u, v), C = the configuration's mask
// (masks.hpp) with the columns of repeated gathered vertices summed.
//
// Elements: ElementKind {Quad, Regular, 4} for the polynomial patches of Regular, Star and NGon
// configurations, {Quad, Polar, n} for polar patches and {Quad, TJunction, 4} for T0–T2 (all polynomial, so
// Gauss rules are exact for polynomial integrands); configuration(e) tells which.
// Boundary: the outermost layer of the net recedes, so the boundary of the surface is made of the patch sides
// that no other patch covers. A side is covered when another side runs along the same curve, whole or as one
// half (cap patches meet a bi-2 patch side in two halves); sides are compared by their points at
// t = 0, 1/4, 1/2, 3/4, 1 in a generic (random) embedding of the dofs, so the test is combinatorial in effect.
// One boundary part, "boundary".
// Interior edges: the same matching of sides, in a generic embedding — one edge per pair of sides that run
// along the same curve (t0 = 0, t1 = 1 on the first, the range on the second), or per side that is one half
// of a longer one (the range (0, ½), (½, 1) or reversed on the longer side); collapsed sides of polar patches
// are points, no edges. continuity 1 (the patches join C1 or G1).
#include <memory>
#include <span>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "basis/geometry.hpp"
#include "basis/polyhedral/configuration.hpp"
#include "basis/space.hpp"
#include "mesh/poly_mesh.hpp"

namespace iga::basis::polyhedral {

class PolyhedralSpace final : public Space {
 public:
  /// Classifies the net (UnsupportedConfigurationError naming every offending vertex/face) and builds the
  /// patches; UnsupportedError naming the configuration and valence when its mask is not available.
  explicit PolyhedralSpace(const mesh::PolyMesh& net);

  std::string name() const override { return "polyhedral"; }
  Index num_dofs() const override { return static_cast<Index>(vertex_of_dof_.size()); }
  Index num_elements() const override { return static_cast<Index>(elements_.size()); }
  ElementKind kind(Index e) const override;
  /// 3: every configuration (regular, star, n-gon, polar, T-junction) gives bi-3 patches (16 BB coefficients).
  std::optional<int> polynomial_degree(Index) const override { return 3; }
  std::span<const Index> dofs(Index e) const override;
  Index max_local_dofs() const override { return max_local_; }
  void evaluate(Index e, const Eigen::Matrix2Xd& pts, int derivatives, BasisValues& out) const override;
  std::vector<BoundaryEdge> boundary_edges() const override { return boundary_; }
  std::vector<std::string> boundary_part_names() const override { return {"boundary"}; }
  std::vector<InteriorEdge> interior_edges() const override { return interior_; }

  /// The control net the space was built from (dofs are some of its vertices).
  const mesh::PolyMesh& control_net() const { return net_; }
  /// The control-net vertex (0-based) of a dof.
  Index vertex(Index dof) const { return vertex_of_dof_[static_cast<std::size_t>(dof)]; }
  /// The configuration site (index into sites()) and the patch within it of element e.
  Index site(Index e) const { return elements_[static_cast<std::size_t>(e)].site; }
  int patch(Index e) const { return elements_[static_cast<std::size_t>(e)].patch; }
  Configuration configuration(Index e) const { return sites_[static_cast<std::size_t>(site(e))].type; }
  const std::vector<ConfigurationSite>& sites() const { return sites_; }
  /// The bi-3 BB coefficients of element e as combinations of its local dofs (16 × dofs(e).size()).
  const Eigen::MatrixXd& extraction(Index e) const { return elements_[static_cast<std::size_t>(e)].c; }

 private:
  struct Element {
    Index site = 0;
    int patch = 0;
    std::vector<Index> dofs;
    Eigen::MatrixXd c;  // 16 × dofs
  };
  void build_sides();  // boundary_ and interior_ by matching sides

  mesh::PolyMesh net_;
  std::vector<ConfigurationSite> sites_;
  std::vector<Element> elements_;
  std::vector<Index> vertex_of_dof_;
  std::vector<BoundaryEdge> boundary_;
  std::vector<InteriorEdge> interior_;
  Index max_local_ = 0;
};

/// The geometry of a polyhedral net: PolyhedralSpace + the positions of the gathered vertices (dim 2 when all
/// z == 0, else 3).
Geometry make_polyhedral_geometry(const mesh::PolyMesh& net);

}  // namespace iga::basis::polyhedral
