#pragma once
// The half-box spline space of a three-valent control net (thesis §2.2.5, §3.2.1): one triangular element per
// net vertex with three faces, evaluated by the regular patch (13 control points, regular_patch.hpp) or, when
// one of its faces is an extraordinary n-gon (n != 6), exactly by (3.40) with matrix powers
// (irregular_patch.hpp). Dofs are the net vertices that some patch uses.
//
// Elements: ElementKind {Triangle, Regular, 6}, or {Triangle, Irregular, n, false, HalfBox} with the EF at
// reference corner (0,0). Element e is the patch of vertex element_vertex(e); its reference triangle has corner
// (0,0) in face F0, (1,0) in F1, (0,1) in F2 (counter-clockwise around the vertex), F0 the EF if there is one
// (patch_net.hpp); side i lies between F_i and F_{i+1}.
//
// Nets where two extraordinary faces meet at a vertex get one subdivision step first (refinement_steps() == 1,
// as Catmull–Clark does for its nets); the refined net is then the control net.
//
// Boundary: a net with a boundary gives the patches of the vertices that have three faces, so the domain
// recedes from the net's outer layer (as for the polyhedral backend); the boundary is made of the patch sides
// whose neighbour vertex has no patch, one part "boundary". Subdivision (subdivide_local) keeps this domain,
// so refined spaces are nested. The boundary curves depend on interior rows of control points; Dirichlet data
// then become coupled constraints (fem/dirichlet.hpp). The thesis's boundary-interpolating double-knot rule
// is not implemented.
//
// Interior edges: side i of the patch of v is dual to the net edge v–w, w = the vertex across it; when w has a
// patch too, its side across from v is the same curve run the other way (F_i, F_{i+1} swap around w). One edge
// per such net edge, from the element with the lower index; continuity 1 (half-box splines are C1).
#include <Eigen/Sparse>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "basis/geometry.hpp"
#include "basis/space.hpp"
#include "mesh/poly_mesh.hpp"

namespace iga::basis::half_box {

class HalfBoxSpace final : public Space {
 public:
  /// InputError (file `name`) for a net that is not three-valent (a vertex named, 1-based) or has no patch;
  /// UnsupportedError for an extraordinary face of a size without a subdivision structure.
  explicit HalfBoxSpace(const mesh::PolyMesh& net, const std::string& name = "mesh");

  std::string name() const override { return "halfbox"; }
  Index num_dofs() const override { return static_cast<Index>(vertex_of_dof_.size()); }
  Index num_elements() const override { return static_cast<Index>(elements_.size()); }
  ElementKind kind(Index e) const override { return elements_[static_cast<std::size_t>(e)].kind; }
  /// 3 (total degree) for regular patches (cubic Bézier triangles, regular_patch.hpp); std::nullopt at an
  /// extraordinary face.
  std::optional<int> polynomial_degree(Index e) const override {
    if (kind(e).family == Family::Regular) return 3;
    return std::nullopt;
  }
  std::span<const Index> dofs(Index e) const override;
  Index max_local_dofs() const override { return max_local_; }
  void evaluate(Index e, const Eigen::Matrix2Xd& pts, int derivatives, BasisValues& out) const override;
  std::vector<BoundaryEdge> boundary_edges() const override { return boundary_; }
  std::vector<std::string> boundary_part_names() const override { return {"boundary"}; }
  std::vector<InteriorEdge> interior_edges() const override;
  /// EF elements: half_box_view(n) on the element's own n + 7 points (exact_view.hpp).
  std::optional<SubdivisionElement> subdivision_element(Index e) const override;

  /// The control net (after the subdivision step that separates extraordinary faces, if one was needed).
  const mesh::PolyMesh& control_net() const { return net_; }
  /// 0 or 1: subdivision steps applied to the given net first.
  int refinement_steps() const { return steps_; }
  /// Whether the functions of the net were linearly dependent (dependency.hpp: a bipartite net whose patches
  /// all annihilate the alternating pattern); then the function of removed_vertex() is left out.
  bool reduced() const { return removed_vertex_ >= 0; }
  Index removed_vertex() const { return removed_vertex_; }
  /// num_dofs × net vertices: the dof coefficients of the function with the given vertex coefficients
  /// (Σ_v a_v φ_v = Σ_d (R a)_d φ_d; identity on the dofs' vertices unless reduced()).
  Eigen::SparseMatrix<double> from_vertices() const;
  /// patch_size × dofs(e).size(): the patch's control-point coefficients from the element's dof coefficients
  /// (a 0/1 selection; a zero row for the function left out).
  Eigen::MatrixXd patch_map(Index e) const;
  /// The net vertex (0-based) of a dof, and the vertex whose patch element e is.
  Index vertex(Index dof) const { return vertex_of_dof_[static_cast<std::size_t>(dof)]; }
  Index element_vertex(Index e) const { return elements_[static_cast<std::size_t>(e)].vertex; }

 private:
  struct Element {
    Index vertex = -1;
    ElementKind kind;
    std::vector<Index> dofs;       // patch order (patch_net.hpp), without the function left out
    int removed = -1;              // local patch index of the function left out, or -1
    std::array<Index, 3> across{};  // net vertex across side i (the neighbour shared by F_i and F_{i+1})
  };
  void build_elements(const std::string& name);
  void build_boundary();

  mesh::PolyMesh net_;
  int steps_ = 0;
  std::vector<Element> elements_;
  std::vector<Index> vertex_of_dof_;
  std::vector<BoundaryEdge> boundary_;
  Index max_local_ = 0;
  Index removed_vertex_ = -1;
  std::vector<double> dependency_;  // c_d / c_removed per dof (reduced spaces)
};

/// The geometry of a three-valent net: HalfBoxSpace + the positions of its dofs' vertices (dim 2 when all
/// z == 0, else 3).
Geometry make_half_box_geometry(const mesh::PolyMesh& net, const std::string& name = "mesh");

}  // namespace iga::basis::half_box
