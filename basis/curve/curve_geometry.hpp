#pragma once
// A planar curve: a CurveSpace plus 2D control points, with its elements chained into loops (outer boundary
// and holes) and the corners where they meet.
#include <Eigen/Core>
#include <memory>
#include <vector>

#include "basis/curve/curve_space.hpp"

namespace iga::basis {

/// Map data at a batch of q parameters of one element.
struct CurvePoints {
  Eigen::Matrix2Xd x;       ///< physical points
  Eigen::Matrix2Xd dx;      ///< dx/dt
  Eigen::Matrix2Xd ddx;     ///< d²x/dt² (derivatives 2 only)
  Eigen::VectorXd speed;    ///< |dx/dt|: the arc-length element ds = speed dt
  Eigen::Matrix2Xd normal;  ///< (dy, −dx)/|dx|: outward when the domain lies to the left of the direction of travel
};

/// Elements joined end to start: elements[k + 1] begins where elements[k] ends. A closed loop also returns
/// from its last element to its first.
struct CurveLoop {
  std::vector<Index> elements;
  bool closed = true;
};

class CurveGeometry {
 public:
  /// control_points: space->num_dofs() × 2. Chains the elements into loops by matching each element's end
  /// point x(1) with another's start x(0) to 1e-9 of the curve's bounding-box diagonal. InputError on a size
  /// mismatch, non-finite coordinates, or an end point shared by more than one start (a branching curve).
  CurveGeometry(std::shared_ptr<const CurveSpace> space, Eigen::MatrixXd control_points);

  const CurveSpace& space() const { return *space_; }
  const std::shared_ptr<const CurveSpace>& space_ptr() const { return space_; }
  const Eigen::MatrixXd& control_points() const { return control_points_; }
  Index num_elements() const { return space_->num_elements(); }

  /// Points, derivatives and normals of element e at parameters t (derivatives 1 or 2). NumericalError naming
  /// the element and parameter where dx/dt = 0 (no normal).
  void evaluate(Index e, const Eigen::VectorXd& t, CurvePoints& out, int derivatives = 1) const;
  Eigen::Vector2d point(Index e, double t) const;

  /// The loops in a fixed order: each starts at its lowest-numbered element (open chains at their free start).
  const std::vector<CurveLoop>& loops() const { return loops_; }
  /// The element that begins where e ends, or -1 at the free end of an open chain; previous() likewise.
  Index next(Index e) const { return next_[static_cast<std::size_t>(e)]; }
  Index previous(Index e) const { return previous_[static_cast<std::size_t>(e)]; }
  /// The domain's interior angle in (0, 2π) at the end of element e, where it meets next(e): π − the turning
  /// angle of the tangent (π at a smooth joint, π/2 at a convex right-angle corner, 3π/2 at a reflex one).
  /// NaN at the free end of an open chain.
  double interior_angle(Index e) const;
  /// Whether the joint at the end of e is a corner: |interior_angle(e) − π| > tolerance (radians).
  bool corner_at_end(Index e, double tolerance = 1e-8) const;
  /// Arc length of element e (composite 5-point Gauss, 8 pieces: relative error below 1e-12 for smooth
  /// elements of moderate curvature).
  double length(Index e) const;
  /// Diagonal of the bounding box of the elements' sampled points.
  double diameter() const { return diameter_; }
  /// Signed area enclosed by the closed loops, ½ ∮ (x dy − y dx) summed over them: positive when every loop
  /// has the domain on its left (outer loop counter-clockwise, holes clockwise).
  double signed_area() const;
  /// ½ ∮ (x dy − y dx) over loop k alone (0 for an open chain): positive counter-clockwise.
  double loop_area(std::size_t k) const;

 private:
  std::shared_ptr<const CurveSpace> space_;
  Eigen::MatrixXd control_points_;
  std::vector<CurveLoop> loops_;
  std::vector<Index> next_, previous_;
  double diameter_ = 0.0;
};

}  // namespace iga::basis
