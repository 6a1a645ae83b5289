#pragma once
// What exact integration sees of an infinitely piecewise element, whatever its subdivision scheme (DESIGN.md,
// "Where the joints must widen next", item 3; thesis §4.2.1): polynomial tiles whose control points come from
// powers of a subdivision matrix. Catmull–Clark (bicubic tiles on the square) and half-box (cubic triangles)
// elements both offer it through Space::subdivision_element(); quadrature/exact uses nothing else.
#include <Eigen/Core>
#include <array>
#include <functional>
#include <vector>

#include "basis/basis_values.hpp"
#include "basis/element_kind.hpp"

namespace iga::basis {

/// One polynomial tile: on it the element's functions are φ(x) = Hᵀ(t(x)) · points, H the r functions of the
/// scheme's regular patch on its reference domain and t(x) = jacobian · x + offset the affine map from the tile
/// (in element coordinates, on layer 1 for the tiles of a view) onto that domain.
struct PatchTile {
  Eigen::MatrixXd points;    ///< r × (the points the tile is expressed in)
  Eigen::Matrix2d jacobian;  ///< dt/dx
};

/// The repeating structure of one configuration (one valence, or one boundary configuration): layer l >= 1 of
/// the element is made of the tiles of layer 1 scaled by 2^-(l-1) (x ↦ 2^(l-1) x before the tile map), whose
/// points are tiles[k].points · A^(l-1) times the m points of the first layer.
struct SubdivisionView {
  Shape patch_shape = Shape::Quad;  ///< the regular patch's reference domain (unit square or unit triangle)
  int patch_degree = 3;             ///< its polynomial degree per direction (quad) or total degree (triangle)
  /// Values and first derivatives (d/dt) of the r patch functions at points of the patch domain (r × q).
  std::function<void(const Eigen::Matrix2Xd&, int derivatives, BasisValues&)> patch_functions;
  Eigen::MatrixXd subdivision;  ///< A (m × m)
  Eigen::VectorXd limit;        ///< w with wᵀ A = wᵀ, Σ w = 1 (the limit-point stencil)
  std::array<PatchTile, 3> tiles;  ///< the tiles of layer 1, points r × m
};

/// An infinitely piecewise element: explicit tiles first (points in terms of the element's dofs), then the
/// view's layers on the points to_points · (dof coefficients), scaled by 2^-shift (the view's layer l is the
/// element's layer l + shift). Interior Catmull–Clark and half-box elements: no explicit tiles, shift 0;
/// Catmull–Clark elements at boundary extraordinary vertices: the three tiles of level 0, shift 1.
struct SubdivisionElement {
  const SubdivisionView* view = nullptr;  ///< valid for the program's lifetime (cached by the backend)
  Eigen::MatrixXd to_points;              ///< m × dofs(e)
  int shift = 0;
  std::vector<PatchTile> explicit_tiles;  ///< points r × dofs(e)
};

}  // namespace iga::basis
