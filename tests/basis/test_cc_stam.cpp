// Stam's evaluation of Catmull–Clark basis functions at an extraordinary vertex (basis/catmull_clark/stam.hpp).
// Expected values come from closed forms (eigenvalues, limit stencil, uniform bicubic B-splines), from an
// independent one-step Catmull–Clark refinement of an explicit mesh written here, from finite differences,
// and from OpenSubdiv's Bfr limit-surface evaluation (an independent implementation).
#include <gtest/gtest.h>
#include <opensubdiv/bfr/refinerSurfaceFactory.h>
#include <opensubdiv/bfr/surface.h>
#include <opensubdiv/far/topologyDescriptor.h>
#include <opensubdiv/far/topologyRefinerFactory.h>

#include <Eigen/Core>
#include <Eigen/LU>
#include <array>
#include <cmath>
#include <map>
#include <memory>
#include <numbers>
#include <random>
#include <set>
#include <thread>
#include <vector>

#include "basis/catmull_clark/stam.hpp"
#include "basis/catmull_clark/subdivision_matrix.hpp"
#include "core/error.hpp"

#include "cc_stam_test_support.hpp"

namespace {

using namespace cc_stam_test;
namespace osd = OpenSubdiv::OPENSUBDIV_VERSION;

TEST(CcStam, EigenStructure) {
  for (int n = 3; n <= 16; ++n) {
    const StamEvaluator& s = stam_evaluator(n);
    const Eigen::VectorXd& lambda = s.eigenvalues();
    const Eigen::MatrixXd &v = s.eigenvectors(), &vi = s.inverse_eigenvectors(), &a = s.subdivision_matrix();
    const int np = 2 * n + 8;
    ASSERT_EQ(lambda.size(), np);
    EXPECT_NEAR(lambda(0), 1.0, 1e-15) << n;
    EXPECT_LT(lambda(1), 1.0 - 1e-3) << n;  // the dominant eigenvalue is simple
    EXPECT_NEAR(lambda(1), subdominant(n), 1e-15) << n;
    EXPECT_NEAR(lambda(2), subdominant(n), 1e-15) << n;
    EXPECT_LT(lambda(3), subdominant(n) - 1e-3) << n;  // multiplicity exactly 2
    for (int i = 1; i < np; ++i) EXPECT_LE(lambda(i), lambda(i - 1)) << n;
    const double reconstruction = (v * lambda.asDiagonal() * vi - a).norm() / a.norm();
    EXPECT_LE(reconstruction, 1e-12) << n;
    EXPECT_LE((v * vi - Eigen::MatrixXd::Identity(np, np)).norm(), 1e-12) << n;
    EXPECT_LE((a * v - v * lambda.asDiagonal()).norm(), 1e-13) << n;
    EXPECT_LE((v.col(0) - Eigen::VectorXd::Ones(np)).norm(), 0.0) << n;
    // The outer block contributes 1/8, 1/16, 1/32 (twice each) and 1/64 exactly.
    for (double mu : {0.125, 0.0625, 0.03125, 0.015625}) {
      EXPECT_GE((lambda.array() == mu).count(), mu == 0.015625 ? 1 : 2) << n << " " << mu;
    }
    std::printf("valence %2d: reconstruction %.2e, cond(V) = %.1f\n", n, reconstruction, v.norm() * vi.norm());
  }
  // n = 4: the subdominant eigenvectors are the grid coordinates i and j (linear precision of B-splines).
  const StamEvaluator& s4 = stam_evaluator(4);
  for (int r = 0; r < 16; ++r) {
    EXPECT_NEAR(s4.eigenvectors()(r, 1), kRegularGrid[static_cast<std::size_t>(r)][0], 1e-14);
    EXPECT_NEAR(s4.eigenvectors()(r, 2), kRegularGrid[static_cast<std::size_t>(r)][1], 1e-14);
  }
}

// ---- 2. Subdivision matrix against an explicit refinement ----
TEST(CcStam, SubdivisionMatrixMatchesMeshRefinement) {
  std::mt19937 rng(2024);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  for (int n = 3; n <= 16; ++n) {
    const StamEvaluator& s = stam_evaluator(n);
    const Eigen::MatrixXd& abar = s.extended_subdivision_matrix();
    ASSERT_EQ(abar.rows(), 2 * n + 17);
    ASSERT_EQ(abar.cols(), 2 * n + 8);
    EXPECT_LE((abar.rowwise().sum() - Eigen::VectorXd::Ones(abar.rows())).cwiseAbs().maxCoeff(), 1e-15) << n;
    EXPECT_LE((abar.topRows(2 * n + 8) - s.subdivision_matrix()).norm(), 0.0);
    const SectorMesh m(n, 3);
    Eigen::Matrix3Xd x(3, m.num_vertices());
    for (Eigen::Index c = 0; c < x.cols(); ++c) x.col(c) << unit(rng), unit(rng), unit(rng);
    const std::vector<int> ids = local_vertices(m);
    Eigen::Matrix3Xd local(3, 2 * n + 8);
    for (int i = 0; i < 2 * n + 8; ++i) local.col(i) = x.col(ids[static_cast<std::size_t>(i)]);
    const Eigen::Matrix3Xd mapped = local * abar.transpose();
    const Refined ref = catmull_clark_step(m, x);
    // Expected new points: EV, edge points of its edges, face points of its faces, then the grid names.
    std::vector<Eigen::Vector3d> expected = {ref.vertex[0]};
    for (int k = 0; k < n; ++k) {
      const int e = m.id(k, 1, 0);
      expected.push_back(ref.edge.at({0, e}));
      expected.push_back(ref.face[static_cast<std::size_t>(k * m.r * m.r)]);
    }
    for (auto [i, j] : std::vector<std::array<int, 2>>{{2, -1},
                                                       {2, 0},
                                                       {2, 1},
                                                       {2, 2},
                                                       {1, 2},
                                                       {0, 2},
                                                       {-1, 2},
                                                       {3, -1},
                                                       {3, 0},
                                                       {3, 1},
                                                       {3, 2},
                                                       {3, 3},
                                                       {2, 3},
                                                       {1, 3},
                                                       {0, 3},
                                                       {-1, 3}}) {
      expected.push_back(refined_point(m, ref, i, j));
    }
    for (int r = 0; r < 2 * n + 17; ++r) {
      EXPECT_LE((mapped.col(r) - expected[static_cast<std::size_t>(r)]).norm(), 1e-14) << "n " << n << " row " << r;
    }
    for (int k = 1; k <= 3; ++k) {  // the picking matrices select one extended point per row
      EXPECT_TRUE(s.picking_matrix(k).rows() == 16 && (s.picking_matrix(k).array() == 1.0).count() == 16);
      EXPECT_EQ(s.picking_matrix(k).sum(), 16.0);
    }
  }
  for (int r = 0; r < 16; ++r) {  // the library's grid names agree with the contract's n = 4 listing
    const auto [i, j] = kRegularGrid[static_cast<std::size_t>(r)];
    EXPECT_EQ(iga::basis::catmull_clark::local_index(4, i, j), r);
  }
  EXPECT_EQ(iga::basis::catmull_clark::local_index(3, -1, 0), iga::basis::catmull_clark::local_index(3, 0, -1));
  EXPECT_THROW(iga::basis::catmull_clark::local_index(5, -1, -1), iga::InputError);
}

// ---- 3. n = 4 is the uniform bicubic B-spline ----
TEST(CcStam, ValenceFourIsBicubicBSpline) {
  std::mt19937 rng(7);
  Eigen::Matrix2Xd pts = sample_points(rng, 1000);
  Eigen::Matrix2Xd special(2, 12);
  special << 0, 1, 0.5, 0.5, 0, 1, 0, 0.25, std::ldexp(1.0, -30), 1e-12, 1e-300, 0.75,  //
      0, 1, 0.5, 0, 0.5, 0, 1, 0.125, 0, 3e-13, 0, 0.5;
  pts.conservativeResize(2, pts.cols() + special.cols());
  pts.rightCols(special.cols()) = special;
  BasisValues bv;
  stam_evaluator(4).evaluate(pts, 2, bv);
  double worst[6] = {0, 0, 0, 0, 0, 0};
  for (Eigen::Index p = 0; p < pts.cols(); ++p) {
    for (int r = 0; r < 16; ++r) {
      const auto bu = cardinal(pts(0, p) - kRegularGrid[static_cast<std::size_t>(r)][0]);
      const auto bw = cardinal(pts(1, p) - kRegularGrid[static_cast<std::size_t>(r)][1]);
      const double expected[6] = {bu[0] * bw[0], bu[1] * bw[0], bu[0] * bw[1],
                                  bu[2] * bw[0], bu[1] * bw[1], bu[0] * bw[2]};
      const Eigen::MatrixXd* blocks[6] = {&bv.value, &bv.du, &bv.dv, &bv.duu, &bv.duv, &bv.dvv};
      for (int d = 0; d < 6; ++d) worst[d] = std::max(worst[d], std::abs((*blocks[d])(r, p) - expected[d]));
    }
  }
  std::printf("n = 4 vs bicubic: value %.1e du %.1e dv %.1e duu %.1e duv %.1e dvv %.1e\n", worst[0], worst[1], worst[2],
              worst[3], worst[4], worst[5]);
  for (double w : worst) EXPECT_LE(w, 1e-13);
}

// ---- 4. Partition of unity, affine invariance, limit point ----
TEST(CcStam, PartitionOfUnityAffineInvarianceLimitPoint) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  for (int n = 3; n <= 8; ++n) {
    const StamEvaluator& s = stam_evaluator(n);
    const int np = s.num_points();
    const Eigen::Matrix2Xd pts = sample_points(rng, 1000);
    BasisValues bv;
    s.evaluate(pts, 2, bv);
    EXPECT_LE((bv.value.colwise().sum().array() - 1.0).abs().maxCoeff(), 1e-14) << n;
    for (const Eigen::MatrixXd* d : {&bv.du, &bv.dv, &bv.duu, &bv.duv, &bv.dvv}) {
      for (Eigen::Index p = 0; p < pts.cols(); ++p) {
        EXPECT_LE(std::abs(d->col(p).sum()), 1e-14 * (1.0 + d->col(p).cwiseAbs().sum())) << n << " " << p;
      }
    }
    // P = a + B x: the surface of P is the affine image of the surface of x.
    const Eigen::Matrix3Xd x = Eigen::Matrix3Xd::NullaryExpr(3, np, [&] { return unit(rng); });
    const Eigen::Vector3d shift(unit(rng), unit(rng), unit(rng));
    const Eigen::Matrix3d lin = Eigen::Matrix3d::NullaryExpr([&] { return unit(rng); });
    const Eigen::Matrix3Xd px = (lin * x).colwise() + shift;
    const Eigen::Matrix3Xd sx = x * bv.value, spx = px * bv.value;
    EXPECT_LE(max_abs((spx - ((lin * sx).colwise() + shift)).eval()), 1e-14) << n;
    EXPECT_LE(max_abs((px * bv.du - lin * x * bv.du).eval()), 1e-13 * (1.0 + max_abs(x * bv.du))) << n;
    // Limit point: closed form (n² V + 4 sum e + sum f) / (n (n + 5)), row 0 of V^{-1}, evaluation at (0,0).
    Eigen::VectorXd closed = Eigen::VectorXd::Zero(np);
    closed(0) = n * n;
    for (int k = 0; k < n; ++k) {
      closed(2 * k + 1) = 4.0;
      closed(2 * k + 2) = 1.0;
    }
    closed /= n * (n + 5.0);
    EXPECT_LE((s.limit_stencil() - closed).cwiseAbs().maxCoeff(), 1e-16) << n;
    EXPECT_LE((s.inverse_eigenvectors().row(0).transpose() - closed).cwiseAbs().maxCoeff(), 1e-14) << n;
    BasisValues at_ev;
    s.evaluate(Eigen::Matrix2Xd::Zero(2, 1), 1, at_ev);
    EXPECT_LE((at_ev.value.col(0) - closed).cwiseAbs().maxCoeff(), 1e-16) << n;
    // Close to the EV the surface converges to the limit point like lambda^l.
    Eigen::Matrix2Xd near(2, 1);
    near << 1e-15, 0.7e-15;
    s.evaluate(near, 0, at_ev);
    EXPECT_LE((at_ev.value.col(0) - closed).cwiseAbs().maxCoeff(), 1e-15 + 20.0 * std::pow(subdominant(n), 49)) << n;
  }
}

// ---- Tangent stencils at the EV (Stam's / Halstead's formula) ----
TEST(CcStam, TangentStencilsAtTheEv) {
  for (int n = 3; n <= 16; ++n) {
    const StamEvaluator& s = stam_evaluator(n);
    BasisValues bv;
    s.evaluate(Eigen::Matrix2Xd::Zero(2, 1), 2, bv);
    const double an = 1.0 + std::cos(2 * std::numbers::pi / n) +
                      std::cos(std::numbers::pi / n) * std::sqrt(2.0 * (9.0 + std::cos(2 * std::numbers::pi / n)));
    for (int dir = 0; dir < 2; ++dir) {
      const auto g = [&](int k) {
        return dir == 0 ? std::cos(2 * std::numbers::pi * k / n) : std::sin(2 * std::numbers::pi * k / n);
      };
      Eigen::VectorXd t = Eigen::VectorXd::Zero(2 * n + 8);
      for (int k = 0; k < n; ++k) {
        t(2 * k + 1) = an * g(k);
        t(2 * k + 2) = g(k) + g(k + 1);
      }
      const Eigen::VectorXd d = dir == 0 ? bv.du.col(0) : bv.dv.col(0);
      const double scale = d.dot(t) / t.squaredNorm();
      EXPECT_LE((d - scale * t).cwiseAbs().maxCoeff(), 1e-13) << n;  // proportional to the closed form
      EXPECT_NEAR(d.dot(s.eigenvectors().col(1 + dir)), 1.0, 1e-13) << n;
      EXPECT_NEAR(d.dot(s.eigenvectors().col(2 - dir)), 0.0, 1e-13) << n;
    }
    if (n == 4) {  // the exact bicubic derivative 1/12 t_u
      EXPECT_LE((bv.du.col(0) - s.inverse_eigenvectors().row(1).transpose()).cwiseAbs().maxCoeff(), 1e-14);
    }
  }
}

// ---- 5. Against OpenSubdiv's Bfr limit surface ----
// Largest deviations over 1200 random points with max(u,v) > 2^-level, where Bfr's irregular patch (refined
// `level` times) consists of exact B-spline sub-patches: basis stencils (relative to max(1, max |phi_i|)) for
// value, du, dv and second derivatives, and surface points / derivatives for random 3D control points
// (relative to the bounding box times max(1, sum |phi_i|)).
TEST(CcStam, DerivativesMatchFiniteDifferences) {
  std::mt19937 rng(3);
  // Levels up to 9: the central difference's rounding error eps 2^l / 1e-6 stays below ~1e-7 relative.
  std::uniform_real_distribution<double> unit(0.0, 1.0), exponent(0.0, 8.0);
  for (int n = 3; n <= 8; ++n) {
    const StamEvaluator& s = stam_evaluator(n);
    int checked = 0;
    double worst1 = 0.0, worst2 = 0.0;
    while (checked < 300) {
      const double scale = checked % 3 == 0 ? std::ldexp(1.0, -static_cast<int>(exponent(rng))) : 1.0;
      const double u = scale * unit(rng), v = scale * unit(rng);
      const StamEvaluator::Tile at = StamEvaluator::locate(u, v);
      if (at.level == 0) continue;
      // h = 1e-6 in the tile's own coordinates (1e-6 · 2^-l in u, v); all stencil points in the same tile.
      const double h = 1e-6 * std::ldexp(1.0, -at.level);
      Eigen::Matrix2Xd pts(2, 5);
      pts << u, u + h, u - h, u, u, v, v, v, v + h, v - h;
      bool same = true;
      for (int c = 1; c < 5; ++c) {
        const StamEvaluator::Tile t = StamEvaluator::locate(pts(0, c), pts(1, c));
        same = same && t.level == at.level && t.tile == at.tile;
      }
      if (!same || pts.minCoeff() < 0.0 || pts.maxCoeff() > 1.0) continue;
      BasisValues bv;
      s.evaluate(pts, 2, bv);
      const Eigen::VectorXd fd_u = (bv.value.col(1) - bv.value.col(2)) / (2 * h);
      const Eigen::VectorXd fd_v = (bv.value.col(3) - bv.value.col(4)) / (2 * h);
      const double s1 = std::max(bv.du.col(0).cwiseAbs().maxCoeff(), bv.dv.col(0).cwiseAbs().maxCoeff());
      const double e1 =
          std::max((fd_u - bv.du.col(0)).cwiseAbs().maxCoeff(), (fd_v - bv.dv.col(0)).cwiseAbs().maxCoeff());
      const Eigen::VectorXd fd_uu = (bv.du.col(1) - bv.du.col(2)) / (2 * h);
      const Eigen::VectorXd fd_uv = (bv.du.col(3) - bv.du.col(4)) / (2 * h);
      const Eigen::VectorXd fd_vu = (bv.dv.col(1) - bv.dv.col(2)) / (2 * h);
      const Eigen::VectorXd fd_vv = (bv.dv.col(3) - bv.dv.col(4)) / (2 * h);
      const double s2 = std::max({bv.duu.col(0).cwiseAbs().maxCoeff(), bv.duv.col(0).cwiseAbs().maxCoeff(),
                                  bv.dvv.col(0).cwiseAbs().maxCoeff()});
      const double e2 =
          std::max({(fd_uu - bv.duu.col(0)).cwiseAbs().maxCoeff(), (fd_uv - bv.duv.col(0)).cwiseAbs().maxCoeff(),
                    (fd_vu - bv.duv.col(0)).cwiseAbs().maxCoeff(), (fd_vv - bv.dvv.col(0)).cwiseAbs().maxCoeff()});
      worst1 = std::max(worst1, e1 / s1);
      worst2 = std::max(worst2, e2 / s2);
      ++checked;
    }
    std::printf("valence %d: finite differences, relative deviation first %.1e second %.1e\n", n, worst1, worst2);
    EXPECT_LE(worst1, 1e-6) << n;
    EXPECT_LE(worst2, 1e-6) << n;
  }
}

// ---- 7. The eigen-decomposition path against X^k Ā A^(l-1) by explicit powers in long double ----
// A's entries are rationals with denominator 64 n² ((3.45) and the regular weights 1/16, 3/32, 1/64), so the
// exact matrix is recovered as round(64 n² A) / (64 n²) in long double. (Powers of the double-rounded A differ
// from the exact scheme by ~eps 2^l in first derivatives, e.g. 3e-14 at l = 10 for n = 5.) The power form
// differentiates nets whose entries agree to ~lambda^l, losing eps_ld 2^l (first) and eps_ld 4^l (second
// derivatives); it serves as reference for values at every level and for derivatives up to levels 10 and 8.
TEST(CcStam, TilesMatchExplicitMatrixPowers) {
  using Ld = long double;
  using MatLd = Eigen::Matrix<Ld, Eigen::Dynamic, Eigen::Dynamic>;
  std::mt19937 rng(17);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (int n : {3, 4, 5, 6, 8, 12, 16}) {
    const StamEvaluator& s = stam_evaluator(n);
    const Ld den = 64.0L * n * n;
    const MatLd abar = (s.extended_subdivision_matrix().cast<Ld>() * den).array().round() / den;
    const MatLd a = abar.topRows(2 * n + 8);
    ASSERT_LE(static_cast<double>((abar - s.extended_subdivision_matrix().cast<Ld>()).cwiseAbs().maxCoeff()), 1e-16);
    MatLd power = MatLd::Identity(2 * n + 8, 2 * n + 8);  // A^(l-1)
    double worst[3] = {0, 0, 0};
    for (int level = 1; level <= 40; ++level, power = a * power) {
      for (int k = 1; k <= 3; ++k) {
        const MatLd net = s.picking_matrix(k).cast<Ld>() * abar * power;  // 16 × (2n+8)
        const double sl = unit(rng), tl = unit(rng);
        const double u = std::ldexp(k == 3 ? sl : 1.0 + sl, -level), v = std::ldexp(k == 1 ? tl : 1.0 + tl, -level);
        const StamEvaluator::Tile at = StamEvaluator::locate(u, v);
        ASSERT_TRUE(at.level == level && at.tile == k);
        Eigen::Matrix<Ld, 16, 6> b;  // value, du, dv, duu, duv, dvv of the 16 tile B-splines at (s, t)
        for (int bb = 0; bb < 4; ++bb) {
          for (int aa = 0; aa < 4; ++aa) {
            const auto cs = cardinal<Ld>(Ld(sl) + 1 - aa), ct = cardinal<Ld>(Ld(tl) + 1 - bb);
            b.row(aa + 4 * bb) << cs[0] * ct[0], cs[1] * ct[0], cs[0] * ct[1], cs[2] * ct[0], cs[1] * ct[1],
                cs[0] * ct[2];
          }
        }
        Eigen::Matrix2Xd pt(2, 1);
        pt << u, v;
        BasisValues bv;
        s.evaluate(pt, 2, bv);
        const Eigen::MatrixXd* ours[6] = {&bv.value, &bv.du, &bv.dv, &bv.duu, &bv.duv, &bv.dvv};
        for (int d = 0; d < 6; ++d) {
          const int order = d == 0 ? 0 : (d < 3 ? 1 : 2);
          if ((order == 1 && level > 10) || (order == 2 && level > 8)) continue;
          const Eigen::Matrix<Ld, Eigen::Dynamic, 1> ref =
              std::ldexp(Ld(1), order * level) * (net.transpose() * b.col(d));
          const Ld e =
              (ref - ours[d]->col(0).cast<Ld>()).cwiseAbs().maxCoeff() / std::max(Ld(1), ref.cwiseAbs().maxCoeff());
          worst[order] = std::max(worst[order], static_cast<double>(e));
        }
      }
    }
    std::printf(
        "valence %2d vs long-double powers: values (l <= 40) %.1e, first (l <= 10) %.1e, second (l <= 8) %.1e\n", n,
        worst[0], worst[1], worst[2]);
    EXPECT_LE(worst[0], 2e-15) << n;
    EXPECT_LE(worst[1], 5e-15) << n;
    EXPECT_LE(worst[2], 5e-14) << n;
  }
}

// ---- Tile rule, continuity across tile boundaries ----
TEST(CcStam, TileLocationAndContinuity) {
  using T = StamEvaluator::Tile;
  const auto eq = [](T a, int level, int tile) { return a.level == level && a.tile == tile; };
  EXPECT_TRUE(eq(StamEvaluator::locate(1.0, 1.0), 1, 2));
  EXPECT_TRUE(eq(StamEvaluator::locate(1.0, 0.0), 1, 1));
  EXPECT_TRUE(eq(StamEvaluator::locate(0.0, 1.0), 1, 3));
  EXPECT_TRUE(eq(StamEvaluator::locate(0.5, 0.0), 1, 1));
  EXPECT_TRUE(eq(StamEvaluator::locate(0.5, 0.5), 1, 2));
  EXPECT_TRUE(eq(StamEvaluator::locate(0.7, 0.5), 1, 2));
  EXPECT_TRUE(eq(StamEvaluator::locate(0.25, 0.5), 1, 3));
  EXPECT_TRUE(eq(StamEvaluator::locate(std::nextafter(0.5, 0.0), 0.1), 2, 1));
  EXPECT_TRUE(eq(StamEvaluator::locate(0.25, 0.25), 2, 2));
  EXPECT_TRUE(eq(StamEvaluator::locate(std::ldexp(1.0, -60), 0.0), 60, 1));
  EXPECT_TRUE(eq(StamEvaluator::locate(std::nextafter(std::ldexp(1.0, -60), 0.0), 0.0), 0, 0));
  EXPECT_TRUE(eq(StamEvaluator::locate(0.0, 0.0), 0, 0));
  // C2 across the tile and layer boundaries: both sides of each boundary agree.
  for (int n : {3, 5, 7}) {
    Eigen::Matrix2Xd pts(2, 8);
    const double below = std::nextafter(0.5, 0.0);
    pts << 0.5, below, 0.7, 0.7, 0.5, below, 0.3, 0.3,  //
        0.3, 0.3, 0.5, below, 0.7, 0.7, 0.5, below;
    BasisValues bv;
    stam_evaluator(n).evaluate(pts, 2, bv);
    for (int c = 0; c < 8; c += 2) {
      EXPECT_LE((bv.value.col(c) - bv.value.col(c + 1)).cwiseAbs().maxCoeff(), 1e-14) << n;
      EXPECT_LE((bv.du.col(c) - bv.du.col(c + 1)).cwiseAbs().maxCoeff(), 1e-12) << n;
      EXPECT_LE((bv.dv.col(c) - bv.dv.col(c + 1)).cwiseAbs().maxCoeff(), 1e-12) << n;
      EXPECT_LE((bv.duu.col(c) - bv.duu.col(c + 1)).cwiseAbs().maxCoeff(), 1e-10) << n;
      EXPECT_LE((bv.duv.col(c) - bv.duv.col(c + 1)).cwiseAbs().maxCoeff(), 1e-10) << n;
      EXPECT_LE((bv.dvv.col(c) - bv.dvv.col(c + 1)).cwiseAbs().maxCoeff(), 1e-10) << n;
    }
  }
}

// ---- Errors, caching, thread safety ----
TEST(CcStam, ErrorsCachingAndThreads) {
  EXPECT_THROW(StamEvaluator(2), iga::InputError);
  EXPECT_THROW(StamEvaluator(17), iga::InputError);
  EXPECT_THROW(stam_evaluator(1), iga::InputError);
  BasisValues bv;
  Eigen::Matrix2Xd outside(2, 1);
  outside << 1.5, 0.2;
  EXPECT_THROW(stam_evaluator(5).evaluate(outside, 0, bv), iga::InputError);
  EXPECT_THROW(stam_evaluator(5).evaluate(Eigen::Matrix2Xd::Zero(2, 1), 3, bv), iga::InputError);
  EXPECT_EQ(stam_evaluator(6).num_points(), 20);
  EXPECT_EQ(stam_evaluator(6).valence(), 6);
  // Concurrent first use (ctest runs each test in its own process): every thread gets the same objects.
  std::array<std::array<const StamEvaluator*, 17>, 4> seen{};
  std::vector<std::thread> threads;
  for (auto& row : seen)
    threads.emplace_back([&row] {
      for (int n = 16; n >= 3; --n) row[static_cast<std::size_t>(n)] = &stam_evaluator(n);
    });
  for (auto& th : threads) th.join();
  for (int n = 3; n <= 16; ++n) {
    for (const auto& row : seen) EXPECT_EQ(row[static_cast<std::size_t>(n)], &stam_evaluator(n));
  }
}

}  // namespace
