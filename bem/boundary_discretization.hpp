#pragma once
// The discretisation of collocation BEM on a planar boundary (thesis §4.3.2, §4.3.4): segments, the spline
// space of u and q, BEM elements and collocation points.
//
// Segments: each closed loop of the curve is split at its corners (interior angle ≠ π beyond
// corner_tolerance) and where the boundary condition changes; a loop without such points is one periodic
// segment (or, when it has fewer than degree + 1 BEM elements, one open segment starting at its first
// element). Every curve element is split into 2^refine BEM elements of equal parameter length. u and q both
// live in SplineCurveSpace(degree, segments): C^{p−1} inside a segment, discontinuous between segments (at
// corners and condition changes both u and q have one dof on each side: discontinuous collocation).
// With Joints::Split every joint between curve elements is a segment end as well. That is for curves that are
// less smooth at their joints than the BEM splines (C^{p−1}): the trace of a Catmull–Clark or cubic B-spline
// geometry is C² at its joints, so its normal, and with it q = ∇u·n, is only C¹ there, and C² splines of degree
// p = 3 approximate q at the rate 2.5 instead of 4; split, every curve element carries polynomials of degree p.
//
// Collocation: one point per dof, at its Greville abscissa (Collocation::Greville) or at the maximum of its
// B-spline (Collocation::Maxima) in the segment parameter. On an open segment the first and the last point
// (which lie on the segment's end, i.e. on a corner) are moved half way to their neighbour (a third of the way
// when the segment has only two dofs), so no collocation point sits on a corner or a condition change.
//
// Scaling: the single-layer operator is singular when the logarithmic capacity of the boundary is 1. The
// discretisation therefore keeps a copy of the curve scaled by scale() = 1 / (2 diameter) (the bounding-box
// diagonal becomes 1/2, so the capacity is at most 1/4). H, G and the solver work in these internal
// coordinates; every input (curve, boundary data, interior points) and every output (u, q, errors) is in the
// user's units: u is unchanged by the scaling, q = ∂u/∂n (user) = scale · ∂u/∂n (internal).
#include <Eigen/Core>
#include <memory>
#include <utility>
#include <vector>

#include "basis/curve/curve_geometry.hpp"
#include "basis/curve/spline_curve_space.hpp"

namespace iga::bem {

enum class Collocation { Greville, Maxima };
/// Smoothness of the BEM splines across the joints of curve elements that are neither corners nor condition
/// changes: C^{p−1} (Smooth, the isogeometric choice) or none (Split: segments end there too).
enum class Joints { Smooth, Split };

/// Boundary condition of a curve element (and of the dofs of its segment).
inline constexpr int kDirichlet = 0;
inline constexpr int kNeumann = 1;

struct DiscretizationOptions {
  int degree = 2;
  int refine = 0;  ///< each curve element is split into 2^refine BEM elements
  Collocation collocation = Collocation::Greville;
  double corner_tolerance = 1e-8;  ///< radians
  Joints joints = Joints::Smooth;
};

/// A BEM element: the parameter sub-interval [a, b] ⊂ [0, 1] of one curve element.
struct BemElement {
  Index curve_element = 0;
  double a = 0.0, b = 1.0;
};

/// A collocation point: BEM element and its parameter t ∈ (0, 1) (or an end), the same point as curve
/// element and curve parameter, and its physical position in user units.
struct CollocationPoint {
  Index element = 0;
  double t = 0.0;
  Index curve_element = 0;
  double curve_t = 0.0;
  Eigen::Vector2d x = Eigen::Vector2d::Zero();
};

/// A segment: its curve elements in the direction of travel, whether it is periodic, its condition.
struct BemSegment {
  std::vector<Index> curve_elements;
  bool closed = false;
  int condition = kDirichlet;
};

class BoundaryDiscretization {
 public:
  /// condition: one entry per curve element, kDirichlet (0) or kNeumann (1). InputError on a size mismatch, an
  /// unknown condition, an open loop (the boundary must be closed), degree < 1 or refine outside 0..20.
  BoundaryDiscretization(const basis::CurveGeometry& curve, std::vector<int> condition,
                         const DiscretizationOptions& options = {});

  const DiscretizationOptions& options() const { return options_; }
  /// The curve in user units, and the same curve in internal coordinates (control points × scale()).
  const basis::CurveGeometry& curve() const { return curve_; }
  const basis::CurveGeometry& scaled_curve() const { return scaled_; }
  double scale() const { return scale_; }

  const basis::SplineCurveSpace& space() const { return *space_; }
  const std::shared_ptr<const basis::SplineCurveSpace>& space_ptr() const { return space_; }
  Index num_dofs() const { return space_->num_dofs(); }
  Index num_elements() const { return space_->num_elements(); }
  const BemElement& element(Index e) const { return elements_[static_cast<std::size_t>(e)]; }
  const std::vector<BemSegment>& segments() const { return segments_; }

  int dof_condition(Index j) const { return dof_condition_[static_cast<std::size_t>(j)]; }
  const std::vector<int>& dof_conditions() const { return dof_condition_; }
  const std::vector<CollocationPoint>& collocation_points() const { return points_; }

  /// The BEM element containing curve parameter t of curve element ce, and its parameter there.
  std::pair<Index, double> locate(Index curve_element, double t) const;

 private:
  void build_segments(const std::vector<int>& condition);
  void build_collocation();

  DiscretizationOptions options_;
  basis::CurveGeometry curve_, scaled_;
  double scale_ = 1.0;
  std::vector<BemSegment> segments_;
  std::shared_ptr<const basis::SplineCurveSpace> space_;
  std::vector<BemElement> elements_;
  std::vector<Index> first_bem_element_;  // per curve element: its first BEM element
  std::vector<int> dof_condition_;
  std::vector<CollocationPoint> points_;
};

}  // namespace iga::bem
