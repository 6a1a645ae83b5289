#include "fem/nitsche.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>

#include "core/error.hpp"
#include "fem/forms.hpp"

namespace iga::fem {

namespace {

// Collects B_K = Σ ∫ s sᵀ ds per element (assemble_boundary calls it once per edge, in order) and the side
// lengths; adds nothing to the global matrix.
class SideGram final : public BoundaryBilinearForm {
 public:
  SideGram(Index elements, const SideOperator& side, int derivatives)
      : side_(side), derivatives_(derivatives), b_(static_cast<std::size_t>(elements)),
        length_(static_cast<std::size_t>(elements), 0.0) {}
  int derivatives() const override { return derivatives_; }
  void add(const BoundaryContext& ctx, Eigen::MatrixXd&) const override {
    Eigen::MatrixXd s;
    side_(ctx, s);
    Eigen::MatrixXd& b = b_[static_cast<std::size_t>(ctx.element)];
    if (b.size() == 0) b = Eigen::MatrixXd::Zero(s.rows(), s.rows());
    b.noalias() += s * ctx.weight.asDiagonal() * s.transpose();
    length_[static_cast<std::size_t>(ctx.element)] += ctx.weight.sum();
  }
  const Eigen::MatrixXd& b(Index e) const { return b_[static_cast<std::size_t>(e)]; }
  double length(Index e) const { return length_[static_cast<std::size_t>(e)]; }

 private:
  const SideOperator& side_;
  int derivatives_;
  mutable std::vector<Eigen::MatrixXd> b_;
  mutable std::vector<double> length_;
};

// λ_max(B, A) on the range of A (A, B symmetric positive semi-definite).
double largest_on_range(const Eigen::MatrixXd& b, const Eigen::MatrixXd& a, Index element) {
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> ea(a);
  if (ea.info() != Eigen::Success || !(ea.eigenvalues().maxCoeff() > 0.0)) {
    throw NumericalError("Nitsche penalty: the local eigenvalue problem of element " + std::to_string(element + 1) +
                         " failed (its element matrix is zero or not finite)");
  }
  const double cut = 1e-11 * ea.eigenvalues().maxCoeff();
  std::vector<Eigen::Index> keep;
  for (Eigen::Index i = 0; i < a.rows(); ++i) {
    if (ea.eigenvalues()(i) > cut) keep.push_back(i);
  }
  Eigen::MatrixXd v(a.rows(), static_cast<Eigen::Index>(keep.size()));
  for (std::size_t j = 0; j < keep.size(); ++j) {
    v.col(static_cast<Eigen::Index>(j)) = ea.eigenvectors().col(keep[j]) / std::sqrt(ea.eigenvalues()(keep[j]));
  }
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eb(v.transpose() * b * v, Eigen::EigenvaluesOnly);
  return eb.eigenvalues().maxCoeff();
}

}  // namespace

std::vector<double> local_penalties(const Assembler& assembler, std::span<const basis::BoundaryEdge> edges,
                                    const SideOperator& side, const ElementOperator& element, int derivatives,
                                    double* equivalent_gamma) {
  const Index ne = assembler.geometry().space().num_elements();
  const SideGram gram(ne, side, derivatives);
  Eigen::SparseMatrix<double> unused;
  assembler.assemble_boundary(edges, &gram, nullptr, &unused, nullptr);
  const Eigen::MatrixXd beta = assembler.integrate_per_element(1, [&](const ElementContext& ctx, Eigen::Ref<Eigen::VectorXd> out) {
    const Eigen::MatrixXd& b = gram.b(ctx.element);
    if (b.size() == 0) return;
    const Eigen::Index q = ctx.weight.size(), n = b.rows();
    const Eigen::MatrixXd& op = element(ctx);
    Eigen::MatrixXd a = Eigen::MatrixXd::Zero(n, n);
    for (Eigen::Index c = 0; c < op.cols() / q; ++c) {
      const auto block = op.middleCols(c * q, q);
      a.noalias() += block * ctx.weight.asDiagonal() * block.transpose();
    }
    out(0) = 4.0 * largest_on_range(b, a, ctx.element);
  }, derivatives);
  std::vector<double> out(static_cast<std::size_t>(ne));
  double gamma = 0.0;
  for (Index e = 0; e < ne; ++e) {
    out[static_cast<std::size_t>(e)] = beta(0, e);
    gamma = std::max(gamma, beta(0, e) * gram.length(e));
  }
  if (equivalent_gamma) *equivalent_gamma = gamma;
  return out;
}

std::vector<double> nitsche_penalties(const Assembler& assembler, std::span<const basis::BoundaryEdge> edges,
                                      double* equivalent_gamma) {
  return local_penalties(
      assembler, edges, [](const BoundaryContext& ctx, Eigen::MatrixXd& dn) { conormal_derivatives(ctx, dn); },
      [](const ElementContext& ctx) -> const Eigen::MatrixXd& { return ctx.grad; }, 1, equivalent_gamma);
}

NitschePenalty nitsche_penalty(const Assembler& assembler, std::span<const basis::BoundaryEdge> edges, double gamma,
                               const SideOperator& side, const ElementOperator& element, int derivatives,
                               double* used) {
  if (gamma > 0.0) {
    if (used) *used = gamma;
    return [gamma](const BoundaryContext& ctx) { return gamma / ctx.weight.sum(); };
  }
  auto beta = std::make_shared<const std::vector<double>>(
      local_penalties(assembler, edges, side, element, derivatives, used));
  return [beta](const BoundaryContext& ctx) { return (*beta)[static_cast<std::size_t>(ctx.element)]; };
}

double nitsche_terms(const Assembler& assembler, std::span<const basis::BoundaryEdge> edges,
                     const std::shared_ptr<const Function>& g, double gamma, Eigen::SparseMatrix<double>& a,
                     Eigen::VectorXd& b) {
  double used = gamma;
  const NitschePenalty penalty = nitsche_penalty(
      assembler, edges, gamma, [](const BoundaryContext& ctx, Eigen::MatrixXd& dn) { conormal_derivatives(ctx, dn); },
      [](const ElementContext& ctx) -> const Eigen::MatrixXd& { return ctx.grad; }, 1, &used);
  const NitscheForm form(penalty);
  const NitscheLoadForm load(g, penalty);
  assembler.assemble_boundary(edges, &form, &load, &a, &b);
  return used;
}

}  // namespace iga::fem
