#include "basis/geometry.hpp"

#include <Eigen/Geometry>
#include <cmath>
#include <sstream>

#include "core/error.hpp"

namespace iga::basis {

Geometry::Geometry(std::shared_ptr<const Space> space, Eigen::MatrixXd control_points)
    : space_(std::move(space)), control_points_(std::move(control_points)) {
  if (!space_) throw InputError("geometry: no space given");
  if (control_points_.rows() != space_->num_dofs()) {
    throw InputError("geometry: " + std::to_string(control_points_.rows()) + " control points for a space of " +
                     std::to_string(space_->num_dofs()) + " functions");
  }
  if (control_points_.cols() != 2 && control_points_.cols() != 3) {
    throw InputError("geometry: control points must have 2 or 3 coordinates, got " +
                     std::to_string(control_points_.cols()));
  }
  if (!control_points_.allFinite()) throw InputError("geometry: a control point has a non-finite coordinate");
}

void Geometry::evaluate(Index e, const BasisValues& basis, GeometryValues& out, bool check) const {
  const auto dofs = space_->dofs(e);
  const Index n = static_cast<Index>(dofs.size());
  const Index q = basis.value.cols();
  // Gather the element's control points (3 × n; z = 0 for planar geometries).
  thread_local Eigen::Matrix3Xd local;
  local.resize(3, n);
  const int d = dim();
  for (Index a = 0; a < n; ++a) {
    local(0, a) = control_points_(dofs[a], 0);
    local(1, a) = control_points_(dofs[a], 1);
    local(2, a) = d == 3 ? control_points_(dofs[a], 2) : 0.0;
  }
  out.x.noalias() = local * basis.value;
  out.xu.noalias() = local * basis.du;
  out.xv.noalias() = local * basis.dv;
  out.measure.resize(q);
  out.normal.resize(3, q);
  out.tu.resize(3, q);
  out.tv.resize(3, q);
  for (Index k = 0; k < q; ++k) {
    const Eigen::Vector3d xu = out.xu.col(k);
    const Eigen::Vector3d xv = out.xv.col(k);
    const double g11 = xu.squaredNorm();
    const double g12 = xu.dot(xv);
    const double g22 = xv.squaredNorm();
    const Eigen::Vector3d c = xu.cross(xv);
    const double det = c.squaredNorm();  // = g11 g22 - g12^2, without cancellation
    const double m = std::sqrt(det);
    out.measure(k) = m;
    if (!(m > 0.0) || !std::isfinite(m)) {
      if (check) {
        std::ostringstream msg;
        msg << "element " << e << ": degenerate geometry map (surface element " << m << ") at quadrature point "
            << k;
        throw NumericalError(msg.str());
      }
      out.normal.col(k).setZero();
      out.tu.col(k).setZero();
      out.tv.col(k).setZero();
      continue;
    }
    out.normal.col(k) = c / m;
    out.tu.col(k) = (g22 * xu - g12 * xv) / det;
    out.tv.col(k) = (g11 * xv - g12 * xu) / det;
  }
}

void Geometry::evaluate(Index e, const Eigen::Matrix2Xd& pts, GeometryValues& out) const {
  BasisValues basis;
  space_->evaluate(e, pts, 1, basis);
  evaluate(e, basis, out);
}

}  // namespace iga::basis
