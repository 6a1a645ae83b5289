#include "fem/forms.hpp"

namespace iga::fem {

void StiffnessForm::add(const ElementContext& ctx, Eigen::MatrixXd& local) const {
  // sum_c G_c W G_c^T as one product: [G_0 .. G_dim-1] diag(w, .., w) [G_0 .. G_dim-1]^T.
  thread_local Eigen::VectorXd w;
  thread_local Eigen::MatrixXd scaled;
  if (a_) {
    a_->values(ctx.geo.x, w);
    w.array() *= ctx.weight.array();
  } else {
    w = ctx.weight;
  }
  const Eigen::Index q = ctx.num_points();
  scaled.resize(ctx.grad.rows(), ctx.grad.cols());
  for (int c = 0; c < ctx.dim; ++c) {
    scaled.middleCols(c * q, q) = ctx.grad.middleCols(c * q, q).array().rowwise() * w.transpose().array();
  }
  local.noalias() += scaled * ctx.grad.transpose();
}

void MassForm::add(const ElementContext& ctx, Eigen::MatrixXd& local) const {
  thread_local Eigen::MatrixXd scaled;
  scaled = ctx.basis.value.array().rowwise() * (c_ * ctx.weight.transpose().array());
  local.noalias() += scaled * ctx.basis.value.transpose();
}

void SourceForm::add(const ElementContext& ctx, Eigen::VectorXd& local) const {
  thread_local Eigen::VectorXd f;
  f_->values(ctx.geo.x, f);
  local.noalias() += ctx.basis.value * f.cwiseProduct(ctx.weight);
}

void BoundaryMassForm::add(const BoundaryContext& ctx, Eigen::MatrixXd& local) const {
  const Eigen::MatrixXd scaled = ctx.basis.value.array().rowwise() * ctx.weight.transpose().array();
  local.noalias() += scaled * ctx.basis.value.transpose();
}

void BoundaryLoadForm::add(const BoundaryContext& ctx, Eigen::VectorXd& local) const {
  Eigen::VectorXd g;
  if (g_) {
    g_->values(ctx.geo.x, g);
  } else {
    gn_->values(ctx.geo.x, ctx.conormal, g);
  }
  local.noalias() += ctx.basis.value * g.cwiseProduct(ctx.weight);
}

void conormal_derivatives(const BoundaryContext& ctx, Eigen::MatrixXd& dn) {
  const Eigen::Index q = ctx.weight.size();
  Eigen::VectorXd su(q), sv(q);
  for (Eigen::Index k = 0; k < q; ++k) {
    su(k) = ctx.geo.tu.col(k).dot(ctx.conormal.col(k));
    sv(k) = ctx.geo.tv.col(k).dot(ctx.conormal.col(k));
  }
  dn.noalias() = ctx.basis.du * su.asDiagonal();
  dn.noalias() += ctx.basis.dv * sv.asDiagonal();
}

void NitscheForm::add(const BoundaryContext& ctx, Eigen::MatrixXd& local) const {
  thread_local Eigen::MatrixXd dn, wphi;
  conormal_derivatives(ctx, dn);
  wphi.noalias() = ctx.basis.value * ctx.weight.asDiagonal();
  local.noalias() -= wphi * dn.transpose();
  local.noalias() -= dn * wphi.transpose();
  local.noalias() += penalty_(ctx) * wphi * ctx.basis.value.transpose();
}

void NitscheLoadForm::add(const BoundaryContext& ctx, Eigen::VectorXd& local) const {
  thread_local Eigen::MatrixXd dn;
  Eigen::VectorXd g;
  g_->values(ctx.geo.x, g);
  conormal_derivatives(ctx, dn);
  const Eigen::VectorXd wg = g.cwiseProduct(ctx.weight);
  local.noalias() += penalty_(ctx) * ctx.basis.value * wg - dn * wg;
}

}  // namespace iga::fem
