#include "fem/forms.hpp"

namespace iga::fem {

namespace {
// local += [G_0 .. G_dim-1] diag(w, .., w) [G_0 .. G_dim-1]^T for N local functions and C = dim·Q gradient columns,
// at compile-time sizes, as column accumulators in registers (Eigen's GEBP packs its operands first, which costs as
// much as the product at these sizes; issue 17's profile). The product is symmetric: the columns of the left half
// take all N rows, those of the right half only the lower N/2, and the upper right block is mirrored (3/4 of the
// flops of the full product).
template <int N, int C>
void gram_fixed(const Eigen::MatrixXd& grad, const Eigen::VectorXd& w, Eigen::MatrixXd& local) {
  static_assert(N % 2 == 0);
  constexpr int H = N / 2;
  using Grad = Eigen::Matrix<double, N, C>;
  const Eigen::Map<const Grad> g(grad.data());
  const Eigen::Index q = w.size();
  Grad scaled;
  for (Eigen::Index c = 0; c < C; ++c) scaled.col(c) = g.col(c) * w(c % q);
  Eigen::Matrix<double, N, N> k;
  for (int j = 0; j < H; ++j) {
    Eigen::Matrix<double, N, 1> acc = Eigen::Matrix<double, N, 1>::Zero();
    for (int c = 0; c < C; ++c) acc += scaled.col(c) * g(j, c);
    k.col(j) = acc;
  }
  for (int j = H; j < N; ++j) {
    Eigen::Matrix<double, H, 1> acc = Eigen::Matrix<double, H, 1>::Zero();
    for (int c = 0; c < C; ++c) acc += scaled.col(c).template tail<H>() * g(j, c);
    k.col(j).template tail<H>() = acc;
  }
  k.template topRightCorner<H, H>() = k.template bottomLeftCorner<H, H>().transpose();
  Eigen::Map<Eigen::Matrix<double, N, N>>(local.data()) += k;
}
}  // namespace

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
  if (ctx.grad.rows() == 16 && ctx.grad.cols() == 32) return gram_fixed<16, 32>(ctx.grad, w, local);
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
