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
  difference_gradients(x, fd_step_, components, out);
}

void Function::gradients(const Eigen::Matrix3Xd& x, Eigen::Matrix3Xd& out) const {
  difference_gradients(x, fd_step_, 3, out);
}

std::string Function::derivative_method(int order) const {
  if (order <= 1) return exact_gradient() ? "closed form" : "finite differences";
  if (exact_hessian()) return "closed form";
  return exact_gradient() ? "finite differences of the closed-form gradient" : "finite differences";
}

void Function::difference_gradients(const Eigen::Matrix3Xd& x, double h, int components, Eigen::Matrix3Xd& out) const {
  try {
    central_difference(*this, x, h, out, components);
    return;
  } catch (const InputError&) {
    // A shifted point left the function's domain (sqrt(x) near x = 0, where the domain ends): point by point,
    // halve the step until the stencil stays where the function is defined; a point where it never does (or
    // the function itself is not finite) gets the error of that point.
  }
  out.setZero(3, x.cols());
  Eigen::Matrix3Xd one(3, 1), g;
  for (Eigen::Index k = 0; k < x.cols(); ++k) {
    one.col(0) = x.col(k);
    for (double step = h;; step *= 0.5) {
      try {
        central_difference(*this, one, step, g, components);
        out.col(k) = g.col(0);
        break;
      } catch (const InputError&) {
        if (step < h * 1e-6) throw;
      }
    }
  }
}

void Function::hessians(const Eigen::Matrix3Xd& x, Eigen::Matrix<double, 6, Eigen::Dynamic>& out) const {
  difference_hessians(x, fd_step_, out);
}

void Function::difference_hessians(const Eigen::Matrix3Xd& x, double h,
                                   Eigen::Matrix<double, 6, Eigen::Dynamic>& out) const {
  // Column j of the Hessian: (−g(x + 2h e_j) + 8 g(x + h e_j) − 8 g(x − h e_j) + g(x − 2h e_j)) / 12h.
  const Eigen::Index q = x.cols();
  Eigen::Matrix3Xd shifted(3, 12 * q), g;
  const double offsets[4] = {2 * h, h, -h, -2 * h};
  for (Eigen::Index k = 0; k < q; ++k) {
    for (int j = 0; j < 3; ++j) {
      for (int o = 0; o < 4; ++o) {
        shifted.col(12 * k + 4 * j + o) = x.col(k);
        shifted(j, 12 * k + 4 * j + o) += offsets[o];
      }
    }
  }
  gradients(shifted, g);
  out.resize(6, q);
  for (Eigen::Index k = 0; k < q; ++k) {
    Eigen::Matrix3d m;
    for (int j = 0; j < 3; ++j) {
      const Eigen::Index c = 12 * k + 4 * j;
      m.col(j) = (-g.col(c) + 8 * g.col(c + 1) - 8 * g.col(c + 2) + g.col(c + 3)) / (12 * h);
    }
    m = 0.5 * (m + m.transpose()).eval();
    out.col(k) << m(0, 0), m(0, 1), m(1, 1), m(0, 2), m(1, 2), m(2, 2);
  }
}

namespace {
class PointwiseFunction final : public Function {
 public:
  PointwiseFunction(PointFunction f, PointGradient g, PointHessian h)
      : f_(std::move(f)), g_(std::move(g)), h_(std::move(h)) {}
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
  void hessians(const Eigen::Matrix3Xd& x, Eigen::Matrix<double, 6, Eigen::Dynamic>& out) const override {
    if (!h_) {
      Function::hessians(x, out);
      return;
    }
    out.resize(6, x.cols());
    for (Eigen::Index k = 0; k < x.cols(); ++k) {
      const Eigen::Matrix3d m = h_(x.col(k));
      out.col(k) << m(0, 0), m(0, 1), m(1, 1), m(0, 2), m(1, 2), m(2, 2);
    }
  }
  bool exact_hessian() const override { return static_cast<bool>(h_); }

 private:
  PointFunction f_;
  PointGradient g_;
  PointHessian h_;
};

class Laplacian final : public Function {
 public:
  Laplacian(std::shared_ptr<const Function> u, bool planar) : u_(std::move(u)), planar_(planar) {}
  void values(const Eigen::Matrix3Xd& x, Eigen::VectorXd& out) const override {
    Eigen::Matrix<double, 6, Eigen::Dynamic> h;
    u_->hessians(x, h);
    out = (h.row(0) + h.row(2)).transpose();
    if (!planar_) out += h.row(5).transpose();
  }

 private:
  std::shared_ptr<const Function> u_;
  bool planar_;
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

std::shared_ptr<Function> make_function(PointFunction f, PointGradient grad, PointHessian hessian) {
  return std::make_shared<PointwiseFunction>(std::move(f), std::move(grad), std::move(hessian));
}

std::shared_ptr<Function> laplacian_of(std::shared_ptr<const Function> u, bool planar) {
  return std::make_shared<Laplacian>(std::move(u), planar);
}

std::shared_ptr<Function> constant_function(double c) {
  return make_function([c](const Eigen::Vector3d&) { return c; },
                       [](const Eigen::Vector3d&) -> Eigen::Vector3d { return Eigen::Vector3d::Zero(); },
                       [](const Eigen::Vector3d&) -> Eigen::Matrix3d { return Eigen::Matrix3d::Zero(); });
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
    void hessians(const Eigen::Matrix3Xd& x, Eigen::Matrix<double, 6, Eigen::Dynamic>& out) const override {
      u_->hessians(x, out);
    }
    bool exact_hessian() const override { return u_->exact_hessian(); }
    std::string derivative_method(int order) const override { return u_->derivative_method(order); }

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
