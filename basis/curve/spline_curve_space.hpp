#pragma once
// B-spline spaces on a sequence of curve segments: the discretisation space of collocation BEM (thesis §4.3.4,
// IgABEM). Each segment k carries degree-p B-splines on uniform integer knots over its segment parameter
// s in [0, elements_k]; element i of the segment is s in [i, i + 1], with element parameter t = s − i in [0, 1].
// Open segments are clamped (elements + p dofs, interpolating at both ends), closed segments periodic
// (elements dofs, C^{p−1} across s = 0 ≡ elements). Segments share no dofs: a spline on them is discontinuous
// from one segment to the next.
#include <vector>

#include "basis/curve/curve_space.hpp"

namespace iga::basis {

struct SplineSegment {
  Index elements = 1;
  bool closed = false;
};

class SplineCurveSpace : public CurveSpace {
 public:
  /// degree >= 1, every segment with elements >= 1, and closed segments with elements >= degree + 1
  /// (InputError otherwise).
  SplineCurveSpace(int degree, std::vector<SplineSegment> segments);

  int degree() const { return degree_; }
  const std::vector<SplineSegment>& segments() const { return segments_; }
  Index num_segments() const { return static_cast<Index>(segments_.size()); }

  Index num_dofs() const override { return num_dofs_; }
  Index num_elements() const override { return static_cast<Index>(element_segment_.size()); }
  /// Local order: the segment's dofs in increasing segment-local index (for periodic segments starting from
  /// the function that begins p elements to the left, wrapped modulo the segment's dof count).
  std::span<const Index> dofs(Index e) const override;
  Index max_local_dofs() const override { return degree_ + 1; }
  void evaluate(Index e, const Eigen::VectorXd& t, int derivatives, CurveBasisValues& out) const override;

  /// The segment of element e and its index within that segment.
  Index segment_of(Index e) const { return element_segment_[static_cast<std::size_t>(e)]; }
  Index index_in_segment(Index e) const { return e - first_element(segment_of(e)); }
  /// Global number of the segment's first element and first dof; its dof count.
  Index first_element(Index segment) const { return first_element_[static_cast<std::size_t>(segment)]; }
  Index first_dof(Index segment) const { return first_dof_[static_cast<std::size_t>(segment)]; }
  Index segment_dofs(Index segment) const;
  /// Greville abscissae of the segment's dofs, in segment parameter s (ascending for open segments; for a
  /// periodic segment dof j has s = j + (p + 1)/2 reduced modulo the element count, so the order follows the
  /// dofs, not the parameter).
  Eigen::VectorXd greville(Index segment) const;
  /// Segment-local function j of segment `segment` (and its first and second derivative in s) at segment
  /// parameter s (periodic segments: s taken modulo the element count).
  Eigen::Vector3d function(Index segment, Index j, double s) const;

 private:
  int degree_;
  std::vector<SplineSegment> segments_;
  Index num_dofs_ = 0;
  std::vector<Index> element_segment_, first_element_, first_dof_;
  std::vector<Index> dofs_;  // (p + 1) per element
};

}  // namespace iga::basis
