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

void Geometry::evaluate(Index e, const BasisValues& basis, GeometryValues& out, bool check, int derivatives) const {
  const auto dofs = space_->dofs(e);
  const Index n = static_cast<Index>(dofs.size());
  const Index q = basis.value.cols();
  // Gather the element's control points (n × 3, z = 0 for planar geometries); x = P^T N as inner products
  // of contiguous columns.
  thread_local Eigen::MatrixX3d local;
  local.resize(n, 3);
  const int d = dim();
  for (Index a = 0; a < n; ++a) {
    local(a, 0) = control_points_(dofs[a], 0);
    local(a, 1) = control_points_(dofs[a], 1);
    local(a, 2) = d == 3 ? control_points_(dofs[a], 2) : 0.0;
  }
  out.x.noalias() = local.transpose().lazyProduct(basis.value);
  out.xu.noalias() = local.transpose().lazyProduct(basis.du);
  out.xv.noalias() = local.transpose().lazyProduct(basis.dv);
  if (derivatives >= 2) {
    out.xuu.noalias() = local.transpose().lazyProduct(basis.duu);
    out.xuv.noalias() = local.transpose().lazyProduct(basis.duv);
    out.xvv.noalias() = local.transpose().lazyProduct(basis.dvv);
  }
  // Metric G = J^T J, its determinant |x_u × x_v|^2 (no cancellation), and T = J G^{-1}, for all points
  // at once (row-wise array expressions over the q columns).
  const auto xu = out.xu.array();
  const auto xv = out.xv.array();
  out.normal.resize(3, q);
  out.normal.row(0) = xu.row(1) * xv.row(2) - xu.row(2) * xv.row(1);
  out.normal.row(1) = xu.row(2) * xv.row(0) - xu.row(0) * xv.row(2);
  out.normal.row(2) = xu.row(0) * xv.row(1) - xu.row(1) * xv.row(0);
  thread_local Eigen::RowVectorXd g11, g12, g22, det;
  g11 = out.xu.colwise().squaredNorm();
  g22 = out.xv.colwise().squaredNorm();
  g12 = (xu * xv).colwise().sum().matrix();
  det = out.normal.colwise().squaredNorm();
  out.measure = det.transpose().cwiseSqrt();
  const bool valid = (out.measure.array() > 0.0).all() && out.measure.allFinite();
  if (!valid && check) {
    Index k = 0;
    while (out.measure(k) > 0.0 && std::isfinite(out.measure(k))) ++k;
    std::ostringstream msg;
    msg << "element " << e << ": degenerate geometry map (surface element " << out.measure(k)
        << ") at quadrature point " << k;
    throw NumericalError(msg.str());
  }
  out.normal.array().rowwise() /= out.measure.transpose().array();
  out.tu.resize(3, q);
  out.tv.resize(3, q);
  out.tu = (xu.rowwise() * (g22.array() / det.array()) - xv.rowwise() * (g12.array() / det.array())).matrix();
  out.tv = (xv.rowwise() * (g11.array() / det.array()) - xu.rowwise() * (g12.array() / det.array())).matrix();
  if (!valid) {
    for (Index k = 0; k < q; ++k) {
      if (!(out.measure(k) > 0.0) || !std::isfinite(out.measure(k))) {
        out.normal.col(k).setZero();
        out.tu.col(k).setZero();
        out.tv.col(k).setZero();
      }
    }
  }
}

void Geometry::evaluate(Index e, const Eigen::Matrix2Xd& pts, GeometryValues& out) const {
  BasisValues basis;
  space_->evaluate(e, pts, 1, basis);
  evaluate(e, basis, out);
}

}  // namespace iga::basis
