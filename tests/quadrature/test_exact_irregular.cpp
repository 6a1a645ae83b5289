// Exact integrals of Stam's functions at an interior EV (quadrature/exact/irregular_integrals.hpp) against
// identities (partition of unity, constants), the bicubic closed form for n = 4, and per-tile Gauss
// quadrature with many levels (error decreasing geometrically towards the exact value).
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <vector>

#include "basis/basis_values.hpp"
#include "basis/catmull_clark/stam.hpp"
#include "basis/catmull_clark/subdivision_matrix.hpp"
#include "core/error.hpp"
#include "quadrature/exact/irregular_integrals.hpp"
#include "quadrature/per_tile.hpp"

using namespace iga::quadrature;
using namespace iga::quadrature::exact;
using iga::basis::BasisValues;
using iga::basis::catmull_clark::stam_evaluator;

namespace {

struct Sampled {
  Eigen::VectorXd w;
  BasisValues b;
};

Sampled sample(int n, int p, int levels, int derivatives) {
  const Rule r = tiled_rule(p, levels);
  Sampled s;
  s.w = r.weights;
  stam_evaluator(n).evaluate(r.points, derivatives, s.b);
  return s;
}

const Eigen::MatrixXd& block(const BasisValues& b, int f) { return f < 0 ? b.value : (f == 0 ? b.du : b.dv); }

Eigen::MatrixXd quad_product(const Sampled& s, int f, int g) {
  return block(s.b, f) * s.w.asDiagonal() * block(s.b, g).transpose();
}

// Exact 1D integrals of products of the uniform cubic B-splines (order 0) and their derivatives (order 1)
// from monomial coefficients: ∫_0^1 t^k = 1/(k+1).
using Poly = std::array<double, 4>;  // c0 + c1 t + c2 t^2 + c3 t^3
std::array<Poly, 4> bspline_poly(int order) {
  const std::array<Poly, 4> v{{{1 / 6.0, -3 / 6.0, 3 / 6.0, -1 / 6.0},
                              {4 / 6.0, 0, -6 / 6.0, 3 / 6.0},
                              {1 / 6.0, 3 / 6.0, 3 / 6.0, -3 / 6.0},
                              {0, 0, 0, 1 / 6.0}}};
  if (order == 0) return v;
  std::array<Poly, 4> d{};
  for (int a = 0; a < 4; ++a)
    for (int k = 1; k < 4; ++k) d[a][k - 1] = k * v[a][k];
  return d;
}
double integrate(const Poly& p, const Poly& q) {
  double s = 0;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) s += p[i] * q[j] / (i + j + 1);
  return s;
}

}  // namespace

TEST(ExactIrregular, PhiSumsToAreaAndMatchesTiledQuadrature) {
  for (int n : {3, 5, 6, 7, 8, 12, 16}) {
    const IrregularIntegrals& I = irregular_integrals(n);
    EXPECT_NEAR(I.phi.sum(), 1.0, 1e-14) << n;
    const Sampled s = sample(n, 4, 40, 0);
    const Eigen::VectorXd q = s.b.value * s.w;
    EXPECT_LT((q - I.phi).cwiseAbs().maxCoeff(), 1e-14) << n;
    // Row sums of the product matrix: Σ_b ∫ φ_a φ_b = ∫ φ_a.
    EXPECT_LT((I.phi_phi.rowwise().sum() - I.phi).cwiseAbs().maxCoeff(), 1e-14) << n;
    EXPECT_LT((I.phi_phi - I.phi_phi.transpose()).cwiseAbs().maxCoeff(), 1e-16) << n;
    EXPECT_LT((quad_product(s, -1, -1) - I.phi_phi).cwiseAbs().maxCoeff(), 1e-14) << n;
  }
}

TEST(ExactIrregular, DerivativeProductsConstantsAndSymmetry) {
  for (int n = 3; n <= 16; ++n) {
    const IrregularIntegrals& I = irregular_integrals(n);
    for (int i = 0; i < 2; ++i)
      for (int j = 0; j < 2; ++j) {
        EXPECT_LT(I.d[i][j].rowwise().sum().cwiseAbs().maxCoeff(), 1e-13) << n;
        EXPECT_LT(I.d[i][j].colwise().sum().cwiseAbs().maxCoeff(), 1e-13) << n;
        EXPECT_LT((I.d[i][j] - I.d[j][i].transpose()).cwiseAbs().maxCoeff(), 1e-14) << n;
      }
  }
}

// Per-tile Gauss quadrature on levels 1..L misses the corner square [0, 2^-L]^2, where the derivative
// products are of size λ^(2L) (λ the subdominant eigenvalue): the error decays geometrically to the exact value.
TEST(ExactIrregular, DerivativeProductsAgainstTiledQuadrature) {
  for (int n : {3, 5, 6, 8}) {
    const IrregularIntegrals& I = irregular_integrals(n);
    std::vector<double> err;
    for (int levels = 12; levels <= 30; levels += 6) {
      const Sampled s = sample(n, 4, levels, 1);  // ∂uφ ∂uφ has degree 6 in v: 4 points
      double e = 0;
      for (int i = 0; i < 2; ++i)
        for (int j = 0; j < 2; ++j) e = std::max(e, (quad_product(s, i, j) - I.d[i][j]).cwiseAbs().maxCoeff());
      err.push_back(e);
      std::printf("n = %2d  L = %2d  max |tiled - exact| = %.3e\n", n, levels, e);
    }
    for (std::size_t k = 1; k < err.size(); ++k) EXPECT_TRUE(err[k] < err[k - 1] || err[k] < 1e-14) << n;
    EXPECT_LT(err.back(), 1e-11) << n;
  }
}

TEST(ExactIrregular, RegularValenceIsTheBicubicBSpline) {
  const IrregularIntegrals& I = irregular_integrals(4);
  const auto v = bspline_poly(0), d = bspline_poly(1);
  Eigen::Matrix4d m00, m11, m10;  // ∫ N_a N_b, ∫ N'_a N'_b, ∫ N'_a N_b
  Eigen::Vector4d m0;
  for (int a = 0; a < 4; ++a) {
    m0(a) = integrate(v[a], {1, 0, 0, 0});
    for (int b = 0; b < 4; ++b) {
      m00(a, b) = integrate(v[a], v[b]);
      m11(a, b) = integrate(d[a], d[b]);
      m10(a, b) = integrate(d[a], v[b]);
    }
  }
  double e_phi = 0, e_pp = 0, e_d = 0;
  for (int i1 = -1; i1 <= 2; ++i1)
    for (int j1 = -1; j1 <= 2; ++j1) {
      const int p = iga::basis::catmull_clark::local_index(4, i1, j1);
      e_phi = std::max(e_phi, std::abs(I.phi(p) - m0(i1 + 1) * m0(j1 + 1)));
      for (int i2 = -1; i2 <= 2; ++i2)
        for (int j2 = -1; j2 <= 2; ++j2) {
          const int q = iga::basis::catmull_clark::local_index(4, i2, j2);
          const int a1 = i1 + 1, b1 = j1 + 1, a2 = i2 + 1, b2 = j2 + 1;
          e_pp = std::max(e_pp, std::abs(I.phi_phi(p, q) - m00(a1, a2) * m00(b1, b2)));
          e_d = std::max(e_d, std::abs(I.d[0][0](p, q) - m11(a1, a2) * m00(b1, b2)));
          e_d = std::max(e_d, std::abs(I.d[1][1](p, q) - m00(a1, a2) * m11(b1, b2)));
          e_d = std::max(e_d, std::abs(I.d[0][1](p, q) - m10(a1, a2) * m10(b2, b1)));
        }
    }
  EXPECT_LT(e_phi, 1e-15);
  EXPECT_LT(e_pp, 1e-15);
  EXPECT_LT(e_d, 1e-15);
}

TEST(ExactIrregular, SecondDerivatives) {
  // n = 3: 4 λ^2 ≈ 0.67 < 1, finite; tiled quadrature approaches it like 0.67^L.
  const auto dd = second_derivative_products(3);
  for (int d = 0; d < 3; ++d)
    for (int e = 0; e < 3; ++e) {
      EXPECT_LT(dd[d][e].rowwise().sum().cwiseAbs().maxCoeff(), 1e-10);
      EXPECT_LT((dd[d][e] - dd[e][d].transpose()).cwiseAbs().maxCoeff(), 1e-10 * dd[d][e].norm());
    }
  double prev = 1e300;
  for (int levels : {10, 20, 30, 40}) {
    const Rule r = tiled_rule(4, levels);
    BasisValues b;
    stam_evaluator(3).evaluate(r.points, 2, b);
    const Eigen::MatrixXd q = b.duu * r.weights.asDiagonal() * b.duu.transpose();
    const double e = (q - dd[0][0]).cwiseAbs().maxCoeff() / dd[0][0].cwiseAbs().maxCoeff();
    std::printf("n = 3 second derivatives  L = %2d  relative max |tiled - exact| = %.3e\n", levels, e);
    EXPECT_LT(e, prev);
    prev = e;
  }
  EXPECT_LT(prev, 1e-5);
  // n = 4: the bicubic closed form ∫ N''_a N''_b = {..} · ∫ N N.
  const auto d4 = second_derivative_products(4);
  const Rule g = tiled_rule(4, 3);  // polynomial everywhere for n = 4: any rule exact for the degree works
  BasisValues b4;
  stam_evaluator(4).evaluate(g.points, 2, b4);
  EXPECT_LT((b4.duv * g.weights.asDiagonal() * b4.dvv.transpose() - d4[1][2]).cwiseAbs().maxCoeff(), 1e-14);
  EXPECT_LT((b4.duu * g.weights.asDiagonal() * b4.duu.transpose() - d4[0][0]).cwiseAbs().maxCoeff(), 1e-14);
  for (int n : {5, 6, 16}) EXPECT_THROW(second_derivative_products(n), iga::UnsupportedError) << n;
}

TEST(ExactIrregular, TripleProductsAgainstTiledQuadrature) {
  for (int n : {3, 4, 5, 7}) {
    const Tensor3 t = triple(n, -1, 0, 1);
    const IrregularIntegrals& I = irregular_integrals(n);
    // Σ_a T[a] = ∫ ∂u φ_b ∂v φ_c (partition of unity in the value factor).
    Eigen::MatrixXd sum = Eigen::MatrixXd::Zero(t[0].rows(), t[0].cols());
    for (const auto& m : t) sum += m;
    EXPECT_LT((sum - I.d[0][1]).cwiseAbs().maxCoeff(), 1e-13) << n;
    double prev = 1e300;
    for (int levels : {10, 20, 30}) {
      const Sampled s = sample(n, 5, levels, 1);  // degree 8 per direction: 5 points
      double e = 0;
      for (std::size_t a = 0; a < t.size(); ++a) {
        const Eigen::VectorXd wa = s.w.cwiseProduct(s.b.value.row(static_cast<Eigen::Index>(a)).transpose());
        const Eigen::MatrixXd q = s.b.du * wa.asDiagonal() * s.b.dv.transpose();
        e = std::max(e, (q - t[a]).cwiseAbs().maxCoeff());
      }
      std::printf("n = %d triple value×du×dv  L = %2d  max |tiled - exact| = %.3e\n", n, levels, e);
      EXPECT_TRUE(e < prev || e < 1e-14) << n;
      prev = e;
    }
    EXPECT_LT(prev, 1e-11) << n;
  }
  EXPECT_THROW(triple(5, 2, 0, 0), iga::InputError);
}
