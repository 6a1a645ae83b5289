// Second derivatives through the geometry map (ElementContext with derivatives = 2): physical Hessians and
// Laplacians against central differences of the first-derivative pipeline on a curved map, and exactness for
// the coordinate functions.
#include <gtest/gtest.h>

#include "basis/bspline/patches.hpp"
#include "basis/registry.hpp"
#include "fem/assembler.hpp"
#include "quadrature/rule_provider.hpp"

namespace {

using namespace iga;

// Physical gradients (2 × nloc) of element e's functions at reference point p, by the first-derivative path.
Eigen::Matrix2Xd gradients(const basis::Geometry& g, Index e, const Eigen::Vector2d& p) {
  Eigen::Matrix2Xd pts(2, 1);
  pts.col(0) = p;
  basis::BasisValues bv;
  basis::GeometryValues gv;
  g.space().evaluate(e, pts, 1, bv);
  g.evaluate(e, bv, gv);
  Eigen::Matrix2Xd out(2, bv.value.rows());
  for (Index a = 0; a < bv.value.rows(); ++a) {
    const Eigen::Vector3d grad = gv.tu.col(0) * bv.du(a, 0) + gv.tv.col(0) * bv.dv(a, 0);
    out.col(a) = grad.head<2>();
  }
  return out;
}

TEST(SecondDerivatives, HessianMatchesFiniteDifferencesOnTheQuarterAnnulus) {
  basis::BackendFacts facts;
  const basis::Refinement r = basis::refine_uniform(basis::bspline::make_quarter_annulus(3), 2, facts);
  const basis::Geometry& g = r.geometry;
  const auto rules = quadrature::make_rule_provider("gauss:3", 3);
  const fem::Assembler assembler(g, *rules);
  fem::ElementContext ctx;
  double worst = 0, worst_trace = 0, scale = 0;
  for (Index e : {Index{0}, Index{5}, g.space().num_elements() - 1}) {
    assembler.prepare(e, ctx, 2);
    const Index q = ctx.num_points();
    ASSERT_EQ(ctx.hessian.cols(), 3 * q);
    for (Index k = 0; k < q; ++k) {
      const Eigen::Vector2d p = ctx.rule->points.col(k);
      // H_x = [∂g/∂u ∂g/∂v] J^{-1}, with J^{-1} rows tu, tv (planar).
      const double h = 1e-5;
      const Eigen::Matrix2Xd gu = (gradients(g, e, p + Eigen::Vector2d(h, 0)) - gradients(g, e, p - Eigen::Vector2d(h, 0))) / (2 * h);
      const Eigen::Matrix2Xd gvv = (gradients(g, e, p + Eigen::Vector2d(0, h)) - gradients(g, e, p - Eigen::Vector2d(0, h))) / (2 * h);
      Eigen::Matrix2d kinv;
      kinv << ctx.geo.tu(0, k), ctx.geo.tu(1, k), ctx.geo.tv(0, k), ctx.geo.tv(1, k);
      for (Index a = 0; a < ctx.hessian.rows(); ++a) {
        Eigen::Matrix2d d;
        d.col(0) = gu.col(a);
        d.col(1) = gvv.col(a);
        const Eigen::Matrix2d fd = d * kinv;  // fd(i, j) = ∂(∂φ/∂x_i)/∂x_j
        const double hxx = ctx.hessian(a, k), hxy = ctx.hessian(a, q + k), hyy = ctx.hessian(a, 2 * q + k);
        scale = std::max(scale, fd.cwiseAbs().maxCoeff());
        worst = std::max({worst, std::abs(hxx - fd(0, 0)), std::abs(hxy - fd(0, 1)), std::abs(hxy - fd(1, 0)),
                          std::abs(hyy - fd(1, 1))});
        worst_trace = std::max(worst_trace, std::abs(ctx.laplacian(a, k) - (hxx + hyy)));
      }
    }
  }
  // Central differences with h = 1e-5 on functions of size ~1 with Hessians ~1e2: truncation ~h² · 1e3,
  // rounding ~1e-16 / h² · 1: both below 1e-5 relative.
  EXPECT_LT(worst / scale, 1e-6) << "scale " << scale;
  EXPECT_LT(worst_trace / scale, 1e-12);
}

TEST(SecondDerivatives, CoordinateFunctionsHaveZeroHessian) {
  basis::BackendFacts facts;
  const basis::Refinement r = basis::refine_uniform(basis::bspline::make_quarter_annulus(2), 1, facts);
  const basis::Geometry& g = r.geometry;
  const auto rules = quadrature::make_rule_provider("gauss:3", 3);
  const fem::Assembler assembler(g, *rules);
  fem::ElementContext ctx;
  double worst = 0;
  for (Index e = 0; e < g.space().num_elements(); ++e) {
    assembler.prepare(e, ctx, 2);
    const auto dofs = g.space().dofs(e);
    for (int c = 0; c < 2; ++c) {
      Eigen::VectorXd x(static_cast<Index>(dofs.size()));
      for (std::size_t a = 0; a < dofs.size(); ++a) x(static_cast<Index>(a)) = g.control_points()(dofs[a], c);
      worst = std::max({worst, (x.transpose() * ctx.hessian).cwiseAbs().maxCoeff(),
                        (x.transpose() * ctx.laplacian).cwiseAbs().maxCoeff()});
    }
  }
  EXPECT_LT(worst, 1e-11);
}

}  // namespace
