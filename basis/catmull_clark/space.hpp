#pragma once
// Catmull–Clark subdivision splines on a control net: one element per (quad) face of the net, one dof per
// vertex of the net.
#include <Eigen/Core>
#include <memory>
#include <string>
#include <vector>

#include "basis/catmull_clark/ghost_net.hpp"
#include "basis/catmull_clark/irregular_patch.hpp"
#include "basis/catmull_clark/stam.hpp"
#include "basis/catmull_clark/topology.hpp"
#include "basis/geometry.hpp"
#include "basis/space.hpp"
#include "mesh/poly_mesh.hpp"

namespace iga::basis::catmull_clark {

/// The Catmull–Clark subdivision splines of a control net (any polygons; open or closed; planar or in 3D).
///
/// Boundary rule (BoundaryRule): natural, OpenSubdiv's VTX_BOUNDARY_EDGE_AND_CORNER: the limit boundary is the
/// uniform cubic B-spline of the boundary polygon, boundary vertices with a single face are interpolated
/// corners, and every function has zero second normal derivative on the boundary (u_nn = 0: L2 rate 2.5, H1
/// 1.5 for solutions with u_nn != 0). Clamped: the net is extended by one ring of ghost faces (ghost_net.hpp)
/// and the space is the extended net's restricted to the net's faces: on regular boundary parts the bicubic
/// B-splines with an open knot vector in the normal direction (full order); a boundary vertex with k faces is
/// an interior vertex of valence k + 2 of the extended net. The dofs are the extended net's vertices (the
/// net's first, then the ghosts, when no global step was needed); its functions are not interpolating on
/// the boundary (three rows of them live there; Dirichlet conditions go through TraceSpace's dependent
/// traces).
/// Regular vertices: interior with 4 faces, boundary with 2 faces, corners (1 face). Extraordinary vertices
/// (EVs): interior valence n != 4 (3..16), boundary vertices with 3..15 faces (n = faces + 1 <= 16).
///
/// If some face is not a quad, or a face touches more than one EV, a global Catmull–Clark step (OpenSubdiv
/// TopologyRefiner, see refine_net) is applied first and the refined net is the control net
/// (refinement_steps() == 1); vertex and face indices below then refer to that net. One step does not
/// always suffice: a non-quad face with an EV corner has a child touching two EVs (the vertex and the face
/// point); then a second step follows (refinement_steps() == 2). Two steps always suffice.
///
/// Elements = faces of the control net, in order. An element's corners c0..c3 are its face's vertices
/// rotated so that c0 is its EV (if any): c_i = face[(i + r) % 4]; reference u runs c0 → c1, v runs c0 → c3.
///   kind: {Quad, Regular, 4}, or {Quad, Irregular, n} at an EV (n = interior valence, or boundary faces + 1;
///   clamped: boundary faces + 2, the valence in the extended net); kind.boundary when the EV is on the
///   domain's boundary (its ring of elements is open, with either rule).
/// Every element is stored as its dofs plus an operator G from the dofs to the local control points of its
/// evaluator ("extraction"):
///   regular faces: the 4×4 bicubic B-spline grid, phantom points by linear extrapolation across the
///     boundary (reflection 2 P_b - P_in; tensor extrapolation at corners), see grid_operator;
///   faces at an interior EV with interior corners c1..c3: Stam's method (StamEvaluator, its 2n+8 points
///     gathered in its local order; see stam.hpp for its treatment of the EV point itself);
///   all other faces at an EV (boundary EVs; interior EVs whose one-ring reaches the boundary): exact
///     evaluation by repeated local subdivision with cached powers (irregular_patch.hpp); at the EV itself
///     (and max(u, v) < 2^-65) values are the limit-point stencil, derivatives are 0.
/// Boundary parts: each boundary loop (ordered as PolyMesh::boundary_loops() of the control net) is split
/// at its corners (vertices with one face) into segments named "b<loop>.<segment>"; segments are numbered
/// in loop order starting with the one that begins at the loop's first corner (first in the loop's half-edge
/// order); a loop without corners is the single part "b<loop>.0". boundary_edges() lists the boundary edges
/// part by part, each part in boundary order (domain on the left), as sides of the rotated elements.
///
/// Interior edges: one per net edge with two faces, in half-edge order of its lower half-edge; side k of an
/// element runs c_k → c_{k+1}, so the two sides of a net edge run opposite ways (t 0 → 1 on the first,
/// 1 → 0 on the second). continuity 2, or 1 where the edge ends at an EV (the space is only C1 there).
///
/// Throws InputError (prefixed by `name`) for: an isolated vertex; an interior vertex with 2 faces; an
/// interior valence above 16 or a boundary vertex with more than 15 faces; (when the global step is needed)
/// a face with more than 16 sides. UnsupportedError for a face whose one-ring cannot be unfolded into a disc
/// (tiny closed nets).
/// How faces at an interior EV whose one-ring is complete (corners c1..c3 interior) are evaluated: Stam's
/// eigenstructure (StamEvaluator, the default) or the repeated local subdivision with cached powers used for
/// every other EV face (irregular_patch.hpp). Both are exact; the choice exists for cross-checks.
enum class IrregularMethod { kStam, kSubdivision };

/// The rule at the boundary of an open net (see above); closed nets have none and both give the same space.
enum class BoundaryRule { kNatural, kClamped };
/// "natural" / "clamped"; InputError naming the accepted words for anything else.
BoundaryRule boundary_rule(const std::string& word);
std::string to_string(BoundaryRule rule);

class CatmullClarkSpace final : public Space {
 public:
  explicit CatmullClarkSpace(const mesh::PolyMesh& mesh, const std::string& name = "mesh",
                             IrregularMethod method = IrregularMethod::kStam,
                             BoundaryRule boundary = BoundaryRule::kNatural);
  /// The clamped space of an extended net (refine_extended's output; its domain all quads, at most one EV per
  /// domain face), no global step.
  CatmullClarkSpace(ExtendedNet net, const std::string& name);

  BoundaryRule boundary_rule() const { return boundary_; }

  int refinement_steps() const { return steps_; }
  /// The net whose vertices are the dofs: with the clamped rule the extended net, whose faces beyond
  /// num_elements() are the ghosts.
  const mesh::PolyMesh& control_mesh() const { return net_; }
  /// The faces that are elements (the first num_elements() of control_mesh()) as a mesh on the same vertices,
  /// with the same half-edge numbering: its boundary is the domain's.
  const mesh::PolyMesh& domain_mesh() const { return boundary_ == BoundaryRule::kClamped ? domain_ : net_; }
  /// Rotation r of element e: corner c_i is vertex face(e)[(i + r) % 4] of the control net.
  int rotation(Index e) const { return elements_[static_cast<std::size_t>(e)].rotation; }

  std::string name() const override { return "cc"; }
  Index num_dofs() const override { return net_.num_vertices(); }
  Index num_elements() const override { return static_cast<Index>(elements_.size()); }
  ElementKind kind(Index e) const override { return elements_[static_cast<std::size_t>(e)].kind; }
  /// 3 for regular faces (bicubic B-spline patches, also with extrapolated phantom points at the boundary);
  /// std::nullopt at an extraordinary vertex.
  std::optional<int> polynomial_degree(Index e) const override {
    if (kind(e).family == Family::Regular) return 3;
    return std::nullopt;
  }
  std::span<const Index> dofs(Index e) const override;
  Index max_local_dofs() const override { return max_local_dofs_; }
  void evaluate(Index e, const Eigen::Matrix2Xd& pts, int derivatives, BasisValues& out) const override;
  /// Regular elements whose 16 × dofs operators onto the bicubic B-splines are equal (a structured net numbers
  /// most interior faces alike) have the same functions.
  Index reference_element(Index e) const override { return twin_[static_cast<std::size_t>(e)]; }
  std::vector<BoundaryEdge> boundary_edges() const override { return boundary_edges_; }
  std::vector<std::string> boundary_part_names() const override { return part_names_; }
  std::vector<InteriorEdge> interior_edges() const override;
  /// Stam elements: stam_view(n) with to_points = stam_map(e); boundary-EV elements: their configuration's
  /// view on level1, shift 1, the three level-0 tiles explicit.
  std::optional<SubdivisionElement> subdivision_element(Index e) const override;

  /// For exact integration (quadrature/exact): Stam's evaluator of element e, or nullptr unless e is
  /// evaluated by Stam's method; then stam_map(e) ((2n+8) × dofs(e).size()) maps the coefficients of dofs(e)
  /// to the evaluator's local points (local points = stam_map · coefficients). irregular(e): the repeated
  /// subdivision data of the other EV elements (irregular_patch.hpp), nullptr for regular and Stam elements.
  const StamEvaluator* stam(Index e) const { return elements_[static_cast<std::size_t>(e)].stam; }
  const Eigen::MatrixXd& stam_map(Index e) const { return elements_[static_cast<std::size_t>(e)].stam_map; }
  const IrregularElement* irregular(Index e) const { return elements_[static_cast<std::size_t>(e)].irregular.get(); }

 private:
  struct Element {
    int rotation = 0;
    ElementKind kind;
    Index dof_offset = 0, num_dofs = 0;
    Eigen::MatrixXd regular;  // 16 × dofs (regular faces)
    std::unique_ptr<IrregularElement> irregular;
    const StamEvaluator* stam = nullptr;
    Eigen::MatrixXd stam_map;  // (2n+8) × dofs
  };
  void build(const std::string& name, IrregularMethod method, Index domain_faces);
  void build_elements(const std::string& name, IrregularMethod method, Index domain_faces);
  void build_boundary();
  void find_twins();

  mesh::PolyMesh net_;
  mesh::PolyMesh domain_;  // clamped: the domain faces alone
  BoundaryRule boundary_ = BoundaryRule::kNatural;
  int steps_ = 0;
  std::vector<Element> elements_;
  std::vector<Index> twin_;  // reference_element() per element
  std::vector<Index> dofs_;
  Index max_local_dofs_ = 0;
  std::vector<BoundaryEdge> boundary_edges_;
  std::vector<std::string> part_names_;
};

/// The geometry of a control net: CatmullClarkSpace + the control net's vertex positions (dim 2 when all
/// z == 0, else 3); with the clamped rule the extended net's (ghosts at their extrapolated positions).
Geometry make_catmull_clark_geometry(const mesh::PolyMesh& mesh, const std::string& name = "mesh",
                                     BoundaryRule boundary = BoundaryRule::kNatural);

/// `steps` uniform refinements of a space with its rule: the refined space and P (fine dofs × dofs).
struct SpaceRefinement {
  std::shared_ptr<const CatmullClarkSpace> space;
  Eigen::SparseMatrix<double> prolongation;
};
SpaceRefinement refine_space(const CatmullClarkSpace& space, int steps);

}  // namespace iga::basis::catmull_clark
