#include "fem/errors.hpp"

#include <cmath>

namespace iga::fem {

ErrorNorms compute_errors(const Assembler& assembler, const Eigen::VectorXd& u, const Function& exact) {
  return error_norms(error_squares(assembler, u, exact));
}

ErrorNorms error_norms(const Eigen::Vector4d& sums) {
  return {std::sqrt(sums(0)), std::sqrt(sums(1)), std::sqrt(sums(2)), std::sqrt(sums(3))};
}

Eigen::Vector4d error_squares(const Assembler& assembler, const Eigen::VectorXd& u, const Function& exact,
                              const std::vector<char>* only) {
  const basis::Space& space = assembler.geometry().space();
  return assembler.integrate(4, [&](const ElementContext& ctx, Eigen::Ref<Eigen::VectorXd> out) {
    const auto dofs = space.dofs(ctx.element);
    thread_local Eigen::VectorXd local, uh, ue;
    thread_local Eigen::Matrix3Xd gh, ge;
    local.resize(static_cast<Index>(dofs.size()));
    for (std::size_t a = 0; a < dofs.size(); ++a) local(static_cast<Index>(a)) = u(dofs[a]);
    uh.noalias() = ctx.basis.value.transpose() * local;
    gh.setZero(3, uh.size());
    for (int c = 0; c < ctx.dim; ++c) gh.row(c) = local.transpose() * ctx.grad_component(c);
    exact.values(ctx.geo.x, ue);
    // Planar: the in-plane gradient (the z-component is projected out below anyway; a finite-difference gradient
    // then evaluates a third fewer points).
    exact.partial_gradients(ctx.geo.x, ctx.dim == 2 ? 2 : 3, ge);
    for (Index k = 0; k < ge.cols(); ++k) {
      const Eigen::Vector3d n = ctx.geo.normal.col(k);
      ge.col(k) -= ge.col(k).dot(n) * n;
    }
    out(0) = ((ue - uh).array().square() * ctx.weight.array()).sum();
    out(1) = ((ge - gh).colwise().squaredNorm().transpose().array() * ctx.weight.array()).sum();
    out(2) = (ue.array().square() * ctx.weight.array()).sum();
    out(3) = (ge.colwise().squaredNorm().transpose().array() * ctx.weight.array()).sum();
  }, 1, only);
}

}  // namespace iga::fem
