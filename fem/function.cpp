#include "fem/function.hpp"

namespace iga::fem {

void Function::gradients(const Eigen::Matrix3Xd& x, Eigen::Matrix3Xd& out) const {
  // Fourth-order central difference: f'(x) ≈ (f(x-2h) - 8 f(x-h) + 8 f(x+h) - f(x+2h)) / (12 h).
  const double h = fd_step_;
  const Eigen::Index q = x.cols();
  out.resize(3, q);
  Eigen::Matrix3Xd shifted(3, q);
  Eigen::VectorXd fm2, fm1, fp1, fp2;
  for (int c = 0; c < 3; ++c) {
    shifted = x;
    shifted.row(c).array() -= 2 * h;
    values(shifted, fm2);
    shifted.row(c).array() += h;
    values(shifted, fm1);
    shifted.row(c).array() += 2 * h;
    values(shifted, fp1);
    shifted.row(c).array() += h;
    values(shifted, fp2);
    out.row(c) = ((fm2 - 8.0 * fm1 + 8.0 * fp1 - fp2) / (12.0 * h)).transpose();
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
