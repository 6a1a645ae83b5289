#include "fem/function.hpp"

#include <cmath>

#include "core/error.hpp"

namespace iga::fem {

namespace {
// Fourth-order central difference of f at the columns of x with step h per coordinate:
// f'(x) ≈ (f(x-2h) - 8 f(x-h) + 8 f(x+h) - f(x+2h)) / (12 h).
void central_difference(const Function& f, const Eigen::Matrix3Xd& x, double h, Eigen::Matrix3Xd& out,
                        int components = 3) {
  const Eigen::Index q = x.cols();
  out.setZero(3, q);
  Eigen::Matrix3Xd shifted(3, q);  // not thread_local: values() may be a user's, and may difference too
  Eigen::VectorXd fm2, fm1, fp1, fp2;
  for (int c = 0; c < components; ++c) {
    shifted = x;
    shifted.row(c).array() -= 2 * h;
    f.values(shifted, fm2);
    shifted.row(c).array() += h;
    f.values(shifted, fm1);
    shifted.row(c).array() += 2 * h;
    f.values(shifted, fp1);
    shifted.row(c).array() += h;
    f.values(shifted, fp2);
    out.row(c) = ((fm2 - 8.0 * fm1 + 8.0 * fp1 - fp2) / (12.0 * h)).transpose();
  }
}
}  // namespace

void Function::partial_gradients(const Eigen::Matrix3Xd& x, int components, Eigen::Matrix3Xd& out) const {
  if (components < 1 || components > 3) {
    throw InputError("partial_gradients: components must be 1, 2 or 3, got " + std::to_string(components));
  }
  if (exact_gradient() || components == 3) {
    gradients(x, out);
    out.bottomRows(3 - components).setZero();
    return;
  }
  try {
    central_difference(*this, x, fd_step_, out, components);
  } catch (const InputError&) {
    gradients(x, out);  // near the edge of the function's domain: point by point with shrinking steps
    out.bottomRows(3 - components).setZero();
  }
}

void Function::gradients(const Eigen::Matrix3Xd& x, Eigen::Matrix3Xd& out) const {
  try {
    central_difference(*this, x, fd_step_, out);
    return;
  } catch (const InputError&) {
    // A shifted point left the function's domain (sqrt(x) near x = 0, where the domain ends): point by point,
    // halve the step until the stencil stays where the function is defined; a point where it never does (or
    // the function itself is not finite) gets the error of that point.
  }
  out.resize(3, x.cols());
  Eigen::Matrix3Xd one(3, 1), g;
  for (Eigen::Index k = 0; k < x.cols(); ++k) {
    one.col(0) = x.col(k);
    for (double h = fd_step_;; h *= 0.5) {
      try {
        central_difference(*this, one, h, g);
        out.col(k) = g.col(0);
        break;
      } catch (const InputError&) {
        if (h < fd_step_ * 1e-6) throw;
      }
    }
  }
}

namespace {
class PointwiseFunction final : public Function {
 public:
  PointwiseFunction(PointFunction f, PointGradient g) : f_(std::move(f)), g_(std::move(g)) {}
  void values(const Eigen::Matrix3Xd& x, Eigen::VectorXd& out) const override {
    out.resize(x.cols());
    for (Eigen::Index k = 0; k < x.cols(); ++k) out(k) = f_(x.col(k));
  }
  void gradients(const Eigen::Matrix3Xd& x, Eigen::Matrix3Xd& out) const override {
    if (!g_) {
      Function::gradients(x, out);
      return;
    }
    out.resize(3, x.cols());
    for (Eigen::Index k = 0; k < x.cols(); ++k) out.col(k) = g_(x.col(k));
  }
  bool exact_gradient() const override { return static_cast<bool>(g_); }

 private:
  PointFunction f_;
  PointGradient g_;
};

class NormalFlux final : public BoundaryFunction {
 public:
  explicit NormalFlux(std::shared_ptr<const Function> u) : u_(std::move(u)) {}
  void values(const Eigen::Matrix3Xd& x, const Eigen::Matrix3Xd& n, Eigen::VectorXd& out) const override {
    Eigen::Matrix3Xd g;
    u_->gradients(x, g);
    out = g.cwiseProduct(n).colwise().sum().transpose();
  }

 private:
  std::shared_ptr<const Function> u_;
};
}  // namespace

double finite_difference_step(const basis::Geometry& geometry) {
  const Eigen::MatrixXd& p = geometry.control_points();
  const double extent = p.rows() > 0 ? (p.colwise().maxCoeff() - p.colwise().minCoeff()).maxCoeff() : 0.0;
  return extent > 0.0 && std::isfinite(extent) ? 1e-3 * extent : 1e-3;
}

std::shared_ptr<Function> make_function(PointFunction f, PointGradient grad) {
  return std::make_shared<PointwiseFunction>(std::move(f), std::move(grad));
}

std::shared_ptr<Function> constant_function(double c) {
  return make_function([c](const Eigen::Vector3d&) { return c; },
                       [](const Eigen::Vector3d&) -> Eigen::Vector3d { return Eigen::Vector3d::Zero(); });
}

std::shared_ptr<Function> shifted_function(std::shared_ptr<const Function> u, double c) {
  class Shifted final : public Function {
   public:
    Shifted(std::shared_ptr<const Function> u, double c) : u_(std::move(u)), c_(c) {}
    void values(const Eigen::Matrix3Xd& x, Eigen::VectorXd& out) const override {
      u_->values(x, out);
      out.array() += c_;
    }
    void gradients(const Eigen::Matrix3Xd& x, Eigen::Matrix3Xd& out) const override { u_->gradients(x, out); }
    bool exact_gradient() const override { return u_->exact_gradient(); }

   private:
    std::shared_ptr<const Function> u_;
    double c_;
  };
  return std::make_shared<Shifted>(std::move(u), c);
}

std::shared_ptr<BoundaryFunction> normal_flux(std::shared_ptr<const Function> u) {
  return std::make_shared<NormalFlux>(std::move(u));
}

}  // namespace iga::fem
