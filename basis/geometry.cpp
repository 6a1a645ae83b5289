#include "basis/geometry.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>

#include "core/error.hpp"

namespace iga::basis {

Geometry::Geometry(std::shared_ptr<const Space> space, Eigen::MatrixXd control_points)
    : Geometry(std::move(space), std::move(control_points), nullptr) {}

Geometry::Geometry(std::shared_ptr<const Space> space, Eigen::MatrixXd control_points, const Geometry& same_map)
    : Geometry(std::move(space), std::move(control_points), &same_map) {}

Geometry::Geometry(std::shared_ptr<const Space> space, Eigen::MatrixXd control_points, const Geometry* same_map)
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
  if (same_map && same_map->dim() != dim()) {
    throw InputError("geometry: " + std::to_string(dim()) + " coordinates for the same map as one with " +
                     std::to_string(same_map->dim()));
  }
  if (dim() == 2) orientation_ = same_map ? same_map->orientation_ : majority_orientation();
}

int Geometry::majority_orientation() const {
  // The sign of det J at each element's centre; the majority decides (a fold shows up at the others).
  Index positive = 0, negative = 0;
  Eigen::Matrix2Xd centre(2, 1);
  BasisValues basis;
  GeometryValues values;
  for (Index e = 0; e < space_->num_elements(); ++e) {
    centre.col(0) = space_->kind(e).shape == Shape::Triangle ? Eigen::Vector2d(1.0 / 3, 1.0 / 3) : Eigen::Vector2d(0.5, 0.5);
    space_->evaluate(e, centre, 1, basis);
    const auto dofs = space_->dofs(e);
    Eigen::Vector2d xu = Eigen::Vector2d::Zero(), xv = Eigen::Vector2d::Zero();
    for (std::size_t a = 0; a < dofs.size(); ++a) {
      xu += basis.du(static_cast<Index>(a), 0) * control_points_.row(dofs[a]).transpose();
      xv += basis.dv(static_cast<Index>(a), 0) * control_points_.row(dofs[a]).transpose();
    }
    const double det = xu(0) * xv(1) - xu(1) * xv(0);
    positive += det > 0.0;
    negative += det < 0.0;
  }
  return negative > positive ? -1 : 1;
}

namespace {
// dst (3 × q) = local^T f for the element's gathered control points local (n × 3) and one block f (n × q) of its
// functions, as inner products of contiguous columns; only the first `dim` rows (a planar map's z is 0). The
// bicubic size (16 functions, 16 points) has a compile-time path: Eigen unrolls it into register blocks, about
// 1.5× faster than the run-time sized product (issue 17's profile).
void map_block(const Eigen::MatrixX3d& local, const Eigen::MatrixXd& f, int dim, Eigen::Matrix3Xd& dst) {
  const Eigen::Index n = f.rows(), q = f.cols();
  dst.resize(3, q);
  if (dim == 2) dst.row(2).setZero();
  if (n == 16 && q == 16) {
    const Eigen::Map<const Eigen::Matrix<double, 16, 16>> v(f.data());
    for (int r = 0; r < dim; ++r) {
      const Eigen::Map<const Eigen::Matrix<double, 16, 1>> p(local.col(r).data());
      dst.row(r).noalias() = p.transpose().lazyProduct(v);
    }
    return;
  }
  dst.topRows(dim).noalias() = local.leftCols(dim).transpose().lazyProduct(f);
}
}  // namespace

void Geometry::evaluate(Index e, const BasisValues& basis, GeometryValues& out, bool check, int derivatives) const {
  const auto dofs = space_->dofs(e);
  const Index n = static_cast<Index>(dofs.size());
  const Index q = basis.value.cols();
  // Gather the element's control points (n × 3, z = 0 for planar geometries).
  thread_local Eigen::MatrixX3d local;
  local.resize(n, 3);
  const int d = dim();
  for (Index a = 0; a < n; ++a) {
    local(a, 0) = control_points_(dofs[a], 0);
    local(a, 1) = control_points_(dofs[a], 1);
    local(a, 2) = d == 3 ? control_points_(dofs[a], 2) : 0.0;
  }
  map_block(local, basis.value, d, out.x);
  map_block(local, basis.du, d, out.xu);
  map_block(local, basis.dv, d, out.xv);
  if (derivatives >= 2) {
    map_block(local, basis.duu, d, out.xuu);
    map_block(local, basis.duv, d, out.xuv);
    map_block(local, basis.dvv, d, out.xvv);
  }
  finish(e, q, out, check);
}

namespace {
// Degeneracy is judged relative to the element's own scale: |x_u × x_v| below kDegenerate × max|x_u|, |x_v|)²
// over the element. A fold of a planar map is det J < 0 (below −kDegenerate × the same scale at output points,
// which may sit on an extraordinary vertex where the map's derivatives vanish).
constexpr double kDegenerate = 1e-12;
// Above this the area element |x_u × x_v| (and an integral over it) overflows a double: 1e308 > (1e154)².
constexpr double kLargestDerivative = 1e154;

[[noreturn]] void fail_at(Index e, const GeometryValues& out, Index k, const std::string& what) {
  std::ostringstream msg;
  msg << std::setprecision(6) << "element " << e << ": " << what << " at (" << out.x(0, k) << ", " << out.x(1, k);
  if (out.x(2, k) != 0.0) msg << ", " << out.x(2, k);
  msg << ")";
  throw NumericalError(msg.str());
}
}  // namespace

void Geometry::finish(Index e, Index q, GeometryValues& out, bool check) const {
  // The metric G = J^T J, its determinant |x_u × x_v|^2 (no cancellation) and T = J G^{-1} are formed from the
  // derivatives scaled by 2^-s to O(1): a power of two is exact, so the values are those of the unscaled
  // formulas, but neither |x_u × x_v|^2 nor G^{-1} over- or underflows for geometries in units of 1e±100.
  const double largest = std::max(out.xu.cwiseAbs().maxCoeff(), out.xv.cwiseAbs().maxCoeff());
  if (!std::isfinite(largest)) fail_at(e, out, 0, "the geometry map's derivatives are not finite");
  if (check && largest > kLargestDerivative) {
    std::ostringstream msg;
    msg << std::setprecision(6) << "element " << e << ": the area element of the geometry map at (" << out.x(0, 0) << ", "
        << out.x(1, 0) << (out.x(2, 0) != 0.0 ? ", " + std::to_string(out.x(2, 0)) : std::string()) << ")"
        << std::setprecision(3) << " overflows a double (its derivatives are " << largest
        << "); rescale the net: coordinates up to about 1e150 work";
    throw NumericalError(msg.str());
  }
  const int s = largest > 0.0 ? std::ilogb(largest) : 0;
  const double scale = std::ldexp(1.0, -s);  // T = J G^{-1} = 2^-s T_s, |x_u × x_v| = 2^2s |x_u,s × x_v,s|
  const double area = std::ldexp(1.0, 2 * s);
  const double floor = kDegenerate * std::ldexp(largest, -s) * std::ldexp(largest, -s);
  const bool planar = dim() == 2;
  out.normal.resize(3, q);
  out.measure.resize(q);
  out.tu.resize(3, q);
  out.tv.resize(3, q);
  bool valid = true;
  for (Index k = 0; k < q; ++k) {  // one point at a time: q is small, and every quantity is a few flops
    const Eigen::Vector3d xu = out.xu.col(k) * scale, xv = out.xv.col(k) * scale;
    const Eigen::Vector3d n = xu.cross(xv);
    const double det = n.squaredNorm(), measure = std::sqrt(det);
    // Planar: the signed det J is the z component of x_u × x_v, of the geometry's orientation everywhere.
    const double signed_measure = planar ? orientation_ * n(2) : measure;
    if (!(signed_measure > floor)) {
      valid = false;
      if (planar && signed_measure < (check ? 0.0 : -floor)) {
        std::ostringstream what;
        what << std::setprecision(3) << "det J = " << n(2) * area << (orientation_ > 0 ? " < 0" : " > 0")
             << " where most of the domain has det J " << (orientation_ > 0 ? "> 0" : "< 0")
             << ": the geometry map folds over";
        fail_at(e, out, k, what.str());
      }
      if (check) {
        std::ostringstream what;
        what << std::setprecision(3) << "degenerate geometry map (|x_u × x_v| = " << measure * area
             << ", below 1e-12 of the element's largest |x_u|² or |x_v|²)";
        fail_at(e, out, k, what.str());
      }
    }
    const double g11 = xu.squaredNorm(), g12 = xu.dot(xv), g22 = xv.squaredNorm();
    out.normal.col(k) = n / measure;
    out.tu.col(k) = (xu * (g22 / det) - xv * (g12 / det)) * scale;
    out.tv.col(k) = (xv * (g11 / det) - xu * (g12 / det)) * scale;
    out.measure(k) = measure * area;
  }
  if (!valid) {
    for (Index k = 0; k < q; ++k) {
      if (!(out.measure(k) > 0.0) || !std::isfinite(out.measure(k)) || !out.tu.col(k).allFinite() ||
          !out.tv.col(k).allFinite()) {
        out.normal.col(k).setZero();
        out.tu.col(k).setZero();
        out.tv.col(k).setZero();
      }
    }
  }
}

Eigen::MatrixXd Geometry::element_points(Index e) const {
  const auto dofs = space_->dofs(e);
  Eigen::MatrixXd p(static_cast<Eigen::Index>(dofs.size()), dim());
  for (std::size_t a = 0; a < dofs.size(); ++a) p.row(static_cast<Eigen::Index>(a)) = control_points_.row(dofs[a]);
  return p;
}

void Geometry::evaluate(Index e, const Eigen::Matrix2Xd& pts, GeometryValues& out) const {
  BasisValues basis;
  space_->evaluate(e, pts, 1, basis);
  evaluate(e, basis, out);
}

std::string Geometry::validity() const {
  // 4-point Gauss–Legendre on [0, 1]; on a triangle element the collapsed square (a, b (1 − a)).
  const double g[4] = {0.0694318442029737, 0.3300094782075719, 0.6699905217924281, 0.9305681557970263};
  Eigen::Matrix2Xd square(2, 16), triangle(2, 16);
  for (int i = 0; i < 4; ++i) {
    for (int j = 0; j < 4; ++j) {
      square.col(4 * i + j) << g[i], g[j];
      triangle.col(4 * i + j) << g[i], g[j] * (1 - g[i]);
    }
  }
  BasisValues basis;
  GeometryValues values;
  for (Index e = 0; e < space_->num_elements(); ++e) {
    try {
      space_->evaluate(e, space_->kind(e).shape == Shape::Triangle ? triangle : square, 1, basis);
      evaluate(e, basis, values, true);
    } catch (const NumericalError& error) {
      return error.what();
    }
  }
  return {};
}

}  // namespace iga::basis
