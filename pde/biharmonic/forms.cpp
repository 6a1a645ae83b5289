#include "pde/biharmonic/forms.hpp"

namespace iga::pde {

void BiharmonicForm::add(const fem::ElementContext& ctx, Eigen::MatrixXd& local) const {
  thread_local Eigen::MatrixXd scaled;
  scaled = ctx.laplacian.array().rowwise() * ctx.weight.transpose().array();
  local.noalias() += scaled * ctx.laplacian.transpose();
}

void ClampedNitscheForm::add(const fem::BoundaryContext& ctx, Eigen::MatrixXd& local) const {
  thread_local Eigen::MatrixXd dn, wdn;
  fem::conormal_derivatives(ctx, dn);
  wdn.noalias() = dn * ctx.weight.asDiagonal();
  local.noalias() -= wdn * ctx.laplacian.transpose();
  local.noalias() -= ctx.laplacian * wdn.transpose();
  local.noalias() += penalty_(ctx) * wdn * dn.transpose();
}

void ClampedNitscheLoad::add(const fem::BoundaryContext& ctx, Eigen::VectorXd& local) const {
  thread_local Eigen::MatrixXd dn;
  Eigen::VectorXd h;
  slope_->values(ctx.geo.x, ctx.conormal, h);
  fem::conormal_derivatives(ctx, dn);
  const Eigen::VectorXd wh = h.cwiseProduct(ctx.weight);
  local.noalias() += penalty_(ctx) * dn * wh - ctx.laplacian * wh;
}

void MomentLoad::add(const fem::BoundaryContext& ctx, Eigen::VectorXd& local) const {
  thread_local Eigen::MatrixXd dn;
  Eigen::VectorXd m;
  m_->values(ctx.geo.x, m);
  fem::conormal_derivatives(ctx, dn);
  local.noalias() += dn * m.cwiseProduct(ctx.weight);
}

}  // namespace iga::pde
