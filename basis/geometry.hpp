#pragma once
// A space plus control points: the isogeometric map from each element's reference domain to the physical
// domain (a planar region, dim 2, or a surface in 3D, dim 3).
#include <Eigen/Core>
#include <memory>

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

  const Space& space() const { return *space_; }
  const std::shared_ptr<const Space>& space_ptr() const { return space_; }
  int dim() const { return static_cast<int>(control_points_.cols()); }
  const Eigen::MatrixXd& control_points() const { return control_points_; }

  /// Map data of element e from basis values already evaluated there (derivatives >= 1).
  /// With check, throws NumericalError naming the element when the map is degenerate (measure 0 or not
  /// finite) at a point; without, such points get tu = tv = 0 (used by output, which samples element edges).
  /// With derivatives = 2 (basis evaluated with second derivatives) also xuu, xuv, xvv.
  void evaluate(Index e, const BasisValues& basis, GeometryValues& out, bool check = true, int derivatives = 1) const;
  /// Convenience: evaluates the basis first.
  void evaluate(Index e, const Eigen::Matrix2Xd& pts, GeometryValues& out) const;

 private:
  std::shared_ptr<const Space> space_;
  Eigen::MatrixXd control_points_;
};

}  // namespace iga::basis
