#include "pde/elasticity/forms.hpp"

#include <cmath>
#include <sstream>
#include <string>

#include "core/error.hpp"

namespace iga::pde {

Lame lame(double young, double poisson, PlaneModel model) {
  const auto shortest = [](double v) {
    std::ostringstream out;
    out << v;
    return out.str();
  };
  if (!(young > 0.0) || !std::isfinite(young)) {
    throw InputError("elasticity: Young's modulus E must be a finite number > 0, got " + shortest(young));
  }
  // Plane stress: ν = 1/2 is allowed (λ* = Eν/(1 − ν²) stays finite); plane strain's λ = Eν/((1 + ν)(1 − 2ν)) is not.
  if (model == PlaneModel::kStress && !(poisson > -1.0 && poisson <= 0.5)) {
    throw InputError("elasticity: Poisson's ratio must lie in (-1, 0.5] in plane stress, got " + shortest(poisson));
  }
  if (model == PlaneModel::kStrain && !(poisson > -1.0 && poisson < 0.5)) {
    throw InputError("elasticity: Poisson's ratio must lie in (-1, 0.5) in plane strain (0.5 is incompressible: the "
                     "displacement form locks), got " + shortest(poisson));
  }
  Lame l;
  l.mu = young / (2 * (1 + poisson));
  l.lambda = model == PlaneModel::kStrain ? young * poisson / ((1 + poisson) * (1 - 2 * poisson))
                                          : young * poisson / (1 - poisson * poisson);
  return l;
}

void ElasticityForm::add(const fem::ElementContext& ctx, Eigen::MatrixXd& local) const {
  // The four blocks from three Gram products of the gradient components: M_xy = G_x W G_yᵀ.
  const Eigen::Index n = ctx.basis.value.rows();
  thread_local Eigen::MatrixXd wx, wy, mxx, mxy, myy;
  const auto gx = ctx.grad_component(0), gy = ctx.grad_component(1);
  wx = gx.array().rowwise() * ctx.weight.transpose().array();
  wy = gy.array().rowwise() * ctx.weight.transpose().array();
  mxx.noalias() = wx * gx.transpose();
  mxy.noalias() = wx * gy.transpose();
  myy.noalias() = wy * gy.transpose();
  const double l = lame_.lambda, m = lame_.mu;
  for (Eigen::Index b = 0; b < n; ++b) {
    for (Eigen::Index a = 0; a < n; ++a) {
      local(2 * a, 2 * b) += (l + 2 * m) * mxx(a, b) + m * myy(a, b);
      local(2 * a, 2 * b + 1) += l * mxy(a, b) + m * mxy(b, a);
      local(2 * a + 1, 2 * b) += l * mxy(b, a) + m * mxy(a, b);
      local(2 * a + 1, 2 * b + 1) += (l + 2 * m) * myy(a, b) + m * mxx(a, b);
    }
  }
}

void BodyForceForm::add(const fem::ElementContext& ctx, Eigen::VectorXd& local) const {
  thread_local Eigen::VectorXd f, g;
  for (int c = 0; c < 2; ++c) {
    if (!b_[static_cast<std::size_t>(c)]) continue;
    b_[static_cast<std::size_t>(c)]->values(ctx.geo.x, f);
    g.noalias() = ctx.basis.value * f.cwiseProduct(ctx.weight);
    for (Eigen::Index a = 0; a < g.size(); ++a) local(2 * a + c) += g(a);
  }
}

void TractionForm::add(const fem::BoundaryContext& ctx, Eigen::VectorXd& local) const {
  Eigen::VectorXd t, g;
  for (int c = 0; c < 2; ++c) {
    if (!t_[static_cast<std::size_t>(c)]) continue;
    t_[static_cast<std::size_t>(c)]->values(ctx.geo.x, ctx.conormal, t);
    g.noalias() = ctx.basis.value * t.cwiseProduct(ctx.weight);
    for (Eigen::Index a = 0; a < g.size(); ++a) local(2 * a + c) += g(a);
  }
}

}  // namespace iga::pde
