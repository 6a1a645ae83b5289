#pragma once
// The trace of a planar Space on (part of) its boundary as a CurveSpace, plus the sparse map from the space's
// dofs to the trace's (G+Smo's componentBasis_withIndices; DESIGN.md item 6). Generic over backends: trace
// functions are the surface functions evaluated on the boundary sides.
#include <Eigen/Sparse>
#include <memory>
#include <vector>

#include "basis/curve/curve_geometry.hpp"
#include "basis/geometry.hpp"
#include "basis/space.hpp"

namespace iga::basis {

/// Element k of the trace is edges[k]: side edges[k].side of element edges[k].element, at
/// side_point(shape, side, t), t in [0, 1] (sides run counter-clockwise on each element, so the domain lies to
/// the left of the direction of travel).
///
/// A surface function lies on the boundary when its restriction to the edges is not zero (largest sampled
/// |value| above 1e-7 of the largest over all functions). The restrictions need not be linearly independent (a
/// receding boundary, e.g. polyhedral splines, whose boundary curves depend on two rows of control points):
/// a maximal independent set S of them is chosen by rank-revealing sparse QR of their Gram matrix at sample
/// points (relative threshold 1e-10), every other one φ_j|Γ = Σ_s A_sj φ_s|Γ, and the trace functions are
/// ψ_k = φ_{S_k}|Γ, S ascending. B-spline and natural Catmull–Clark traces are independent: A is empty; the
/// clamped Catmull–Clark boundary has three rows of functions on it (A couples them). Edges of elements that are
/// not polynomial are sampled on dyadic pieces toward both ends (an extraordinary corner may sit at either).
/// Derivatives are d/dt through side_tangent; at an end of an edge where the surface evaluator gives none (the
/// Catmull–Clark limit stencil at an extraordinary vertex) they are those of the degree-9 interpolant of the
/// edge's traces at Chebyshev points (exact for polynomial traces of degree <= 9, e.g. the cubic boundary curves).
class TraceSpace : public CurveSpace {
 public:
  /// InputError for an empty edge list or an edge naming an element or side that does not exist;
  /// NumericalError when a dependent restriction is not in the span of the independent ones.
  TraceSpace(std::shared_ptr<const Space> space, std::vector<BoundaryEdge> edges);

  Index num_dofs() const override { return static_cast<Index>(surface_dofs_.size()); }
  Index num_elements() const override { return static_cast<Index>(edges_.size()); }
  std::span<const Index> dofs(Index e) const override;
  Index max_local_dofs() const override { return max_local_; }
  void evaluate(Index e, const Eigen::VectorXd& t, int derivatives, CurveBasisValues& out) const override;

  const Space& surface() const { return *space_; }
  const BoundaryEdge& edge(Index e) const { return edges_[static_cast<std::size_t>(e)]; }
  /// The surface dof S_k of each trace function ψ_k (ascending).
  const std::vector<Index>& surface_dofs() const { return surface_dofs_; }
  /// R (num_dofs() × surface num_dofs()): the restriction of u = Σ_i u_i φ_i to the edges is Σ_k (R u)_k ψ_k.
  /// R(k, S_k) = 1 and R(k, j) = A_{S_k j} for the dependent functions j.
  const Eigen::SparseMatrix<double, Eigen::RowMajor>& restriction() const { return restriction_; }
  /// The dependent part alone: A (num_dofs() × surface num_dofs(), zero on the S columns); empty (no non-zeros)
  /// when the restrictions are independent.
  const Eigen::SparseMatrix<double, Eigen::RowMajor>& dependent() const { return dependent_; }

 private:
  // t-derivatives of element e's functions at point k (t = 0 or 1) from the edge's interpolant at sample points.
  void end_derivatives(Index e, Index k, double t, int derivatives, CurveBasisValues& out) const;

  std::shared_ptr<const Space> space_;
  std::vector<BoundaryEdge> edges_;
  std::vector<Index> surface_dofs_;
  std::vector<Index> dof_offsets_, local_dofs_;  // element e: local_dofs_[dof_offsets_[e] .. dof_offsets_[e+1])
  std::vector<Index> local_rows_;                // the surface element's local row of each trace dof, same layout
  Index max_local_ = 0;
  Eigen::SparseMatrix<double, Eigen::RowMajor> restriction_, dependent_;
};

/// The boundary of a planar geometry as a curve: the TraceSpace on some of its boundary edges and the curve with
/// control points R P (the geometry map restricted to the edges).
struct BoundaryTrace {
  std::shared_ptr<const TraceSpace> space;
  CurveGeometry curve;
};
/// On `edges` (every boundary edge of the space when empty). InputError for a surface (dim 3) geometry.
BoundaryTrace trace_geometry(const Geometry& geometry, std::vector<BoundaryEdge> edges = {});

}  // namespace iga::basis
