#pragma once
// The Bézier cell of one shape and degree as VTK stores it (VTK_BEZIER_QUADRILATERAL, VTK_BEZIER_TRIANGLE), and the
// interpolation that gives its control points from values at nodes (used by bezier_writer.cpp).
#include <Eigen/Core>
#include <Eigen/LU>
#include <array>
#include <vector>

#include "basis/element_kind.hpp"

namespace iga::io {

/// Cell point k (VTK's order, from vtkHigherOrderQuadrilateral::PointIndexFromIJK and
/// vtkHigherOrderTriangle::Index) is the Bernstein coefficient with lattice index lattice[k] = (i, j):
///  - Quad, degree d: B_i^d(u) B_j^d(v), 0 <= i, j <= d;
///  - Triangle, degree d: d! / (i! j! k!) u^i v^j (1 − u − v)^k, k = d − i − j (VTK's barycentric index (i, j, k)).
/// (u, v) are the reference coordinates of basis::side_point and VTK's parametric coordinates (r, s) alike.
///
/// nodes.col(k) is the interpolation node of point k: the tensor grid (t_i, t_j) of the Chebyshev–Lobatto points
/// t_i = (1 − cos(iπ/d)) / 2 (made exactly symmetric: t_{d−i} = 1 − t_i) on the square; the uniform lattice
/// (i/d, j/d) on the triangle. Both include the element's sides, and the nodes on a side are symmetric about its
/// midpoint, so two elements that share a side and a degree take the same nodes on it. Control points from values
/// at the nodes: control = collocation.solve(values), with collocation(k, m) = (Bernstein function m)(node k) —
/// exact (to round-off) for a polynomial of the cell's degree; for any other function the unique Bézier cell that
/// interpolates it at the nodes, whose side curves depend only on the values on that side.
struct BezierLayout {
  basis::Shape shape = basis::Shape::Quad;
  int degree = 1;
  std::vector<std::array<int, 2>> lattice;
  Eigen::Matrix2Xd nodes;
  std::vector<bool> on_side;  ///< point k lies on a side of the element
  Eigen::PartialPivLU<Eigen::MatrixXd> collocation;

  int num_points() const { return static_cast<int>(lattice.size()); }
  /// The cell points along side s (basis::side_point numbering), in the side's direction, both corners included.
  std::vector<int> side_points(int side) const;
  /// Values of the cell's Bernstein functions (rows, in point order) at reference points pts (2 × q).
  Eigen::MatrixXd bernstein(const Eigen::Matrix2Xd& pts) const;
  /// VTK_BEZIER_QUADRILATERAL or VTK_BEZIER_TRIANGLE.
  unsigned char vtk_type() const;
};

/// The layout of a shape and degree (1 <= degree <= kMaxBezierDegree), built and factored once; thread-safe.
/// InputError for a degree out of range.
constexpr int kMaxBezierDegree = 16;
const BezierLayout& bezier_layout(basis::Shape shape, int degree);

/// Index of VTK_BEZIER_CURVE point k of a degree-d curve in the side order of BezierLayout::side_points: VTK lists
/// the two ends first, then the interior points in order.
int curve_point_order(int degree, int k);

}  // namespace iga::io
