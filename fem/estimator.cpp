#include "fem/estimator.hpp"

#include <chrono>
#include <cmath>

#include "core/error.hpp"
#include "fem/assembler.hpp"

namespace iga::fem {

namespace {

// u_h's physical gradient at the points of a side context (3 × q).
void side_gradient(const basis::Space& space, const BoundaryContext& ctx, const Eigen::VectorXd& u, Eigen::Matrix3Xd& grad) {
  const auto dofs = space.dofs(ctx.element);
  thread_local Eigen::VectorXd local;
  local.resize(static_cast<Index>(dofs.size()));
  for (std::size_t a = 0; a < dofs.size(); ++a) local(static_cast<Index>(a)) = u(dofs[a]);
  const Eigen::RowVectorXd gu = local.transpose() * ctx.basis.du;
  const Eigen::RowVectorXd gv = local.transpose() * ctx.basis.dv;
  grad = (ctx.geo.tu.array().rowwise() * gu.array() + ctx.geo.tv.array().rowwise() * gv.array()).matrix();
}

}  // namespace

Estimate estimate_residual(const PoissonSolver& solver) {
  const auto t0 = std::chrono::steady_clock::now();
  const PoissonResult& r = solver.result();
  if (r.u.size() == 0) throw InputError("estimate_residual: the problem has not been solved");
  const Assembler& assembler = solver.assembler();
  const basis::Space& space = solver.geometry().space();
  const PoissonProblem& problem = solver.problem();
  const Eigen::VectorXd& u = r.u;
  const double c = problem.reaction;

  // Element residuals h_K² ‖f + Δu_h − c u_h‖²_K, with h_K² = |K|.
  const Eigen::MatrixXd element = assembler.integrate_per_element(
      1,
      [&](const ElementContext& ctx, Eigen::Ref<Eigen::VectorXd> out) {
        const auto dofs = space.dofs(ctx.element);
        thread_local Eigen::VectorXd local, f;
        local.resize(static_cast<Index>(dofs.size()));
        for (std::size_t a = 0; a < dofs.size(); ++a) local(static_cast<Index>(a)) = u(dofs[a]);
        Eigen::RowVectorXd res = local.transpose() * ctx.laplacian;
        if (c != 0.0) res -= c * (local.transpose() * ctx.basis.value);
        if (problem.source) {
          problem.source->values(ctx.geo.x, f);
          res += f.transpose();
        }
        out(0) = ctx.weight.sum() * res.array().square().matrix().dot(ctx.weight);
      },
      2);
  Estimate est;
  Eigen::VectorXd eta2 = element.row(0).transpose();
  est.residual = std::sqrt(eta2.sum());

  // Jumps of the normal flux across C0 interior edges: h_E ∫ [∂u_h/∂n]², half to each side.
  BoundaryContext side[2];
  Eigen::Matrix3Xd grad[2];
  double jump2 = 0.0;
  for (const basis::InteriorEdge& edge : space.interior_edges()) {
    if (edge.continuity > 0) continue;
    const quadrature::Rule1D& line = assembler.rules().side_rule(space.kind(edge.element[0]), edge.side[0]);
    for (int i = 0; i < 2; ++i) {
      assembler.prepare_side(edge.element[i], edge.side[i], edge.t0[i], edge.t1[i], line, side[i]);
      side_gradient(space, side[i], u, grad[i]);
    }
    const Eigen::RowVectorXd jump = ((grad[0] - grad[1]).array() * side[0].conormal.array()).colwise().sum();
    const double h = side[0].weight.sum();
    const double term = h * jump.array().square().matrix().dot(side[0].weight);
    eta2(edge.element[0]) += 0.5 * term;
    eta2(edge.element[1]) += 0.5 * term;
    jump2 += term;
    ++est.jump_edges;
  }
  est.jump = std::sqrt(jump2);

  // Neumann residuals h_E ∫ (g_N − ∂u_h/∂n)².
  double neumann2 = 0.0;
  Eigen::VectorXd g;
  for (const basis::BoundaryEdge& edge : solver.neumann_edges()) {
    assembler.prepare_side(edge.element, edge.side, 0.0, 1.0, assembler.rules().side_rule(space.kind(edge.element), edge.side), side[0]);
    side_gradient(space, side[0], u, grad[0]);
    problem.neumann->values(side[0].geo.x, side[0].conormal, g);
    const Eigen::RowVectorXd flux = (grad[0].array() * side[0].conormal.array()).colwise().sum();
    const Eigen::RowVectorXd res = g.transpose() - flux;
    const double term = side[0].weight.sum() * res.array().square().matrix().dot(side[0].weight);
    eta2(edge.element) += term;
    neumann2 += term;
  }
  est.neumann = std::sqrt(neumann2);
  if (!eta2.allFinite()) throw NumericalError("estimate_residual: an error indicator is not finite (check the data)");
  est.indicators = eta2.cwiseSqrt();
  est.total = std::sqrt(eta2.sum());
  est.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return est;
}

}  // namespace iga::fem
