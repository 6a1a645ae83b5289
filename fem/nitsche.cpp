#include "fem/nitsche.hpp"

#include <Eigen/Dense>
#include <algorithm>

#include "core/error.hpp"
#include "fem/forms.hpp"

namespace iga::fem {

namespace {

// Collects B_K = Σ ∫ ∂_n φ ∂_n φᵀ ds per element (assemble_boundary calls it once per edge, in order) and the
// side lengths; adds nothing to the global matrix.
class NormalDerivativeGram final : public BoundaryBilinearForm {
 public:
  explicit NormalDerivativeGram(Index elements)
      : b_(static_cast<std::size_t>(elements)), length_(static_cast<std::size_t>(elements), 0.0) {}
  void add(const BoundaryContext& ctx, Eigen::MatrixXd&) const override {
    Eigen::MatrixXd dn;
    conormal_derivatives(ctx, dn);
    Eigen::MatrixXd& b = b_[static_cast<std::size_t>(ctx.element)];
    if (b.size() == 0) b = Eigen::MatrixXd::Zero(dn.rows(), dn.rows());
    b.noalias() += dn * ctx.weight.asDiagonal() * dn.transpose();
    length_[static_cast<std::size_t>(ctx.element)] += ctx.weight.sum();
  }
  const Eigen::MatrixXd& b(Index e) const { return b_[static_cast<std::size_t>(e)]; }
  double length(Index e) const { return length_[static_cast<std::size_t>(e)]; }

 private:
  mutable std::vector<Eigen::MatrixXd> b_;
  mutable std::vector<double> length_;
};

}  // namespace

std::vector<double> nitsche_penalties(const Assembler& assembler, std::span<const basis::BoundaryEdge> edges,
                                      double* equivalent_gamma) {
  const Index ne = assembler.geometry().space().num_elements();
  const NormalDerivativeGram gram(ne);
  Eigen::SparseMatrix<double> unused;
  assembler.assemble_boundary(edges, &gram, nullptr, &unused, nullptr);
  const Eigen::MatrixXd beta = assembler.integrate_per_element(1, [&](const ElementContext& ctx, Eigen::Ref<Eigen::VectorXd> out) {
    const Eigen::MatrixXd& b = gram.b(ctx.element);
    if (b.size() == 0) return;
    const Eigen::Index q = ctx.weight.size(), n = b.rows();
    Eigen::MatrixXd a = Eigen::MatrixXd::Zero(n, n);
    for (int c = 0; c < ctx.dim; ++c) {
      const auto g = ctx.grad.middleCols(c * q, q);
      a.noalias() += g * ctx.weight.asDiagonal() * g.transpose();
    }
    // Remove the constants' null direction: A + s 1 1ᵀ is definite, and B 1 = 0 keeps their eigenvalue at 0.
    a += (a.trace() / static_cast<double>(n * n)) * Eigen::MatrixXd::Ones(n, n);
    const Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> es(b, a, Eigen::EigenvaluesOnly);
    if (es.info() != Eigen::Success) {
      throw NumericalError("Nitsche penalty: the local eigenvalue problem of element " + std::to_string(ctx.element + 1) +
                           " failed (its stiffness matrix is not definite beyond the constants)");
    }
    out(0) = 4.0 * es.eigenvalues().maxCoeff();
  });
  std::vector<double> out(static_cast<std::size_t>(ne));
  double gamma = 0.0;
  for (Index e = 0; e < ne; ++e) {
    out[static_cast<std::size_t>(e)] = beta(0, e);
    gamma = std::max(gamma, beta(0, e) * gram.length(e));
  }
  if (equivalent_gamma) *equivalent_gamma = gamma;
  return out;
}

double nitsche_terms(const Assembler& assembler, std::span<const basis::BoundaryEdge> edges,
                     const std::shared_ptr<const Function>& g, double gamma, Eigen::SparseMatrix<double>& a,
                     Eigen::VectorXd& b) {
  std::vector<double> beta;
  NitschePenalty penalty;
  double used = gamma;
  if (gamma > 0.0) {
    penalty = [gamma](const BoundaryContext& ctx) { return gamma / ctx.weight.sum(); };
  } else {
    beta = nitsche_penalties(assembler, edges, &used);
    penalty = [&beta](const BoundaryContext& ctx) { return beta[static_cast<std::size_t>(ctx.element)]; };
  }
  const NitscheForm form(penalty);
  const NitscheLoadForm load(g, penalty);
  assembler.assemble_boundary(edges, &form, &load, &a, &b);
  return used;
}

}  // namespace iga::fem
