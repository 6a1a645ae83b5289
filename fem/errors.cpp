#include "fem/errors.hpp"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>

#include "core/error.hpp"

namespace iga::fem {

std::string norm_name(Norm norm) {
  switch (norm) {
    case Norm::kL2: return "L2";
    case Norm::kH1: return "H1";
    case Norm::kH2: return "H2";
    case Norm::kLaplacian: return "laplacian";
  }
  return "?";
}

namespace {

// The discrete solution and the exact one at an element's points, to the order the norms need.
struct Fields {
  Eigen::VectorXd uh, ue;
  Eigen::Matrix3Xd gh, ge;
  Eigen::Matrix<double, 6, Eigen::Dynamic> hh, he;  // rows xx, xy, yy (planar) as Function::hessians
  // Finite-difference derivatives only: those with the step doubled, for the estimate of their error.
  Eigen::Matrix3Xd ge2;
  Eigen::Matrix<double, 6, Eigen::Dynamic> he2;
};

void project_tangent(const ElementContext& ctx, Eigen::Matrix3Xd& g) {
  for (Index k = 0; k < g.cols(); ++k) {
    const Eigen::Vector3d n = ctx.geo.normal.col(k);
    g.col(k) -= g.col(k).dot(n) * n;
  }
}

void evaluate_fields(const ElementContext& ctx, const Eigen::VectorXd& local, const Function& exact, int order,
                     Fields& f) {
  f.uh.noalias() = ctx.basis.value.transpose() * local;
  exact.values(ctx.geo.x, f.ue);
  if (order >= 1) {
    f.gh.setZero(3, f.uh.size());
    for (int c = 0; c < ctx.dim; ++c) f.gh.row(c) = local.transpose() * ctx.grad_component(c);
    // Planar: the in-plane gradient (the z-component is projected out below anyway; a finite-difference gradient
    // then evaluates a third fewer points).
    const int components = ctx.dim == 2 ? 2 : 3;
    exact.partial_gradients(ctx.geo.x, components, f.ge);
    project_tangent(ctx, f.ge);
    if (!exact.exact_gradient()) {
      exact.difference_gradients(ctx.geo.x, 2 * exact.fd_step(), components, f.ge2);
      project_tangent(ctx, f.ge2);
    }
  }
  if (order >= 2) {
    f.hh.setZero(6, f.uh.size());
    for (int b = 0; b < 3; ++b) f.hh.row(b) = local.transpose() * ctx.hessian_block(b);
    exact.hessians(ctx.geo.x, f.he);
    if (!exact.exact_hessian()) exact.difference_hessians(ctx.geo.x, 2 * exact.fd_step(), f.he2);
  }
}

// ∫ |D_h u − D_2h u|² in a norm's derivatives: the estimate of the finite differences' error (0 for exact ones).
double derivative_error_square(Norm norm, const Function& exact, const Fields& f, const Eigen::VectorXd& w) {
  switch (norm) {
    case Norm::kL2: return 0.0;
    case Norm::kH1:
      if (exact.exact_gradient()) return 0.0;
      return ((f.ge - f.ge2).colwise().squaredNorm().transpose().array() * w.array()).sum();
    case Norm::kH2: {
      if (exact.exact_hessian()) return 0.0;
      const Eigen::ArrayXXd d = (f.he.topRows(3) - f.he2.topRows(3)).array();
      return ((d.row(0).square() + 2 * d.row(1).square() + d.row(2).square()).transpose() * w.array()).sum();
    }
    case Norm::kLaplacian: {
      if (exact.exact_hessian()) return 0.0;
      const Eigen::ArrayXd d = ((f.he.row(0) + f.he.row(2)) - (f.he2.row(0) + f.he2.row(2))).transpose().array();
      return (d.square() * w.array()).sum();
    }
  }
  return 0.0;
}

// ∫ of the pointwise square of a norm's integrand: of exact − discrete (error), or of the exact solution alone.
double square(Norm norm, const Fields& f, const Eigen::VectorXd& w, bool error) {
  const double s = error ? 1.0 : 0.0;
  switch (norm) {
    case Norm::kL2: return ((f.ue - s * f.uh).array().square() * w.array()).sum();
    case Norm::kH1: return ((f.ge - s * f.gh).colwise().squaredNorm().transpose().array() * w.array()).sum();
    case Norm::kH2: {
      const Eigen::ArrayXXd d = (f.he.topRows(3) - s * f.hh.topRows(3)).array();
      return ((d.row(0).square() + 2 * d.row(1).square() + d.row(2).square()).transpose() * w.array()).sum();
    }
    case Norm::kLaplacian: {
      const Eigen::ArrayXd d = ((f.he.row(0) + f.he.row(2)) - s * (f.hh.row(0) + f.hh.row(2))).transpose().array();
      return (d.square() * w.array()).sum();
    }
  }
  return 0.0;
}

int order(Norm norm) { return norm == Norm::kL2 ? 0 : norm == Norm::kH1 ? 1 : 2; }

}  // namespace

Eigen::VectorXd norm_squares(const Assembler& assembler, const Eigen::VectorXd& u, const Function& exact,
                             std::span<const Norm> norms, const std::vector<char>* only) {
  int needed = 0;
  for (Norm n : norms) needed = std::max(needed, order(n));
  if (needed >= 2 && assembler.geometry().dim() != 2) {
    throw UnsupportedError("error norms: the H2 and Laplacian norms are for planar domains (this is a surface)");
  }
  const basis::Space& space = assembler.geometry().space();
  const int k = static_cast<int>(norms.size());
  return assembler.integrate(3 * k, [&](const ElementContext& ctx, Eigen::Ref<Eigen::VectorXd> out) {
    const auto dofs = space.dofs(ctx.element);
    thread_local Eigen::VectorXd local;
    thread_local Fields f;
    local.resize(static_cast<Index>(dofs.size()));
    for (std::size_t a = 0; a < dofs.size(); ++a) local(static_cast<Index>(a)) = u(dofs[a]);
    evaluate_fields(ctx, local, exact, needed, f);
    for (int i = 0; i < k; ++i) {
      out(2 * i) = square(norms[static_cast<std::size_t>(i)], f, ctx.weight, true);
      out(2 * i + 1) = square(norms[static_cast<std::size_t>(i)], f, ctx.weight, false);
      out(2 * k + i) = derivative_error_square(norms[static_cast<std::size_t>(i)], exact, f, ctx.weight);
    }
  }, std::max(needed, 1), only);
}

std::string derivatives_in(Norm norm, const Function& exact) {
  return norm == Norm::kL2 ? "values" : exact.derivative_method(order(norm));
}

std::vector<NormError> norm_errors(const std::vector<std::string>& names, const Eigen::VectorXd& squares,
                                   const std::vector<std::string>& derivatives) {
  std::vector<NormError> out;
  const Index n = static_cast<Index>(names.size());
  if ((squares.size() != 2 * n && squares.size() != 3 * n) || (!derivatives.empty() && derivatives.size() != names.size())) {
    throw Error("norm_errors: " + std::to_string(squares.size()) + " squares and " +
                std::to_string(derivatives.size()) + " derivative methods for " + std::to_string(n) + " norms");
  }
  for (Index i = 0; i < n; ++i) {
    const std::string& name = names[static_cast<std::size_t>(i)];
    const double e = std::sqrt(squares(2 * i));
    const double x = std::sqrt(squares(2 * i + 1));
    if (!std::isfinite(e) || !std::isfinite(x)) {
      throw NumericalError("the " + name + " error against the exact solution is not finite (error " +
                           std::to_string(e) + ", exact " + std::to_string(x) +
                           "): does the exact solution overflow, or did the solve diverge?");
    }
    NormError figure{name, e, x, derivatives.empty() ? std::string() : derivatives[static_cast<std::size_t>(i)], 0.0};
    if (squares.size() == 3 * n) {
      figure.derivative_error = std::sqrt(squares(2 * n + i));
      if (!(figure.derivative_error <= kDerivativeErrorShare * e)) {
        std::ostringstream msg;
        msg << std::setprecision(3) << "the " << name << " error (" << e
            << ") is not reported: it needs the exact solution's derivatives, here finite differences whose error is "
               "estimated at "
            << figure.derivative_error << ", more than " << 100 * kDerivativeErrorShare
            << " % of it; give the exact solution with derivatives in closed form"
            << (figure.derivatives.empty() ? "" : " (" + figure.derivatives + ")");
        throw NumericalError(msg.str());
      }
    }
    out.push_back(std::move(figure));
  }
  return out;
}

ErrorNorms compute_errors(const Assembler& assembler, const Eigen::VectorXd& u, const Function& exact) {
  return error_norms(error_squares(assembler, u, exact));
}

ErrorNorms error_norms(const Eigen::Vector4d& sums) {
  return {std::sqrt(sums(0)), std::sqrt(sums(1)), std::sqrt(sums(2)), std::sqrt(sums(3))};
}

Eigen::Vector4d error_squares(const Assembler& assembler, const Eigen::VectorXd& u, const Function& exact,
                              const std::vector<char>* only) {
  const Norm norms[2] = {Norm::kL2, Norm::kH1};
  const Eigen::VectorXd s = norm_squares(assembler, u, exact, norms, only);
  return {s(0), s(2), s(1), s(3)};
}

}  // namespace iga::fem
