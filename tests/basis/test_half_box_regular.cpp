// The regular half-box patch (basis/half_box/regular_patch.hpp). The BB coefficients are checked against an
// independent route written here: H111 evaluated by numerical directional convolution (2.23) of the triangle
// indicator (Gauss–Legendre on the pieces between grid lines, exact for the piecewise polynomials up to
// rounding), on the three-directional grid with lines x, y, x + y ∈ Z.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <array>
#include <cmath>
#include <functional>
#include <random>
#include <vector>

#include "basis/half_box/patch_net.hpp"
#include "basis/half_box/regular_patch.hpp"
#include "core/error.hpp"
#include "test_half_box_support.hpp"

namespace {

using namespace iga::basis::half_box;
using Fn = std::function<double(double, double)>;
using iga::Index;

// ∫_0^1 f(p − τ d) dτ, split at the crossings of the grid lines, 3-point Gauss–Legendre per piece.
Fn convolve(Fn f, double dx, double dy) {
  return [f, dx, dy](double x, double y) {
    std::vector<double> ts{0.0, 1.0};
    const double a[3][2] = {{1, 0}, {0, 1}, {1, 1}};
    for (const auto& l : a) {
      const double c0 = l[0] * x + l[1] * y, c1 = l[0] * dx + l[1] * dy;
      if (c1 == 0) continue;
      for (int k = -10; k <= 10; ++k) {
        const double t = (c0 - k) / c1;
        if (t > 0 && t < 1) ts.push_back(t);
      }
    }
    std::sort(ts.begin(), ts.end());
    const double g[3] = {-std::sqrt(0.6), 0.0, std::sqrt(0.6)}, w[3] = {5.0 / 9, 8.0 / 9, 5.0 / 9};
    double s = 0;
    for (std::size_t i = 0; i + 1 < ts.size(); ++i) {
      const double m = 0.5 * (ts[i] + ts[i + 1]), h = 0.5 * (ts[i + 1] - ts[i]);
      for (int q = 0; q < 3; ++q) s += w[q] * h * f(x - (m + h * g[q]) * dx, y - (m + h * g[q]) * dy);
    }
    return s;
  };
}

// H111 from the up triangle U(0,0) and from the down triangle D(0,0); their supports are centred on U(1,0)
// and D(1,0) (13 triangles each).
const Fn& h_up() {
  static const Fn f = convolve(convolve(convolve([](double x, double y) { return (x > 0 && y > 0 && x + y < 1) ? 1.0 : 0.0; }, 1, 0), 0, 1), 1, -1);
  return f;
}
const Fn& h_down() {
  static const Fn f = convolve(convolve(convolve([](double x, double y) { return (x < 1 && y < 1 && x + y > 1) ? 1.0 : 0.0; }, 1, 0), 0, 1), 1, -1);
  return f;
}

// The 13 control points of the patch U(0,0) as grid triangles (up?, i, j), in the order of regular_patch.hpp.
struct Tri { bool up; int i, j; };
const std::array<Tri, 13> kOrder{{{true, 0, 0}, {false, 0, -1}, {false, 0, 0}, {false, -1, 0}, {true, -1, 0},
                                  {false, -1, -1}, {true, 0, -1}, {true, 1, -1}, {false, 1, -1}, {true, 1, 0},
                                  {true, 0, 1}, {false, -1, 1}, {true, -1, 1}}};

double blending(const Tri& t, double x, double y) { return (t.up ? h_up() : h_down())(x - (t.i - 1), y - t.j); }

TEST(HalfBoxRegular, MatchesNumericalConvolution) {
  const Eigen::Matrix2Xd uv = half_box_test::random_triangle_points(40, 11);
  iga::basis::BasisValues b;
  evaluate_regular(uv, 1, b);
  double err = 0;
  for (Index p = 0; p < uv.cols(); ++p)
    for (int i = 0; i < 13; ++i)
      err = std::max(err, std::abs(b.value(i, p) - blending(kOrder[static_cast<std::size_t>(i)], uv(0, p), uv(1, p))));
  // Rounding of three nested Gauss sums of terms below 1: 1e-14 is the observed accuracy with margin.
  EXPECT_LT(err, 1e-14);
}

TEST(HalfBoxRegular, SupportIsThirteenTriangles) {
  int up = 0, down = 0;
  for (int i = -4; i <= 4; ++i)
    for (int j = -4; j <= 4; ++j) {
      if (h_up()(i + 1.0 / 3, j + 1.0 / 3) > 1e-12) ++up;
      if (h_up()(i + 2.0 / 3, j + 2.0 / 3) > 1e-12) ++down;
    }
  EXPECT_EQ(up + down, 13);
}

TEST(HalfBoxRegular, SumWithMirrorIsCentrallySymmetric) {
  // H111 + H̄111 = M221 (thesis §2.2.5), a box spline, is centrally symmetric about the centre (3/2, 1/2) of
  // the rhombus U(1,0) ∪ D(1,0) on which the two copies are centred; each half alone is not.
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> d(-2.0, 2.0);
  double err = 0;
  for (int k = 0; k < 50; ++k) {
    const double x = 1.5 + d(rng), y = 0.5 + d(rng);
    const double m = h_up()(x, y) + h_down()(x, y), mr = h_up()(3 - x, 1 - y) + h_down()(3 - x, 1 - y);
    err = std::max(err, std::abs(m - mr));
  }
  EXPECT_LT(err, 1e-14);
}

TEST(HalfBoxRegular, BezierMatrixRankPartitionAndLinearPrecision) {
  const auto& m = bezier_matrix();
  Eigen::FullPivLU<Eigen::MatrixXd> lu(m);
  EXPECT_EQ(lu.rank(), 10);  // 13 functions span the cubics with a 3-dimensional kernel (thesis §3.2.1)
  for (int i = 0; i < 10; ++i) EXPECT_NEAR(m.row(i).sum(), 1.0, 1e-15);
  // Linear precision: control points at the centroids of their grid triangles give BB coefficients at the
  // BB abscissae (i,j,k)/3 of the patch, i.e. the patch is the identity map.
  Eigen::Matrix<double, 13, 2> c;
  for (int i = 0; i < 13; ++i) {
    const Tri& t = kOrder[static_cast<std::size_t>(i)];
    c(i, 0) = t.i + (t.up ? 1.0 : 2.0) / 3;
    c(i, 1) = t.j + (t.up ? 1.0 : 2.0) / 3;
  }
  const Eigen::Matrix<double, 10, 2> bb = m * c;
  const int idx[10][3] = {{3, 0, 0}, {2, 1, 0}, {2, 0, 1}, {1, 2, 0}, {1, 1, 1}, {1, 0, 2}, {0, 3, 0}, {0, 2, 1}, {0, 1, 2}, {0, 0, 3}};
  for (int r = 0; r < 10; ++r) {
    EXPECT_NEAR(bb(r, 0), idx[r][1] / 3.0, 1e-15);
    EXPECT_NEAR(bb(r, 1), idx[r][2] / 3.0, 1e-15);
  }
}

TEST(HalfBoxRegular, DerivativesMatchFiniteDifferences) {
  const Eigen::Matrix2Xd uv = half_box_test::random_triangle_points(10, 5);
  const double h = 1e-4;
  Eigen::Matrix2Xd all(2, 5 * uv.cols());
  for (Index p = 0; p < uv.cols(); ++p) {
    all.col(5 * p) = uv.col(p);
    all.col(5 * p + 1) = uv.col(p) + Eigen::Vector2d(h, 0);
    all.col(5 * p + 2) = uv.col(p) - Eigen::Vector2d(h, 0);
    all.col(5 * p + 3) = uv.col(p) + Eigen::Vector2d(0, h);
    all.col(5 * p + 4) = uv.col(p) - Eigen::Vector2d(0, h);
  }
  iga::basis::BasisValues b;
  evaluate_regular(all, 2, b);
  double e1 = 0, e2 = 0;
  for (Index p = 0; p < uv.cols(); ++p) {
    const Index c = 5 * p;
    // cubic: central differences have error h²/6 · |f'''| <= 1e-8·(bounded third derivatives ~ 6)
    e1 = std::max(e1, (b.du.col(c) - (b.value.col(c + 1) - b.value.col(c + 2)) / (2 * h)).cwiseAbs().maxCoeff());
    e1 = std::max(e1, (b.dv.col(c) - (b.value.col(c + 3) - b.value.col(c + 4)) / (2 * h)).cwiseAbs().maxCoeff());
    e2 = std::max(e2, (b.duu.col(c) - (b.du.col(c + 1) - b.du.col(c + 2)) / (2 * h)).cwiseAbs().maxCoeff());
    e2 = std::max(e2, (b.duv.col(c) - (b.du.col(c + 3) - b.du.col(c + 4)) / (2 * h)).cwiseAbs().maxCoeff());
    e2 = std::max(e2, (b.dvv.col(c) - (b.dv.col(c + 3) - b.dv.col(c + 4)) / (2 * h)).cwiseAbs().maxCoeff());
    EXPECT_NEAR(b.value.col(c).sum(), 1.0, 1e-15);
    EXPECT_NEAR(b.du.col(c).sum(), 0.0, 1e-14);
    EXPECT_NEAR(b.duu.col(c).sum(), 0.0, 1e-13);
  }
  EXPECT_LT(e1, 1e-7);
  EXPECT_LT(e2, 1e-7);
}

TEST(HalfBoxRegular, RejectsBadDerivativeOrder) {
  iga::basis::BasisValues b;
  EXPECT_THROW(evaluate_regular(Eigen::Matrix2Xd::Zero(2, 1), 3, b), iga::InputError);
}

TEST(HalfBoxRegular, C1AcrossPatchesOfAHexagonalTorus) {
  // All-hexagon closed net (dual of a 10 × 10 triangulated torus, perturbed): position and normal of the two
  // patches along every side at 7 points; the side correspondence follows from the faces at the corners.
  const iga::mesh::PolyMesh net = half_box_test::torus_net(10, 0, 0.2);
  double dx = 0, dn = 0;
  for (Index v = 0; v < net.num_vertices(); ++v) {
    const PatchNet p = patch_net(net, v);
    ASSERT_EQ(p.valence, 6);
    for (int side = 0; side < 3; ++side) {
      const Index fa = p.faces[static_cast<std::size_t>(side)], fb = p.faces[static_cast<std::size_t>((side + 1) % 3)];
      const Index w = p.points[static_cast<std::size_t>(1 + side)];  // u_side: neighbour shared by F_side, F_side+1
      const PatchNet q = patch_net(net, w);
      const Eigen::Vector2d corners[3] = {{0, 0}, {1, 0}, {0, 1}};
      int a = -1, bq = -1;
      for (int i = 0; i < 3; ++i) {
        if (q.faces[static_cast<std::size_t>(i)] == fa) a = i;
        if (q.faces[static_cast<std::size_t>(i)] == fb) bq = i;
      }
      ASSERT_GE(a, 0);
      ASSERT_GE(bq, 0);
      Eigen::Matrix2Xd up(2, 7), uq(2, 7);
      for (int k = 0; k < 7; ++k) {
        const double t = k / 6.0;
        up.col(k) = (1 - t) * corners[side] + t * corners[(side + 1) % 3];
        uq.col(k) = (1 - t) * corners[a] + t * corners[bq];
      }
      const auto ep = half_box_test::eval_patch(net, p, up), eq = half_box_test::eval_patch(net, q, uq);
      dx = std::max(dx, (ep.x - eq.x).cwiseAbs().maxCoeff());
      for (int k = 0; k < 7; ++k) {
        const Eigen::Vector3d np = ep.du.col(k).cross(ep.dv.col(k)).normalized(), nq = eq.du.col(k).cross(eq.dv.col(k)).normalized();
        dn = std::max(dn, np.cross(nq).norm());
      }
    }
  }
  EXPECT_LT(dx, 1e-13);
  EXPECT_LT(dn, 1e-12);
  std::printf("regular torus: max position jump %.2e, max normal jump (sin angle) %.2e\n", dx, dn);
}

}  // namespace
