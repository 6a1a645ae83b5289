#pragma once
// Tensor-product Bernstein–Bézier patches of the polyhedral spline: the regular bi-2 patch (paper, eq. (2)
// re-expressed in BB form (3)), Bernstein degree elevation (bi-2 → bi-3, (3,2) → (3,3)) and evaluation.
//
// Coefficient layout (as PatchMask in mask.hpp): BB coefficient b_ij (i along u = 0..degree_u, j along v)
// is row j·(degree_u + 1) + i. Parameters (u, v) ∈ [0,1]² (the patch's own domain); derivatives are with
// respect to (u, v).
#include <Eigen/Core>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "basis/polyhedral/mask.hpp"
#include "basis/space.hpp"

namespace iga::basis::polyhedral {

/// A patch: its degrees and BB coefficients ((degree_u+1)(degree_v+1) rows, one column per coordinate — or,
/// for a mask, per gathered vertex).
struct BezierPatch {
  int degree_u = 3;
  int degree_v = 3;
  Eigen::MatrixXd coefficients;
};

/// The Regular configuration's mask: the uniform bi-2 B-spline piece over the dual face of the centre v
/// (eq. (2)) in BB form, 9 rows × 9 gathered vertices in the Regular gather order [v, e_0, f_0, …, e_3, f_3].
/// u runs from e_2 toward e_0 and v from e_3 toward e_1; the control point grid (i, j) (i along u) is
/// f_2 e_3 f_3 / e_2 v e_0 / f_1 e_1 f_0 for j = 0, 1, 2. Closed form per direction: with B-spline control
/// points c_0, c_1, c_2 the BB coefficients are ((c_0 + c_1)/2, c_1, (c_1 + c_2)/2).
PatchMask regular_mask();

/// Univariate Bernstein degree elevation p → q (q >= p): E ((q+1) × (p+1)), b' = E b. One step p → p+1 is
/// b'_i = (i/(p+1)) b_{i−1} + (1 − i/(p+1)) b_i.
Eigen::MatrixXd elevation_matrix(int p, int q);

/// The coefficients of the same polynomial patch in degree (target_u, target_v) (each >= the current one).
/// Works on any number of columns (points or mask columns). InputError if a target is below the degree or
/// the row count does not match the degrees.
BezierPatch elevate(const BezierPatch& patch, int target_u, int target_v);
PatchMask elevate(const PatchMask& mask, int target_u, int target_v);

/// Tensor Bernstein basis values at points pts (2 × q, (u, v) ∈ [0,1]²): rows = coefficient index
/// j·(degree_u+1)+i, columns = points, for the derivative ∂^order_u/∂u ∂^order_v/∂v (orders 0..2).
Eigen::MatrixXd bernstein_tensor(int degree_u, int degree_v, const Eigen::Matrix2Xd& pts, int order_u, int order_v);

/// Positions and parametric derivatives of a patch at points (each q × columns of coefficients).
struct PatchValues {
  Eigen::MatrixXd x, xu, xv;        ///< filled for derivatives >= 0, >= 1
  Eigen::MatrixXd xuu, xuv, xvv;    ///< filled for derivatives >= 2
};
PatchValues evaluate(const BezierPatch& patch, const Eigen::Matrix2Xd& pts, int derivatives);

/// The Bernstein "super space" of a list of patches: element e is patch e on [0,1]², and its
/// (degree_u+1)(degree_v+1) tensor Bernstein polynomials are its own dofs (first_dof(e), …, in the coefficient
/// layout above), shared with no other element — a discontinuous space. A Geometry over it whose control
/// points are the patches' BB coefficients is the patchwork surface itself, which is how patches are sampled
/// for output (io/vtu_writer) before a smooth space is assembled. It has no boundary edges.
class BezierPatchSpace final : public Space {
 public:
  /// degrees: (degree_u, degree_v) per patch (each 1..30); kinds: one per patch.
  BezierPatchSpace(std::vector<std::pair<int, int>> degrees, std::vector<ElementKind> kinds);

  std::string name() const override { return "bezier-patches"; }
  Index num_dofs() const override { return offsets_.back(); }
  Index num_elements() const override { return static_cast<Index>(degrees_.size()); }
  ElementKind kind(Index e) const override { return kinds_[static_cast<std::size_t>(e)]; }
  std::span<const Index> dofs(Index e) const override;
  Index max_local_dofs() const override { return max_local_; }
  void evaluate(Index e, const Eigen::Matrix2Xd& pts, int derivatives, BasisValues& out) const override;
  std::vector<BoundaryEdge> boundary_edges() const override { return {}; }
  std::vector<std::string> boundary_part_names() const override { return {}; }
  Index first_dof(Index e) const { return offsets_[static_cast<std::size_t>(e)]; }

 private:
  std::vector<std::pair<int, int>> degrees_;
  std::vector<ElementKind> kinds_;
  std::vector<Index> offsets_;  // size elements + 1
  std::vector<Index> dofs_;     // 0 .. num_dofs − 1
  Index max_local_ = 0;
};

}  // namespace iga::basis::polyhedral
