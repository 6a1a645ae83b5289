// Bézier patches of the polyhedral spline (basis/polyhedral/bezier.hpp): the regular bi-2 patch against the
// uniform quadratic B-splines of basis/bspline (Cox–de Boor, an independent implementation), Bernstein degree
// elevation (the surface is unchanged), and patch evaluation against finite differences and closed forms.
#include <gtest/gtest.h>

#include <Eigen/Core>
#include <memory>
#include <random>

#include "basis/bspline/knot_vector.hpp"
#include "basis/geometry.hpp"
#include "basis/polyhedral/bezier.hpp"
#include "core/error.hpp"

namespace {

using namespace iga::basis::polyhedral;
using iga::basis::bspline::KnotVector;

Eigen::MatrixXd random_matrix(Eigen::Index rows, Eigen::Index cols, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> d(-1.0, 1.0);
  Eigen::MatrixXd m(rows, cols);
  for (Eigen::Index i = 0; i < rows; ++i) {
    for (Eigen::Index j = 0; j < cols; ++j) m(i, j) = d(rng);
  }
  return m;
}

Eigen::Matrix2Xd random_points(int q, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> d(0.0, 1.0);
  Eigen::Matrix2Xd p(2, q);
  for (int k = 0; k < q; ++k) p.col(k) = Eigen::Vector2d(d(rng), d(rng));
  return p;
}

TEST(PolyhedralBezier, RegularPatchIsTheUniformBiquadraticBSpline) {
  // Open knots 0,0,0,1,2,3,4,5,5,5: on [2,3) the B-splines N_2, N_3, N_4 have uniform knots (0..3, 1..4,
  // 2..5), i.e. they are N^2(t − i) of eq. (2) with t = 2 + s. Their values and derivatives by Cox–de Boor.
  const KnotVector kv(2, {0, 0, 0, 1, 2, 3, 4, 5, 5, 5});
  const PatchMask mask = regular_mask();
  ASSERT_EQ(mask.coefficients.rows(), 9);
  ASSERT_EQ(mask.coefficients.cols(), 9);
  // Grid position (i, j) of the gathered vertices [v, e_0, f_0, e_1, f_1, e_2, f_2, e_3, f_3] (bezier.hpp).
  const int gi[9] = {1, 2, 2, 1, 0, 0, 0, 1, 2};
  const int gj[9] = {1, 1, 2, 2, 2, 1, 0, 0, 0};
  const Eigen::MatrixXd control = random_matrix(9, 3, 7);  // one point per gathered vertex
  const BezierPatch patch{2, 2, mask.coefficients * control};
  const Eigen::Matrix2Xd pts = random_points(25, 8);
  const PatchValues pv = evaluate(patch, pts, 2);
  for (int k = 0; k < pts.cols(); ++k) {
    const Eigen::MatrixXd nu = iga::basis::bspline::basis_functions(kv, 4, 2.0 + pts(0, k), 2);
    const Eigen::MatrixXd nv = iga::basis::bspline::basis_functions(kv, 4, 2.0 + pts(1, k), 2);
    Eigen::RowVector3d x = Eigen::RowVector3d::Zero(), xu = x, xv = x, xuu = x, xuv = x, xvv = x;
    for (int c = 0; c < 9; ++c) {
      const int i = gi[c], j = gj[c];
      x += nu(0, i) * nv(0, j) * control.row(c);
      xu += nu(1, i) * nv(0, j) * control.row(c);
      xv += nu(0, i) * nv(1, j) * control.row(c);
      xuu += nu(2, i) * nv(0, j) * control.row(c);
      xuv += nu(1, i) * nv(1, j) * control.row(c);
      xvv += nu(0, i) * nv(2, j) * control.row(c);
    }
    EXPECT_LT((pv.x.row(k) - x).norm(), 1e-14);
    EXPECT_LT((pv.xu.row(k) - xu).norm(), 1e-13);
    EXPECT_LT((pv.xv.row(k) - xv).norm(), 1e-13);
    EXPECT_LT((pv.xuu.row(k) - xuu).norm(), 1e-12);
    EXPECT_LT((pv.xuv.row(k) - xuv).norm(), 1e-12);
    EXPECT_LT((pv.xvv.row(k) - xvv).norm(), 1e-12);
  }
  // Partition of unity of the mask rows.
  for (int r = 0; r < 9; ++r) EXPECT_NEAR(mask.coefficients.row(r).sum(), 1.0, 1e-15);
}

TEST(PolyhedralBezier, DegreeElevationLeavesTheSurfaceUnchanged) {
  const Eigen::Matrix2Xd pts = random_points(40, 11);
  struct Case {
    int du, dv, tu, tv;
  };
  for (const Case c : {Case{2, 2, 3, 3}, Case{3, 2, 3, 3}, Case{1, 2, 4, 3}, Case{2, 2, 2, 2}}) {
    const BezierPatch p{c.du, c.dv, random_matrix((c.du + 1) * (c.dv + 1), 3, static_cast<unsigned>(c.du * 10 + c.dv))};
    const BezierPatch q = elevate(p, c.tu, c.tv);
    ASSERT_EQ(q.coefficients.rows(), (c.tu + 1) * (c.tv + 1));
    const PatchValues a = evaluate(p, pts, 2), b = evaluate(q, pts, 2);
    EXPECT_LT((a.x - b.x).cwiseAbs().maxCoeff(), 1e-14);
    EXPECT_LT((a.xu - b.xu).cwiseAbs().maxCoeff(), 1e-13);
    EXPECT_LT((a.xv - b.xv).cwiseAbs().maxCoeff(), 1e-13);
    EXPECT_LT((a.xuv - b.xuv).cwiseAbs().maxCoeff(), 1e-12);
    // The same on a mask: elevating the mask then applying it = applying it then elevating.
    PatchMask m{c.du, c.dv, p.coefficients.leftCols(2)};
    const PatchMask me = elevate(m, c.tu, c.tv);
    EXPECT_LT((me.coefficients - q.coefficients.leftCols(2)).cwiseAbs().maxCoeff(), 1e-15);
  }
  // Closed form of one step 2 → 3: (b0, (b0 + 2 b1)/3, (2 b1 + b2)/3, b2).
  const Eigen::MatrixXd e = elevation_matrix(2, 3);
  Eigen::MatrixXd expected(4, 3);
  expected << 1, 0, 0, 1.0 / 3, 2.0 / 3, 0, 0, 2.0 / 3, 1.0 / 3, 0, 0, 1;
  EXPECT_LT((e - expected).cwiseAbs().maxCoeff(), 3e-16);  // 1/3, 2/3 rounded: one ulp
  EXPECT_THROW(elevation_matrix(3, 2), iga::InputError);
  EXPECT_THROW(elevate(BezierPatch{2, 2, Eigen::MatrixXd::Zero(8, 3)}, 3, 3), iga::InputError);
}

TEST(PolyhedralBezier, EvaluationMatchesClosedForms) {
  // The bi-3 patch with b_ij = (i/3, j/3, (i/3)^2 (j/3)) represents (u, v, p(u) v) where the BB form of
  // u^2 in degree 3 has coefficients (0, 0, 1/3, 1): x = u, y = v, z = u^2 v.
  BezierPatch p{3, 3, Eigen::MatrixXd(16, 3)};
  const double sq[4] = {0.0, 0.0, 1.0 / 3.0, 1.0};
  for (int j = 0; j <= 3; ++j) {
    for (int i = 0; i <= 3; ++i) p.coefficients.row(j * 4 + i) << i / 3.0, j / 3.0, sq[i] * (j / 3.0);
  }
  const Eigen::Matrix2Xd pts = random_points(20, 13);
  const PatchValues v = evaluate(p, pts, 2);
  for (int k = 0; k < pts.cols(); ++k) {
    const double u = pts(0, k), w = pts(1, k);
    EXPECT_LT((v.x.row(k) - Eigen::RowVector3d(u, w, u * u * w)).norm(), 1e-14);
    EXPECT_LT((v.xu.row(k) - Eigen::RowVector3d(1, 0, 2 * u * w)).norm(), 1e-13);
    EXPECT_LT((v.xv.row(k) - Eigen::RowVector3d(0, 1, u * u)).norm(), 1e-13);
    EXPECT_LT((v.xuu.row(k) - Eigen::RowVector3d(0, 0, 2 * w)).norm(), 1e-12);
    EXPECT_LT((v.xuv.row(k) - Eigen::RowVector3d(0, 0, 2 * u)).norm(), 1e-12);
    EXPECT_LT(v.xvv.row(k).norm(), 1e-12);
  }
}

}  // namespace
