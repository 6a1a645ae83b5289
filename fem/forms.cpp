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

}  // namespace iga::fem
