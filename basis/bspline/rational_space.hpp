#pragma once
// NURBS: the rational tensor-product B-spline space of one patch (Piegl & Tiller, The NURBS Book, §4.2-4.5).
#include <Eigen/Core>
#include <Eigen/Sparse>
#include <memory>

#include "basis/bspline/tensor_space.hpp"
#include "basis/geometry.hpp"

namespace iga::basis::bspline {

/// R_i = w_i N_i / W with W = Σ_j w_j N_j over a TensorSpace's functions N_i and positive weights w_i: the same
/// elements, dofs, boundary parts and interior edges as the tensor space, and the rational functions (a partition
/// of unity) as its basis. A geometry over it with control points P_i is the NURBS map Σ R_i P_i: conics (circles)
/// exactly. Derivatives by the quotient rule (The NURBS Book, eq. 4.8 and its second-order analogue), with
/// respect to the element's reference coordinates as for TensorSpace.
/// The name is the tensor space's ("bspline"): it is a B-spline backend space with weights.
class RationalSpace final : public Space {
 public:
  /// InputError when the weights are not one finite, positive number per function.
  RationalSpace(std::shared_ptr<const TensorSpace> base, Eigen::VectorXd weights);

  std::string name() const override { return base_->name(); }
  Index num_dofs() const override { return base_->num_dofs(); }
  Index num_elements() const override { return base_->num_elements(); }
  ElementKind kind(Index e) const override { return base_->kind(e); }
  /// std::nullopt: rational functions are not polynomials (rational_form() says what they are).
  std::optional<int> polynomial_degree(Index) const override { return std::nullopt; }
  /// max(p_u, p_v) and the weights of the element's dofs.
  std::optional<RationalForm> rational_form(Index e) const override;
  std::span<const Index> dofs(Index e) const override { return base_->dofs(e); }
  Index max_local_dofs() const override { return base_->max_local_dofs(); }
  void evaluate(Index e, const Eigen::Matrix2Xd& pts, int derivatives, BasisValues& out) const override;
  /// The B-spline space's twins: they share B-spline values (evaluate_reference), and each element divides by its
  /// own weight function (from_reference).
  Index reference_element(Index e) const override { return base_->reference_element(e); }
  void evaluate_reference(Index twin, const Eigen::Matrix2Xd& pts, int derivatives, BasisValues& out) const override {
    base_->evaluate(twin, pts, derivatives, out);
  }
  void from_reference(Index e, const BasisValues& reference, int derivatives, BasisValues& out) const override;
  std::vector<BoundaryEdge> boundary_edges() const override { return base_->boundary_edges(); }
  std::vector<std::string> boundary_part_names() const override { return base_->boundary_part_names(); }
  std::vector<InteriorEdge> interior_edges() const override { return base_->interior_edges(); }

  const TensorSpace& base() const { return *base_; }
  const std::shared_ptr<const TensorSpace>& base_ptr() const { return base_; }
  const Eigen::VectorXd& weights() const { return weights_; }

 private:
  std::shared_ptr<const TensorSpace> base_;
  Eigen::VectorXd weights_;
};

/// The space as a NURBS space, or nullptr.
const RationalSpace* rational_space(const Space& space);

/// A NURBS geometry: control points (nu*nv) × dim and weights (nu*nv), index i + nu*j.
Geometry make_rational_patch(KnotVector u, KnotVector v, Eigen::MatrixXd control_points, Eigen::VectorXd weights);

/// Refinement of a NURBS patch to a finer nested B-spline space, given the B-spline refinement matrix R (fine
/// B-spline coefficients = R × coarse ones: knot insertion, refine-and-smooth): fine weights R w, fine control points
/// (R (w ∘ P)) / (R w) (homogeneous coordinates), and the prolongation of coefficients W_f⁻¹ R W_c
/// (W = diag(weights)): the coarse rational functions are these combinations of the fine ones. Returns the fine
/// geometry and sets *prolongation.
Geometry refine_rational(const Geometry& coarse, std::shared_ptr<const TensorSpace> fine_base,
                         const Eigen::SparseMatrix<double>& r, Eigen::SparseMatrix<double>* prolongation);

}  // namespace iga::basis::bspline
