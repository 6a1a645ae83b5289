// bem: free terms c(P) (the rigid-body identity), the singular and nearly singular kernel quadrature.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "bem/assembly.hpp"
#include "bem/boundary_discretization.hpp"
#include "bem/kernel_quadrature.hpp"
#include "bem/laplace_kernel.hpp"
#include "bem_geometries.hpp"
#include "fem/threads.hpp"
#include "quadrature/gauss_legendre.hpp"

using iga::Index;
namespace tb = iga::test::bem;
constexpr double kPi = std::numbers::pi;

TEST(BemFreeTerm, CornersAndSmoothPoints) {
  const auto sq = tb::square(-0.3, 0.9);
  for (Index e = 0; e < 4; ++e) {
    EXPECT_NEAR(iga::bem::free_term(sq, e, 1.0), 0.25, 1e-10) << "corner at the end of edge " << e;
    EXPECT_NEAR(iga::bem::free_term(sq, e, 0.0), 0.25, 1e-10);
    EXPECT_NEAR(iga::bem::free_term(sq, e, 0.37), 0.5, 1e-12);
  }
  const auto hole = tb::square_with_hole();
  for (Index e = 4; e < 8; ++e) {
    EXPECT_NEAR(hole.interior_angle(e), 1.5 * kPi, 1e-12);
    EXPECT_NEAR(iga::bem::free_term(hole, e, 1.0), 0.75, 1e-10) << "reflex corner at the end of edge " << e;
  }
  // A triangle with angles π/2, π/3, π/6.
  const auto tri = tb::polygons({{{0.0, 0.0}, {1.0, 0.0}, {0.0, std::sqrt(3.0)}}});
  for (Index e = 0; e < 3; ++e) {
    EXPECT_NEAR(iga::bem::free_term(tri, e, 1.0), tri.interior_angle(e) / (2 * kPi), 1e-10);
  }
  EXPECT_NEAR(tri.interior_angle(2), kPi / 2, 1e-12);
  const auto loop = tb::smooth_loop();
  for (Index e = 0; e < loop.num_elements(); ++e) {
    for (double t : {0.0, 0.25, 0.5, 1.0}) EXPECT_NEAR(iga::bem::free_term(loop, e, t), 0.5, 1e-12);
  }
}

TEST(BemFreeTerm, RowSumsOfTheDoubleLayer) {
  // c(P_i) = −Σ_j ∫ φ_j ∂v/∂n: 1/2 at every collocation point (none sits on a corner).
  for (int p : {1, 2, 3}) {
    iga::bem::DiscretizationOptions o;
    o.degree = p;
    o.refine = 2;
    const iga::bem::BoundaryDiscretization d(tb::square_with_hole(), std::vector<int>(8, 0), o);
    const iga::bem::BemMatrices m = iga::bem::assemble(d);
    EXPECT_LT((m.free_term.array() - 0.5).abs().maxCoeff(), 1e-12) << "p " << p;
    EXPECT_LT((m.H * Eigen::VectorXd::Ones(d.num_dofs())).cwiseAbs().maxCoeff(), 1e-13);
  }
}

TEST(BemKernelQuadrature, SingleLayerOnAStraightElement) {
  // ∫_0^1 −ln|s − s0| ds / (2π) on the segment [(0,0), (1,0)] (closed form:
  // −(s0 ln s0 + (1−s0) ln(1−s0) − 1)/(2π)), and against s²: closed form by parts.
  const auto sq = tb::square(0.0, 1.0);
  for (double s0 : {0.0, 0.3, 0.5, 1.0}) {
    iga::bem::KernelNodes n;
    iga::bem::append_kernel_nodes(sq, 0, 0.0, 1.0, Eigen::Vector2d(s0, 0.0), s0, n);
    double i0 = 0.0, i2 = 0.0;
    for (std::size_t k = 0; k < n.size(); ++k) {
      i0 += n.single[k];
      i2 += n.single[k] * n.t[k] * n.t[k];
    }
    auto xlogx = [](double x) { return x > 0 ? x * std::log(x) : 0.0; };
    const double exact0 = -(xlogx(s0) + xlogx(1 - s0) - 1.0) / (2 * kPi);
    // ∫_0^1 s² ln|s − s0| ds = [((s−s0)³/3 + s0 (s−s0)² + s0² (s−s0)) ln|s−s0| − (s−s0)³/9 − s0 (s−s0)²/2 − s0² (s−s0)]
    auto prim = [&](double s) {
      const double u = s - s0;
      const double l = u == 0.0 ? 0.0 : std::log(std::abs(u));
      return (u * u * u / 3 + s0 * u * u + s0 * s0 * u) * l - u * u * u / 9 - s0 * u * u / 2 - s0 * s0 * u;
    };
    const double exact2 = -(prim(1.0) - prim(0.0)) / (2 * kPi);
    EXPECT_NEAR(i0, exact0, 1e-15) << "s0 " << s0;
    EXPECT_NEAR(i2, exact2, 1e-15) << "s0 " << s0;
  }
}

TEST(BemKernelQuadrature, NearlySingular) {
  // A point at distance δ above the middle of the segment [(0,0), (1,0)]: ∫ ∂v/∂n ds = −(angle subtended)/(2π)
  // (n = (0, −1) outward for the square's bottom edge, so (Q − P)·n = δ), and ∫ v ds in closed form.
  const auto sq = tb::square(0.0, 1.0);
  for (double delta : {1e-1, 1e-3, 1e-6, 1e-10}) {
    const Eigen::Vector2d p(0.4, delta);
    iga::bem::KernelNodes n;
    iga::bem::append_kernel_nodes(sq, 0, 0.0, 1.0, p, std::numeric_limits<double>::quiet_NaN(), n);
    double dl = 0.0, sl = 0.0;
    for (std::size_t k = 0; k < n.size(); ++k) {
      dl += n.dbl[k];
      sl += n.single[k];
    }
    const double angle = std::atan(0.6 / delta) + std::atan(0.4 / delta);
    // The nodes' parameters carry an absolute rounding of ~1e-16 (t ∈ [0, 1]), a relative perturbation of
    // ~1e-16/δ of the near field: measured 3e-13 at δ = 1e-6, 6e-10 at δ = 1e-10; the bound is 1e-18/δ.
    EXPECT_NEAR(dl, -angle / (2 * kPi), std::max(1e-13, 1e-18 / delta)) << "delta " << delta;
    // ∫ ln sqrt(u² + δ²) du = u ln sqrt(u² + δ²) − u + δ atan(u/δ)
    auto prim = [&](double u) { return 0.5 * u * std::log(u * u + delta * delta) - u + delta * std::atan(u / delta); };
    EXPECT_NEAR(sl, -(prim(0.6) - prim(-0.4)) / (2 * kPi), std::max(1e-14, 1e-18 / delta)) << "delta " << delta;
    EXPECT_FALSE(n.hit_point);
  }
}

TEST(BemAssembly, SameMatricesForAnyNumberOfThreads) {
  iga::bem::DiscretizationOptions o;
  o.degree = 3;
  o.refine = 2;
  const iga::bem::BoundaryDiscretization d(tb::square_with_hole(), {0, 0, 1, 1, 1, 0, 1, 0}, o);
  const int before = iga::fem::num_threads();
  iga::fem::set_num_threads(1);
  const iga::bem::BemMatrices a = iga::bem::assemble(d);
  iga::fem::set_num_threads(2);
  const iga::bem::BemMatrices b = iga::bem::assemble(d);
  iga::fem::set_num_threads(before);
  EXPECT_EQ((a.H - b.H).cwiseAbs().maxCoeff(), 0.0);
  EXPECT_EQ((a.G - b.G).cwiseAbs().maxCoeff(), 0.0);
}
