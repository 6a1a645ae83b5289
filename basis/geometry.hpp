#pragma once
// A space plus control points: the isogeometric map from each element's reference domain to the physical
// domain (a planar region, dim 2, or a surface in 3D, dim 3).
#include <Eigen/Core>
#include <memory>
#include <string>

#include "basis/space.hpp"

namespace iga::basis {

/// Map data at a batch of q points of one element. Physical quantities are always 3 × q (z = 0 for planar).
struct GeometryValues {
  Eigen::Matrix3Xd x;       ///< physical points
  Eigen::Matrix3Xd xu, xv;  ///< parametric derivatives of the map, columns of the Jacobian J (3 × 2)
  Eigen::VectorXd measure;  ///< sqrt(det(J^T J)): |det J| for planar domains, the surface element otherwise
  Eigen::Matrix3Xd normal;  ///< unit normal (x_u × x_v)/|x_u × x_v|; ±e_z for planar domains
  /// Gradient transform T = J G^{-1} with G = J^T J: the physical (surface) gradient of a function with
  /// parametric derivatives (f_u, f_v) is tu * f_u + tv * f_v.
  Eigen::Matrix3Xd tu, tv;
  Eigen::Matrix3Xd xuu, xuv, xvv;  ///< second parametric derivatives of the map (when asked for: derivatives 2)
};

class Geometry {
 public:
  /// control_points: num_dofs × dim, dim 2 (planar) or 3 (surface). Throws InputError on a size mismatch
  /// or non-finite coordinates.
  Geometry(std::shared_ptr<const Space> space, Eigen::MatrixXd control_points);
  /// The map of `same_map` in a space that contains its space (control_points: its coefficients there, e.g.
  /// prolongated by a refinement): the same map, so its orientation carries over instead of being sampled again
  /// over every element. The caller vouches for the sameness.
  Geometry(std::shared_ptr<const Space> space, Eigen::MatrixXd control_points, const Geometry& same_map);

  const Space& space() const { return *space_; }
  const std::shared_ptr<const Space>& space_ptr() const { return space_; }
  int dim() const { return static_cast<int>(control_points_.cols()); }
  const Eigen::MatrixXd& control_points() const { return control_points_; }
  /// Element e's control points in dofs(e) order (dofs × dim).
  Eigen::MatrixXd element_points(Index e) const;
  /// Planar geometries: +1 when det J > 0 (a counter-clockwise map, as a net whose faces are listed
  /// counter-clockwise gives), −1 when det J < 0 (clockwise), decided by the majority of the elements' centres;
  /// evaluation refuses points of the other sign (a fold). Surfaces: +1.
  int orientation() const { return orientation_; }

  /// Map data of element e from basis values already evaluated there (derivatives >= 1).
  /// With check, throws NumericalError naming the element and the physical point when the map is degenerate
  /// there (|x_u × x_v| below 1e-12 of the element's largest derivative squared, so independent of the units)
  /// or, for a planar domain, when the sign of det J is not orientation(): the map folds over. Without check (output,
  /// which samples element edges and extraordinary vertices), such points get tu = tv = 0, and only a clear
  /// fold (det J below −1e-12 of the scale) throws.
  /// With derivatives = 2 (basis evaluated with second derivatives) also xuu, xuv, xvv.
  void evaluate(Index e, const BasisValues& basis, GeometryValues& out, bool check = true, int derivatives = 1) const;
  /// Convenience: evaluates the basis first.
  void evaluate(Index e, const Eigen::Matrix2Xd& pts, GeometryValues& out) const;
  /// What a solver would refuse in this map, as the message evaluate() with check gives at the first element
  /// where it does ("element 5: det J = ... folds over at (x, y)", a degenerate or overflowing map), or empty when
  /// every element is valid at its 4 × 4 Gauss points (the points of a program's default rule, or of any rule of
  /// that size): for programs that show a geometry without solving on it (iga-geometry).
  std::string validity() const;

 private:
  Geometry(std::shared_ptr<const Space> space, Eigen::MatrixXd control_points, const Geometry* same_map);
  int majority_orientation() const;
  void finish(Index e, Index q, GeometryValues& out, bool check) const;
  std::shared_ptr<const Space> space_;
  Eigen::MatrixXd control_points_;
  int orientation_ = 1;
};

}  // namespace iga::basis
