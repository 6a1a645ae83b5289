// The geometric matrix series of quadrature/exact/series.hpp against explicit summation of their terms:
// random contractive matrices, a Jordan block with repeated eigenvalues, the deflated s = 1 case of
// derivative integrals, and the third-order (triple-product) series.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <random>

#include "basis/catmull_clark/stam.hpp"
#include "core/error.hpp"
#include "quadrature/exact/series.hpp"

using namespace iga::quadrature::exact;

namespace {

Eigen::MatrixXd random_matrix(int m, int k, unsigned seed) {
  std::mt19937 gen(seed);
  std::uniform_real_distribution<double> d(-1.0, 1.0);
  Eigen::MatrixXd a(m, k);
  for (int i = 0; i < m; ++i)
    for (int j = 0; j < k; ++j) a(i, j) = d(gen);
  return a;
}

// Spectral radius rho, well conditioned eigenvectors not needed: A = rho * R / spectral_radius(R).
Eigen::MatrixXd contractive(int m, double rho, unsigned seed) {
  Eigen::MatrixXd a = random_matrix(m, m, seed);
  const double r = a.eigenvalues().cwiseAbs().maxCoeff();
  return a * (rho / r);
}

Eigen::MatrixXd explicit_stein(const Eigen::MatrixXd& a, const Eigen::MatrixXd& c, double s, int terms) {
  Eigen::MatrixXd x = Eigen::MatrixXd::Zero(c.rows(), c.cols());
  Eigen::MatrixXd p = Eigen::MatrixXd::Identity(a.rows(), a.cols());
  const Eigen::MatrixXd sa = std::sqrt(s) * a;  // s^j (A^j)^T C A^j = ((√s A)^j)^T C (√s A)^j
  for (int j = 0; j < terms; ++j) {
    x += p.transpose() * c * p;
    p = (p * sa).eval();
  }
  return x;
}

double rel(const Eigen::MatrixXd& a, const Eigen::MatrixXd& b) { return (a - b).norm() / b.norm(); }

}  // namespace

TEST(ExactSeries, SteinRandomContractive) {
  for (unsigned seed = 1; seed <= 5; ++seed) {
    const Eigen::MatrixXd a = contractive(7, 0.9, seed);
    const Eigen::MatrixXd c = random_matrix(7, 7, seed + 100);
    for (double s : {0.25, 1.0}) {
      const Eigen::MatrixXd x = stein(a, c, s);
      EXPECT_LT(rel(x, explicit_stein(a, c, s, 3000)), 1e-13) << "seed " << seed << " s " << s;
      // The Stein equation itself.
      EXPECT_LT(rel(c + s * a.transpose() * x * a, x), 1e-14);
    }
  }
}

// A = V J V^-1 with J = a 3×3 Jordan block of 0.8, the eigenvalue 0.5 twice and 0.3: the series is not a sum of
// rank-one eigen-terms; doubling is unaffected.
TEST(ExactSeries, SteinJordanBlockAndRepeatedEigenvalues) {
  Eigen::MatrixXd j = Eigen::MatrixXd::Zero(6, 6);
  j(0, 0) = j(1, 1) = j(2, 2) = 0.8;
  j(0, 1) = j(1, 2) = 1.0;
  j(3, 3) = j(4, 4) = 0.5;
  j(5, 5) = 0.3;
  const Eigen::MatrixXd v = Eigen::MatrixXd::Identity(6, 6) + 0.3 * random_matrix(6, 6, 7);
  const Eigen::MatrixXd a = v * j * v.inverse();
  const Eigen::MatrixXd c = random_matrix(6, 6, 8);
  const Eigen::MatrixXd x = stein(a, c, 1.2);  // 1.2 * 0.8^2 < 1
  EXPECT_LT(rel(x, explicit_stein(a, c, 1.2, 6000)), 1e-12);
  EXPECT_LT(rel(c + 1.2 * a.transpose() * x * a, x), 1e-14);
  // Pure Jordan block (v = I).
  const Eigen::MatrixXd xj = stein(j, c, 1.0);
  EXPECT_LT(rel(xj, explicit_stein(j, c, 1.0, 6000)), 1e-12);
}

TEST(ExactSeries, LinearSeries) {
  const Eigen::MatrixXd a = contractive(9, 0.95, 11);
  const Eigen::VectorXd c = random_matrix(9, 1, 12);
  const Eigen::VectorXd y = linear_series(a, c, 1.0);
  EXPECT_LT((y - c - a.transpose() * y).norm() / y.norm(), 1e-14);
  Eigen::VectorXd e = Eigen::VectorXd::Zero(9), t = c;
  for (int k = 0; k < 5000; ++k) {
    e += t;
    t = (a.transpose() * t).eval();
  }
  EXPECT_LT((y - e).norm() / e.norm(), 1e-12);
}

// Derivative integrals: A = the Catmull–Clark subdivision matrix (eigenvalue 1, rows sum to 1), C with
// C 1 = 0 and 1^T C = 0, s = 1: with A - 1 w^T the doubling converges to the explicit sum of (A^j)^T C A^j (which converges because C annihilates the eigenvalue 1).
TEST(ExactSeries, DeflationOfTheConstantMode) {
  for (int n : {3, 5, 7}) {
    const auto& st = iga::basis::catmull_clark::stam_evaluator(n);
    const Eigen::MatrixXd& a = st.subdivision_matrix();
    const Eigen::VectorXd& w = st.limit_stencil();
    EXPECT_LT((w.transpose() * a - w.transpose()).norm(), 1e-14);
    const int m = static_cast<int>(a.rows());
    Eigen::MatrixXd d = random_matrix(m, m, 20 + static_cast<unsigned>(n));
    d -= d.rowwise().mean() * Eigen::RowVectorXd::Ones(m);  // rows sum to 0
    const Eigen::MatrixXd c = d.transpose() * d + d;          // C 1 = 0 and 1^T C = 0? (d 1 = 0; 1^T d not)
    const Eigen::MatrixXd cc = c - Eigen::VectorXd::Ones(m) * (Eigen::VectorXd::Ones(m).transpose() * c) / m;
    ASSERT_LT((cc * Eigen::VectorXd::Ones(m)).norm(), 1e-12);
    ASSERT_LT((Eigen::VectorXd::Ones(m).transpose() * cc).norm(), 1e-12);
    // Without annihilation the series with s = 1 diverges (linear growth from the eigenvalue 1).
    EXPECT_THROW(stein(a, Eigen::MatrixXd::Identity(m, m), 1.0), iga::NumericalError);
    const Eigen::MatrixXd x = stein(deflate_constant(a, w), cc, 1.0);
    EXPECT_LT(rel(x, explicit_stein(a, cc, 1.0, 400)), 1e-12) << "n = " << n;
  }
}

TEST(ExactSeries, TripleSeries) {
  const int m = 5;
  const Eigen::MatrixXd p = contractive(m, 0.9, 31), q = contractive(m, 0.7, 32), r = contractive(m, 0.8, 33);
  Tensor3 c(m);
  for (int i = 0; i < m; ++i) c[static_cast<std::size_t>(i)] = random_matrix(m, m, 40 + static_cast<unsigned>(i));
  const double s = 1.3;
  const Tensor3 t = triple_series(c, p, q, r, s);
  Tensor3 e(m, Eigen::MatrixXd::Zero(m, m));
  Eigen::MatrixXd pj = Eigen::MatrixXd::Identity(m, m), qj = pj, rj = pj;
  double sj = 1;
  for (int j = 0; j < 400; ++j) {
    const Tensor3 term = contract(c, pj, qj, rj);
    for (int i = 0; i < m; ++i) e[static_cast<std::size_t>(i)] += sj * term[static_cast<std::size_t>(i)];
    pj = (pj * p).eval();
    qj = (qj * q).eval();
    rj = (rj * r).eval();
    sj *= s;
  }
  double err = 0, nrm = 0;
  for (int i = 0; i < m; ++i) {
    err += (t[static_cast<std::size_t>(i)] - e[static_cast<std::size_t>(i)]).squaredNorm();
    nrm += e[static_cast<std::size_t>(i)].squaredNorm();
  }
  EXPECT_LT(std::sqrt(err / nrm), 1e-12);
}
