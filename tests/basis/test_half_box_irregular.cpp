// Exact evaluation of EF patches (basis/half_box/irregular_patch.hpp) and patch gathering (patch_net.hpp).
// Independent routes: one global subdivision step with the stencils (subdivide) followed by evaluation of the
// four children must give the same surface (refinability); valence 6 must give the regular patch; central
// differences; the limit of derivatives at the EF corner; C1 (normals) across every side of a closed net
// with pentagons and heptagons; the characteristic map built from the DFT block D_1 (3.34).
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <complex>
#include <numbers>
#include <random>
#include <utility>
#include <array>

#include "basis/half_box/irregular_patch.hpp"
#include "basis/half_box/local_net.hpp"
#include "basis/half_box/patch_net.hpp"
#include "basis/half_box/regular_patch.hpp"
#include "basis/half_box/subdivision.hpp"
#include "basis/half_box/subdivision_structure.hpp"
#include "core/error.hpp"
#include "test_half_box_support.hpp"

namespace {

using namespace iga::basis::half_box;
using iga::Index;
using half_box_test::eval_patch;
namespace mesh = iga::mesh;

struct Errors {
  double value = 0, derivative = 0;
};

// Compares patch p of `net` with its four children in the once-subdivided net at the points uv.
void compare_with_children(const mesh::PolyMesh& net, const NetSubdivision& sub, const PatchNet& p,
                           const Eigen::Matrix2Xd& uv, Errors& err) {
  const Index v = p.vertex;
  const Index h0 = half_edge_of(net, p.faces[0], v);
  const Index h1 = net.half_edge(net.half_edge(h0).prev).twin, h2 = net.half_edge(net.half_edge(h1).prev).twin;
  const auto coarse = eval_patch(net, p, uv);
  for (Index i = 0; i < uv.cols(); ++i) {
    const double u = uv(0, i), w = uv(1, i);
    Index child, f0;
    Eigen::Matrix2d j = 2 * Eigen::Matrix2d::Identity();
    Eigen::Vector2d y(2 * u, 2 * w);
    if (u + w <= 0.5) {
      child = h0, f0 = p.faces[0];
    } else if (u >= 0.5) {
      child = h1, f0 = sub.edge_face[static_cast<std::size_t>(net.half_edge(h0).prev)], y(0) -= 1;
    } else if (w >= 0.5) {
      child = h2, f0 = sub.edge_face[static_cast<std::size_t>(h0)], y(1) -= 1;
    } else {
      child = sub.vertex_point[static_cast<std::size_t>(v)], f0 = sub.edge_face[static_cast<std::size_t>(net.half_edge(h0).prev)];
      j << 2, 2, -2, 0;
      y = j * Eigen::Vector2d(u, w) + Eigen::Vector2d(-1, 1);
    }
    const PatchNet q = gather_patch(sub.net, half_edge_of(sub.net, f0, child));
    const auto fine = eval_patch(sub.net, q, y);
    err.value = std::max(err.value, (fine.x.col(0) - coarse.x.col(i)).norm());
    const Eigen::Vector3d du = j(0, 0) * fine.du.col(0) + j(1, 0) * fine.dv.col(0);
    const Eigen::Vector3d dv = j(0, 1) * fine.du.col(0) + j(1, 1) * fine.dv.col(0);
    err.derivative = std::max({err.derivative, (du - coarse.du.col(i)).norm(), (dv - coarse.dv.col(i)).norm()});
  }
}

mesh::PolyMesh with_random_points(const mesh::PolyMesh& m, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> d(-1.0, 1.0);
  std::vector<Eigen::Vector3d> pts;
  for (Index v = 0; v < m.num_vertices(); ++v) pts.push_back(m.point(v) + 0.3 * Eigen::Vector3d(d(rng), d(rng), d(rng)));
  std::vector<std::vector<Index>> faces;
  for (Index f = 0; f < m.num_faces(); ++f) faces.emplace_back(m.face(f).begin(), m.face(f).end());
  return mesh::PolyMesh::build(std::move(pts), std::move(faces));
}

TEST(HalfBoxIrregular, SubdivideThenEvaluateOnLocalNets) {
  // Points in all layers 1..4 (u + v down to 1/16) and at random.
  Eigen::Matrix2Xd uv = half_box_test::random_triangle_points(60, 21);
  for (Index i = 0; i < 20; ++i) uv.col(i) /= std::ldexp(1.0, static_cast<int>(i % 4));
  for (int n = 3; n <= 12; ++n) {
    const mesh::PolyMesh net = with_random_points(ring_net(n), 100 + static_cast<unsigned>(n));
    const NetSubdivision sub = subdivide_local(net);
    const PatchNet p = gather_patch(net, net.face_half_edge(0));
    EXPECT_EQ(p.valence, n);
    Errors e;
    compare_with_children(net, sub, p, uv, e);
    EXPECT_LT(e.value, 1e-13) << n;
    EXPECT_LT(e.derivative, 1e-12) << n;
  }
}

TEST(HalfBoxIrregular, SubdivideThenEvaluateOnAClosedNetWithPentagonsAndHeptagons) {
  const mesh::PolyMesh torus = half_box_test::torus_net(12, 2, 0.15);
  EXPECT_FALSE(efs_separated(torus));
  const mesh::PolyMesh net = subdivide(torus).net;
  EXPECT_TRUE(efs_separated(net));
  const NetSubdivision sub = subdivide(net);
  const Eigen::Matrix2Xd uv = half_box_test::random_triangle_points(12, 5);
  Errors reg, ef;
  int efs = 0;
  for (Index v = 0; v < net.num_vertices(); ++v) {
    const PatchNet p = patch_net(net, v);
    if (p.valence != 6) ++efs;
    compare_with_children(net, sub, p, uv, p.valence == 6 ? reg : ef);
  }
  EXPECT_EQ(efs, 2 * (5 + 5 + 7 + 7));  // two flips: 2 pentagons + 2 heptagons each
  std::printf("closed net: regular patches %.2e / %.2e, EF patches %.2e / %.2e (values / first derivatives)\n",
              reg.value, reg.derivative, ef.value, ef.derivative);
  EXPECT_LT(reg.value, 1e-12);
  EXPECT_LT(reg.derivative, 1e-12);
  EXPECT_LT(ef.value, 1e-12);
  EXPECT_LT(ef.derivative, 1e-12);
}

// The evaluator applies bezier_operator = tile_operator^T · bezier_matrix()^T to the Bernstein values; the
// two-stage product of (3.40) as written, H111^T(t) = bezier_matrix()^T · Bernstein(t), then the tile operator,
// must give the same values and first derivatives up to regrouped rounding (1e-15 relative to max(1, |entry|),
// points on layers 1..60, n = 3..12; measured worst 8.9e-16), and the same second derivatives bit for bit
// (they stay two-stage: regrouped, their rounding of summands of size 4^(l−1) reaches 1e-11 relative at
// layer 10 and more deeper down).
TEST(HalfBoxIrregular, FusedTileOperatorsEqualTheTwoStageProduct) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> d(0.0, 1.0);
  const auto mt = bezier_matrix().transpose();
  double overall = 0;
  for (int n = 3; n <= 12; ++n) {
    const SubdivisionStructure& s = subdivision_structure(n);
    Eigen::Matrix2Xd uv(2, 60);
    for (int p = 0; p < 60; ++p) {
      double u = d(rng), v = d(rng);
      if (u + v > 1) u = 1 - u, v = 1 - v;
      uv.col(p) = std::ldexp(1.0, -p) * Eigen::Vector2d(u, v);  // layer about p + 1
    }
    iga::basis::BasisValues out;
    evaluate_irregular(n, uv, 2, out);
    double worst = 0;
    for (int p = 0; p < 60; ++p) {
      int e = 0;
      std::frexp(uv(0, p) + uv(1, p), &e);
      const int layer = std::max(1, 1 - e);
      const double ul = std::ldexp(uv(0, p), layer - 1), vl = std::ldexp(uv(1, p), layer - 1);
      const int k = tile_of(ul, vl);
      const TileMap& t = s.tiles[static_cast<std::size_t>(k)];
      const Eigen::Vector2d x = t.jacobian * Eigen::Vector2d(ul, vl) + t.offset;
      BernsteinValues b;
      bernstein_cubic(x(0), x(1), 2, b);
      const Eigen::Matrix2d& j = t.jacobian;
      const double f = std::ldexp(1.0, layer - 1);
      using Vector13 = Eigen::Matrix<double, kRegularPatchSize, 1>;
      const Vector13 hs = mt * b.du, ht = mt * b.dv, hss = mt * b.duu, hst = mt * b.duv, htt = mt * b.dvv;
      const double f2 = f * f;
      auto second = [&](int a, int c) -> Vector13 {
        return f2 * (j(0, a) * j(0, c) * hss + (j(0, a) * j(1, c) + j(1, a) * j(0, c)) * hst + j(1, a) * j(1, c) * htt);
      };
      const auto opv = s.tile_operator(k, layer, false).transpose(), opd = s.tile_operator(k, layer, true).transpose();
      const std::array<std::pair<Eigen::VectorXd, Eigen::VectorXd>, 6> pairs{{
          {opv * Vector13(mt * b.value), out.value.col(p)},
          {opd * (f * (j(0, 0) * hs + j(1, 0) * ht)), out.du.col(p)},
          {opd * (f * (j(0, 1) * hs + j(1, 1) * ht)), out.dv.col(p)},
          {opd * second(0, 0), out.duu.col(p)},
          {opd * second(0, 1), out.duv.col(p)},
          {opd * second(1, 1), out.dvv.col(p)}}};
      for (std::size_t c = 0; c < pairs.size(); ++c) {
        const auto& [two_stage, evaluated] = pairs[c];
        if (c >= 3) {
          EXPECT_EQ(two_stage, evaluated) << "n = " << n << ", point " << p << ", second derivative " << c - 3;
          continue;
        }
        for (Index i = 0; i < two_stage.size(); ++i) {
          worst = std::max(worst, std::abs(two_stage(i) - evaluated(i)) / std::max(1.0, std::abs(two_stage(i))));
        }
      }
    }
    EXPECT_LT(worst, 1e-15) << "n = " << n;
    overall = std::max(overall, worst);
  }
  std::printf("fused tile operators: worst relative difference of values and first derivatives %.2g\n", overall);
}

TEST(HalfBoxIrregular, ValenceSixIsTheRegularPatch) {
  const Eigen::Matrix2Xd uv = half_box_test::random_triangle_points(50, 8);
  iga::basis::BasisValues a, b;
  evaluate_irregular(6, uv, 2, a);
  evaluate_regular(uv, 2, b);
  EXPECT_LT((a.value - b.value).cwiseAbs().maxCoeff(), 1e-14);
  EXPECT_LT((a.du - b.du).cwiseAbs().maxCoeff(), 1e-13);
  EXPECT_LT((a.dv - b.dv).cwiseAbs().maxCoeff(), 1e-13);
  // Second derivatives carry 4^(l−1) on layer l and the random points reach layer ~6: 1e-11.
  EXPECT_LT((a.duu - b.duu).cwiseAbs().maxCoeff(), 1e-11);
  EXPECT_LT((a.duv - b.duv).cwiseAbs().maxCoeff(), 1e-11);
  EXPECT_LT((a.dvv - b.dvv).cwiseAbs().maxCoeff(), 1e-11);
}

TEST(HalfBoxIrregular, PartitionOfUnityAndFiniteDifferences) {
  for (int n : {3, 4, 5, 7, 8, 12}) {
    Eigen::Matrix2Xd uv = half_box_test::random_triangle_points(20, 30 + static_cast<unsigned>(n));
    for (Index i = 0; i < 10; ++i) uv.col(i) *= std::ldexp(1.0, -static_cast<int>(3 * i));  // down to 2^-27
    iga::basis::BasisValues b;
    evaluate_irregular(n, uv, 2, b);
    for (Index i = 0; i < uv.cols(); ++i) {
      EXPECT_NEAR(b.value.col(i).sum(), 1.0, 1e-14);
      EXPECT_NEAR(b.du.col(i).sum(), 0.0, 1e-12);
      EXPECT_NEAR(b.dv.col(i).sum(), 0.0, 1e-12);
    }
    // Central differences at layer-1..3 points, h = 1e-6 relative to the layer (inside one tile).
    const Eigen::Matrix2Xd base = half_box_test::random_triangle_points(10, 60 + static_cast<unsigned>(n));
    double e1 = 0, e2 = 0;
    for (Index i = 0; i < base.cols(); ++i) {
      const Eigen::Vector2d x = base.col(i);
      const double s = x.sum(), h = 1e-6 * s;
      Eigen::Matrix2Xd pts(2, 5);
      pts << x(0), x(0) + h, x(0) - h, x(0), x(0), x(1), x(1), x(1), x(1) + h, x(1) - h;
      if ((pts.colwise().sum().array() > 1).any() || (pts.array() < 0).any()) continue;
      iga::basis::BasisValues c;
      evaluate_irregular(n, pts, 2, c);
      e1 = std::max(e1, s * (c.du.col(0) - (c.value.col(1) - c.value.col(2)) / (2 * h)).cwiseAbs().maxCoeff());
      e1 = std::max(e1, s * (c.dv.col(0) - (c.value.col(3) - c.value.col(4)) / (2 * h)).cwiseAbs().maxCoeff());
      e2 = std::max(e2, s * s * (c.duu.col(0) - (c.du.col(1) - c.du.col(2)) / (2 * h)).cwiseAbs().maxCoeff());
      e2 = std::max(e2, s * s * (c.duv.col(0) - (c.du.col(3) - c.du.col(4)) / (2 * h)).cwiseAbs().maxCoeff());
      e2 = std::max(e2, s * s * (c.dvv.col(0) - (c.dv.col(3) - c.dv.col(4)) / (2 * h)).cwiseAbs().maxCoeff());
    }
    // Scaled by the layer size; central-difference truncation (h/s)² plus rounding 1e-16 s/h: 1e-8.
    EXPECT_LT(e1, 1e-8) << n;
    EXPECT_LT(e2, 1e-8) << n;
  }
}

TEST(HalfBoxIrregular, LimitAndTangentsAtTheCorner) {
  for (int n = 3; n <= 12; ++n) {
    const SubdivisionStructure& s = subdivision_structure(n);
    // The derivatives converge along 2^-m (1/3, 1/3) (tangent_stencils); m = 40, 45, 50.
    Eigen::Matrix2Xd uv(2, 4);
    const double e = std::ldexp(1.0, -40) / 3;
    uv << 0, e, e / 32, e / 1024, 0, e, e / 32, e / 1024;
    iga::basis::BasisValues b;
    evaluate_irregular(n, uv, 1, b);
    EXPECT_LT((b.value.col(0) - s.limit_stencil.transpose()).norm(), 1e-15);
    for (Index i = 1; i < 4; ++i) {
      // The value moves by about s · |grad| with s = u + v <= 2^-40: 1e-11.
      EXPECT_LT((b.value.col(i) - b.value.col(0)).cwiseAbs().maxCoeff(), 1e-11) << n;
      // Derivatives converge like m 2^-m (Jordan block of 1/4); without deflation rounding would be ~2^40 eps.
      EXPECT_LT((b.du.col(i) - b.du.col(0)).cwiseAbs().maxCoeff(), 1e-10) << n;
      EXPECT_LT((b.dv.col(i) - b.dv.col(0)).cwiseAbs().maxCoeff(), 1e-10) << n;
    }
    EXPECT_THROW(evaluate_irregular(n, Eigen::Matrix2Xd::Zero(2, 1), 2, b), iga::NumericalError);
  }
  iga::basis::BasisValues b;
  EXPECT_THROW(evaluate_irregular(5, Eigen::Matrix2Xd::Constant(2, 1, 0.7), 0, b), iga::InputError);
}

// Maximum normal jump (sin of the angle) and position jump over all sides of all patches at parameters ts.
void side_jumps(const mesh::PolyMesh& net, const std::vector<double>& ts, double& dx, double& dn, bool ef_only) {
  const Eigen::Vector2d corners[3] = {{0, 0}, {1, 0}, {0, 1}};
  for (Index v = 0; v < net.num_vertices(); ++v) {
    const PatchNet p = patch_net(net, v);
    if (ef_only && p.valence == 6) continue;
    for (int side = 0; side < 3; ++side) {
      const Index fa = p.faces[static_cast<std::size_t>(side)], fb = p.faces[static_cast<std::size_t>((side + 1) % 3)];
      // The neighbour across the side shares fa and fb with v: the next or the previous vertex of fa.
      const Index hv = half_edge_of(net, fa, v);
      const Index w = net.half_edge(net.half_edge(hv).twin).face == fb ? net.half_edge_target(hv)
                                                                       : net.half_edge(net.half_edge(hv).prev).origin;
      const PatchNet q = patch_net(net, w);
      int a = -1, b = -1;
      for (int i = 0; i < 3; ++i) {
        if (q.faces[static_cast<std::size_t>(i)] == fa) a = i;
        if (q.faces[static_cast<std::size_t>(i)] == fb) b = i;
      }
      ASSERT_GE(a, 0);
      ASSERT_GE(b, 0);
      Eigen::Matrix2Xd up(2, static_cast<Index>(ts.size())), uq(2, static_cast<Index>(ts.size()));
      for (std::size_t k = 0; k < ts.size(); ++k) {
        up.col(static_cast<Index>(k)) = (1 - ts[k]) * corners[side] + ts[k] * corners[(side + 1) % 3];
        uq.col(static_cast<Index>(k)) = (1 - ts[k]) * corners[a] + ts[k] * corners[b];
      }
      const auto ep = eval_patch(net, p, up), eq = eval_patch(net, q, uq);
      dx = std::max(dx, (ep.x - eq.x).cwiseAbs().maxCoeff());
      for (Index k = 0; k < up.cols(); ++k) {
        const Eigen::Vector3d np = ep.du.col(k).cross(ep.dv.col(k)).normalized(), nq = eq.du.col(k).cross(eq.dv.col(k)).normalized();
        dn = std::max(dn, np.cross(nq).norm());
      }
    }
  }
}

TEST(HalfBoxIrregular, C1AcrossAllSidesOfAClosedNet) {
  const mesh::PolyMesh net = subdivide(half_box_test::torus_net(12, 2, 0.15)).net;
  double dx = 0, dn = 0, dx_ef = 0, dn_ef = 0;
  side_jumps(net, {0.0, 1.0 / 6, 0.5, 5.0 / 6, 1.0}, dx, dn, false);
  // Close to the EF corners (the sides between two EF patches are spokes of the EF).
  side_jumps(net, {1e-9, 1e-6, 1e-3, 0.01, 0.1, 0.3, 0.7}, dx_ef, dn_ef, true);
  std::printf("closed net C1: all sides %.2e / %.2e, near EFs %.2e / %.2e (position / sin normal angle)\n", dx, dn, dx_ef, dn_ef);
  EXPECT_LT(dx, 1e-12);
  EXPECT_LT(dn, 1e-10);
  EXPECT_LT(dx_ef, 1e-12);
  EXPECT_LT(dn_ef, 1e-10);
}

TEST(HalfBoxIrregular, CharacteristicMapIsRegularAndInjective) {
  using cd = std::complex<double>;
  for (int n = 3; n <= 8; ++n) {
    // Natural configuration: eigenvector ω^k g of A_n, g the eigenvector of λ = 1/2 of the lower-triangular
    // block D_1 = Σ ω^k A_k (3.34), solved by forward substitution.
    const Eigen::MatrixXd& a = subdivision_structure(n).ring_matrix;
    const cd om = std::polar(1.0, -2 * std::numbers::pi / n);
    Eigen::Matrix4cd d = Eigen::Matrix4cd::Zero();
    for (int k = 0; k < n; ++k) d += std::pow(om, k) * a.block(0, 4 * k, 4, 4).cast<cd>();
    Eigen::Vector4cd g;
    g(0) = 1;
    for (int j = 1; j < 4; ++j) {
      cd s = 0;
      for (int i = 0; i < j; ++i) s += d(j, i) * g(i);
      g(j) = s / (0.5 - d(j, j));
    }
    const mesh::PolyMesh ring = ring_net(n);
    std::vector<Eigen::Vector3d> pts;
    for (int k = 0; k < n; ++k)
      for (int j = 0; j < 4; ++j) {
        const cd z = std::pow(om, k) * g(j);
        pts.emplace_back(z.real(), z.imag(), 0.0);
      }
    std::vector<std::vector<Index>> faces;
    for (Index f = 0; f < ring.num_faces(); ++f) faces.emplace_back(ring.face(f).begin(), ring.face(f).end());
    const mesh::PolyMesh net = mesh::PolyMesh::build(pts, faces);
    // Jacobian on a grid of layer 1 of every patch; outer (s = 1) and inner (s = 1/2) curves around the EF.
    double jmin = 1e300, jmax = -1e300, turn_outer = 0, turn_inner = 0;
    bool monotone = true;
    const int m = 24;
    for (int curve = 0; curve < 2; ++curve) {
      double prev = std::nan(""), first = std::nan(""), sign = 0, total = 0;
      for (int k = 0; k < n; ++k) {
        const PatchNet p = gather_patch(net, half_edge_of(net, 0, 4 * k));
        const double s = curve == 0 ? 1.0 : 0.5;
        Eigen::Matrix2Xd uv(2, m);
        for (int i = 0; i < m; ++i) uv.col(i) << s * (1.0 - double(i) / m), s * double(i) / m;
        const auto e = eval_patch(net, p, uv);
        for (int i = 0; i < m; ++i) {
          const double ang = std::atan2(e.x(1, i), e.x(0, i));
          if (std::isnan(first)) first = ang;
          if (!std::isnan(prev)) {
            const double da = std::remainder(ang - prev, 2 * std::numbers::pi);
            if (sign == 0) sign = da > 0 ? 1 : -1;
            if (da * sign <= 0) monotone = false;
            total += da;
          }
          prev = ang;
        }
      }
      total += std::remainder(first - prev, 2 * std::numbers::pi);
      (curve == 0 ? turn_outer : turn_inner) = total;
    }
    for (int k = 0; k < n; ++k) {
      const PatchNet p = gather_patch(net, half_edge_of(net, 0, 4 * k));
      Eigen::Matrix2Xd uv(2, 0);
      std::vector<Eigen::Vector2d> grid;
      for (int i = 0; i <= m; ++i)
        for (int j = 0; i + j <= m; ++j)
          if (i + j >= m / 2) grid.emplace_back(double(i) / m, double(j) / m);
      uv.resize(2, static_cast<Index>(grid.size()));
      for (std::size_t i = 0; i < grid.size(); ++i) uv.col(static_cast<Index>(i)) = grid[i];
      const auto e = eval_patch(net, p, uv);
      for (Index i = 0; i < uv.cols(); ++i) {
        const double jac = e.du(0, i) * e.dv(1, i) - e.du(1, i) * e.dv(0, i);
        jmin = std::min(jmin, jac);
        jmax = std::max(jmax, jac);
      }
    }
    std::printf("n = %d: Jacobian in [%.3e, %.3e], turning outer %.4f inner %.4f (2 pi = %.4f)\n", n, jmin, jmax,
                turn_outer, turn_inner, 2 * std::numbers::pi);
    EXPECT_TRUE(jmin > 0 || jmax < 0) << n;
    EXPECT_GT(std::min(std::abs(jmin), std::abs(jmax)), 1e-3 * std::max(std::abs(jmin), std::abs(jmax))) << n;
    EXPECT_TRUE(monotone) << n;
    EXPECT_NEAR(std::abs(turn_outer), 2 * std::numbers::pi, 1e-12) << n;
    EXPECT_NEAR(std::abs(turn_inner), 2 * std::numbers::pi, 1e-12) << n;
  }
}

TEST(HalfBoxPatchNet, OrdersAndErrors) {
  const mesh::PolyMesh net = ring_net(5);
  const PatchNet p = gather_patch(net, net.face_half_edge(0));
  // EF counter-clockwise from v_00; F1 = H_0 from v_(n−1)0; the spoke v_01; F2 = H_1 (ring_net numbering).
  EXPECT_EQ(p.points, (std::vector<Index>{0, 4, 8, 12, 16, 17, 19, 2, 1, 3, 6, 5}));
  EXPECT_EQ(p.faces, (std::array<Index, 3>{0, 1, 2}));
  // v_01 lies on the boundary of the local net.
  EXPECT_THROW(patch_net(net, 1), iga::InputError);
  // On the unsubdivided torus with flips a vertex between a pentagon and a heptagon cannot have a patch.
  const mesh::PolyMesh torus = half_box_test::torus_net(12, 1, 0.0);
  bool thrown = false;
  for (Index v = 0; v < torus.num_vertices() && !thrown; ++v) {
    try {
      patch_net(torus, v);
    } catch (const iga::UnsupportedError& e) {
      thrown = true;
      EXPECT_NE(std::string(e.what()).find("subdivide the net once"), std::string::npos);
    }
  }
  EXPECT_TRUE(thrown);
}

}  // namespace
