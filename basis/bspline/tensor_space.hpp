#pragma once
// Tensor-product B-spline space on one patch, evaluated by Bézier extraction, batched over points.
#include <Eigen/Core>
#include <Eigen/Sparse>
#include <algorithm>
#include <vector>

#include "basis/bspline/knot_vector.hpp"
#include "basis/space.hpp"

namespace iga::basis::bspline {

/// Functions N_i(u) M_j(v), global dof i + nu * j. Elements are the products of the non-empty knot
/// intervals, element index ex + nex * ey, each mapped to the unit square: reference (s, t) is
/// u = a_x + s (b_x - a_x), v = a_y + t (b_y - a_y). Derivatives are with respect to (s, t).
/// Boundary parts: 0 "v0" (v = v_min, side 0), 1 "u1" (u = u_max, side 1), 2 "v1" (side 2), 3 "u0" (side 3).
/// Interior edges: first the knot lines u = const (element ex side 1 against ex + 1 side 3, row by row), then
/// v = const (element side 2 against the one above, side 0); continuity = degree − multiplicity of the knot
/// in that direction (a knot of multiplicity p gives 0).
class TensorSpace final : public Space {
 public:
  TensorSpace(KnotVector u, KnotVector v);

  std::string name() const override { return "bspline"; }
  Index num_dofs() const override { return nu_ * nv_; }
  Index num_elements() const override { return nex_ * ney_; }
  ElementKind kind(Index) const override { return {}; }
  /// max(p_u, p_v): every element is a polynomial patch.
  std::optional<int> polynomial_degree(Index) const override { return std::max(u_.degree(), v_.degree()); }
  /// Knot intervals whose extraction operators agree to 1e-14 have the same functions: all but p − 1 at each end of
  /// a uniform knot vector (the operator depends on the ratios of the 2p − 1 spans around the interval).
  Index reference_element(Index e) const override;
  std::span<const Index> dofs(Index e) const override;
  Index max_local_dofs() const override { return nloc_; }
  void evaluate(Index e, const Eigen::Matrix2Xd& pts, int derivatives, BasisValues& out) const override;
  std::vector<BoundaryEdge> boundary_edges() const override;
  std::vector<std::string> boundary_part_names() const override { return {"v0", "u1", "v1", "u0"}; }
  /// Vertical edges (between ex and ex + 1) row by row, then horizontal ones; continuity = degree − multiplicity
  /// of the knot line.
  std::vector<InteriorEdge> interior_edges() const override;

  const KnotVector& knots_u() const { return u_; }
  const KnotVector& knots_v() const { return v_; }
  Index num_basis_u() const { return nu_; }
  Index num_basis_v() const { return nv_; }
  Index num_elements_u() const { return nex_; }
  Index num_elements_v() const { return ney_; }
  /// Knot-parameter rectangle of element e: (u_a, u_b, v_a, v_b).
  Eigen::Vector4d element_box(Index e) const;

 private:
  KnotVector u_, v_;
  Index nu_ = 0, nv_ = 0, nex_ = 0, ney_ = 0, nloc_ = 0;
  std::vector<Eigen::MatrixXd> cu_, cv_;  // extraction operators per interval
  std::vector<Index> twin_u_, twin_v_;    // the lowest interval with the same operator, per interval
  std::vector<Index> dofs_;               // nloc_ per element
};

/// Values and (s, t)-derivatives of the (pu+1)(pv+1) tensor-product B-splines of one knot-interval product
/// from its extraction operators cu, cv (extraction.hpp) at reference points on the unit square, local index
/// a + (pu+1) b: Bernstein values (cached per thread for repeated point sets) times the operators.
void evaluate_bezier_tensor(const Eigen::MatrixXd& cu, const Eigen::MatrixXd& cv, const Eigen::Matrix2Xd& pts,
                            int derivatives, BasisValues& out);

/// The space as a tensor-product B-spline space, or nullptr when it is another backend's (for algorithms that
/// work on knot vectors, such as refine::refine_smooth_tensor).
const TensorSpace* tensor_space(const Space& space);

/// Refinement matrix between two tensor spaces whose knot vectors are nested in each direction:
/// kron(R_v, R_u), so fine control points = R * coarse control points.
Eigen::SparseMatrix<double> refinement_matrix(const TensorSpace& coarse, const TensorSpace& fine);

}  // namespace iga::basis::bspline
