#pragma once
// Scalar fields of the physical position, evaluated in batches: sources, boundary data, exact solutions.
#include <Eigen/Core>

#include "basis/geometry.hpp"
#include <functional>
#include <memory>
#include <string>

namespace iga::fem {

/// A scalar function u(x) of physical position x = (x, y, z) (z = 0 on planar domains).
class Function {
 public:
  virtual ~Function() = default;
  /// out(k) = u(x.col(k)). `out` is resized to x.cols().
  virtual void values(const Eigen::Matrix3Xd& x, Eigen::VectorXd& out) const = 0;
  /// out.col(k) = grad u(x.col(k)) (3 × q). The default is a fourth-order central difference with step
  /// fd_step() in each coordinate; override when the gradient is known in closed form.
  virtual void gradients(const Eigen::Matrix3Xd& x, Eigen::Matrix3Xd& out) const;
  /// The first `components` (1..3) entries of gradients(), the rest 0: a planar domain's in-plane gradient is
  /// components = 2. When exact_gradient() is false (the finite difference) only those coordinates are differenced,
  /// a third fewer evaluations in the plane; otherwise gradients() is called and the rest zeroed.
  void partial_gradients(const Eigen::Matrix3Xd& x, int components, Eigen::Matrix3Xd& out) const;
  /// True when gradients() is exact (closed form), false when it is a finite difference.
  virtual bool exact_gradient() const { return false; }
  /// out.col(k) = the Hessian of u at x.col(k), 6 × q, rows xx, xy, yy, xz, yz, zz (the first three are a planar
  /// domain's, in the order of ElementContext::hessian's blocks). The default is a fourth-order central difference
  /// of gradients() with step fd_step(), symmetrised; override when the Hessian is known in closed form.
  virtual void hessians(const Eigen::Matrix3Xd& x, Eigen::Matrix<double, 6, Eigen::Dynamic>& out) const;
  /// True when hessians() is exact (closed form).
  virtual bool exact_hessian() const { return false; }
  /// How the derivatives of the given order (1: gradients(), 2: hessians()) are computed, for reports: "closed form",
  /// "finite differences", or what an override says ("symbolic (GiNaC)").
  virtual std::string derivative_method(int order) const;
  /// The gradients() of the finite difference with step h instead of fd_step() (the first `components` entries, the
  /// rest 0), for estimates of that difference's own error; point by point with shrinking steps where the stencil
  /// leaves the function's domain, as gradients() does.
  void difference_gradients(const Eigen::Matrix3Xd& x, double h, int components, Eigen::Matrix3Xd& out) const;
  /// The default hessians() with step h: the difference of gradients() (exact or not).
  void difference_hessians(const Eigen::Matrix3Xd& x, double h, Eigen::Matrix<double, 6, Eigen::Dynamic>& out) const;
  /// Step of the default finite-difference gradient (physical units); 1e-3 suits domains of size ~1, and
  /// finite_difference_step(geometry) gives the step for any other (the same relative to the domain's size).
  double fd_step() const { return fd_step_; }
  void set_fd_step(double h) { fd_step_ = h; }

 private:
  double fd_step_ = 1e-3;
};

using PointFunction = std::function<double(const Eigen::Vector3d&)>;
using PointGradient = std::function<Eigen::Vector3d(const Eigen::Vector3d&)>;
using PointHessian = std::function<Eigen::Matrix3d(const Eigen::Vector3d&)>;

/// A Function from a point-wise callable, with an optional closed-form gradient.
/// 1e-3 × the largest extent of the geometry's control points: the finite-difference step that is to a domain of
/// any size (units of 1e-100 or 1e100) what 1e-3 is to the unit square.
double finite_difference_step(const basis::Geometry& geometry);

std::shared_ptr<Function> make_function(PointFunction f, PointGradient grad = {}, PointHessian hessian = {});
/// The Laplacian of u, Δu = u_xx + u_yy (+ u_zz), from u's hessians(), as a function (for boundary data such as a
/// simply supported plate's Δu = g). `planar`: without u_zz.
std::shared_ptr<Function> laplacian_of(std::shared_ptr<const Function> u, bool planar = true);
/// The constant c (gradient 0).
std::shared_ptr<Function> constant_function(double c);

/// u + c (same gradient).
std::shared_ptr<Function> shifted_function(std::shared_ptr<const Function> u, double c);

/// Boundary data that may depend on the outward unit (co)normal n: g(x, n), evaluated in batches.
class BoundaryFunction {
 public:
  virtual ~BoundaryFunction() = default;
  virtual void values(const Eigen::Matrix3Xd& x, const Eigen::Matrix3Xd& n, Eigen::VectorXd& out) const = 0;
};

/// The normal flux grad u · n of a function with a gradient (for manufactured Neumann data).
std::shared_ptr<BoundaryFunction> normal_flux(std::shared_ptr<const Function> u);

}  // namespace iga::fem
