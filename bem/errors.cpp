#include "bem/errors.hpp"

#include <cmath>

#include "quadrature/gauss_legendre.hpp"

namespace iga::bem {

namespace {

double evaluate(const BoundaryDiscretization& d, const Eigen::VectorXd& c, Index e, double t) {
  basis::CurveBasisValues v;
  d.space().evaluate(e, Eigen::VectorXd::Constant(1, t), 0, v);
  const std::span<const Index> dofs = d.space().dofs(e);
  double r = 0.0;
  for (std::size_t j = 0; j < dofs.size(); ++j) r += c(dofs[j]) * v.value(static_cast<Index>(j), 0);
  return r;
}

// ∫_Γ (f_h − f)² dΓ with f_h from coefficients c (nullptr: f_h = 0), f = u (flux false) or ∇u·n (flux true).
double l2_squared(const BoundaryDiscretization& d, const Eigen::VectorXd* c, const fem::Function& exact, bool flux) {
  const quadrature::Rule1D g = quadrature::gauss_legendre(d.space().degree() + 6);
  basis::CurvePoints pts;
  basis::CurveBasisValues v;
  Eigen::VectorXd fv;
  Eigen::Matrix3Xd grad;
  double sum = 0.0;
  for (Index e = 0; e < d.num_elements(); ++e) {
    const BemElement& el = d.element(e);
    d.curve().evaluate(el.curve_element, (el.a + (el.b - el.a) * g.points.array()).matrix(), pts);
    Eigen::Matrix3Xd x = Eigen::Matrix3Xd::Zero(3, pts.x.cols());
    x.topRows<2>() = pts.x;
    if (flux) {
      exact.gradients(x, grad);
      fv = (grad.topRows<2>().cwiseProduct(pts.normal)).colwise().sum().transpose();
    } else {
      exact.values(x, fv);
    }
    Eigen::VectorXd fh = Eigen::VectorXd::Zero(fv.size());
    if (c != nullptr) {
      d.space().evaluate(e, g.points, 0, v);
      const std::span<const Index> dofs = d.space().dofs(e);
      for (std::size_t j = 0; j < dofs.size(); ++j) fh += (*c)(dofs[j]) * v.value.row(static_cast<Index>(j)).transpose();
    }
    sum += ((el.b - el.a) * g.weights.array() * pts.speed.array() * (fh - fv).array().square()).sum();
  }
  return sum;
}

}  // namespace

double evaluate_u(const BoundaryDiscretization& d, const Solution& s, Index e, double t) { return evaluate(d, s.u, e, t); }
double evaluate_q(const BoundaryDiscretization& d, const Solution& s, Index e, double t) { return evaluate(d, s.q, e, t); }

double flux_l2_error(const BoundaryDiscretization& d, const Solution& s, const fem::Function& exact) {
  return std::sqrt(l2_squared(d, &s.q, exact, true));
}
double u_l2_error(const BoundaryDiscretization& d, const Solution& s, const fem::Function& exact) {
  return std::sqrt(l2_squared(d, &s.u, exact, false));
}
double flux_l2_norm(const BoundaryDiscretization& d, const fem::Function& exact) {
  return std::sqrt(l2_squared(d, nullptr, exact, true));
}
double u_l2_norm(const BoundaryDiscretization& d, const fem::Function& exact) {
  return std::sqrt(l2_squared(d, nullptr, exact, false));
}

}  // namespace iga::bem
