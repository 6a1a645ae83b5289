#include "fem/errors.hpp"

#include <cmath>

namespace iga::fem {

ErrorNorms compute_errors(const Assembler& assembler, const Eigen::VectorXd& u, const Function& exact) {
  const basis::Space& space = assembler.geometry().space();
  const Eigen::VectorXd sums = assembler.integrate(4, [&](const ElementContext& ctx, Eigen::Ref<Eigen::VectorXd> out) {
    const auto dofs = space.dofs(ctx.element);
    Eigen::VectorXd local(static_cast<Index>(dofs.size()));
    for (std::size_t a = 0; a < dofs.size(); ++a) local(static_cast<Index>(a)) = u(dofs[a]);
    const Eigen::VectorXd uh = ctx.basis.value.transpose() * local;
    Eigen::Matrix3Xd gh = Eigen::Matrix3Xd::Zero(3, uh.size());
    for (int c = 0; c < ctx.dim; ++c) gh.row(c) = (ctx.grad_component(c).transpose() * local).transpose();
    Eigen::VectorXd ue;
    Eigen::Matrix3Xd ge;
    exact.values(ctx.geo.x, ue);
    exact.gradients(ctx.geo.x, ge);
    for (Index k = 0; k < ge.cols(); ++k) {
      const Eigen::Vector3d n = ctx.geo.normal.col(k);
      ge.col(k) -= ge.col(k).dot(n) * n;
    }
    out(0) = ((ue - uh).array().square() * ctx.weight.array()).sum();
    out(1) = ((ge - gh).colwise().squaredNorm().transpose().array() * ctx.weight.array()).sum();
    out(2) = (ue.array().square() * ctx.weight.array()).sum();
    out(3) = (ge.colwise().squaredNorm().transpose().array() * ctx.weight.array()).sum();
  });
  return {std::sqrt(sums(0)), std::sqrt(sums(1)), std::sqrt(sums(2)), std::sqrt(sums(3))};
}

}  // namespace iga::fem
