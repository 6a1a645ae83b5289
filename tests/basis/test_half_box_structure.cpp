// The local subdivision structure of an EF (basis/half_box/subdivision_structure.hpp): the generated A_n
// against the thesis's block-circulant form (3.33) and its DFT blocks (3.34), the quoted rows of A_5, the
// spectrum, the Jordan structure, the ineffective eigenvectors (thesis §3.2.1: three for n = 6), the
// projector and tangent stencils, and thread-safe caching.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <complex>
#include <numbers>
#include <thread>

#include "basis/half_box/regular_patch.hpp"
#include "basis/half_box/subdivision.hpp"
#include "basis/half_box/subdivision_structure.hpp"
#include "core/error.hpp"

namespace {

using namespace iga::basis::half_box;
using iga::Index;
using cd = std::complex<double>;

// Block (r, c) of the thesis's A_n with b = c = d = 1/4: A_(c − r mod n), (3.33).
Eigen::Matrix4d thesis_block(int n, int k) {
  const std::vector<double> a = s1_weights(n);
  Eigen::Matrix4d m = Eigen::Matrix4d::Zero();
  m(0, 0) = a[static_cast<std::size_t>(k)];
  if (k == 0) m.block(1, 0, 3, 4) << 0.25, 0.25, 0, 0, 0.5, 0.125, 0.125, 0, 0.5, 0.125, 0, 0.125;
  if (k == 1) m.block(1, 0, 3, 4) << 0.25, 0, 0, 0, 0, 0, 0, 0, 0.125, 0.125, 0, 0;
  if (k == n - 1) m.block(1, 0, 3, 4) << 0.25, 0, 0, 0, 0.125, 0.125, 0, 0, 0, 0, 0, 0;
  return m;
}

TEST(HalfBoxStructure, RingMatrixIsTheBlockCirculantOfTheThesis) {
  for (int n = 3; n <= 12; ++n) {
    const Eigen::MatrixXd& a = subdivision_structure(n).ring_matrix;
    ASSERT_EQ(a.rows(), 4 * n);
    for (int r = 0; r < n; ++r)
      for (int c = 0; c < n; ++c)
        EXPECT_LT((a.block(4 * r, 4 * c, 4, 4) - thesis_block(n, ((c - r) % n + n) % n)).norm(), 1e-16) << n << " " << r << " " << c;
  }
  // Rows of the printed A_5 (b = c = d = 1/4): row 3 and the corrected last row.
  const Eigen::MatrixXd& a5 = subdivision_structure(5).ring_matrix;
  Eigen::RowVectorXd r3 = Eigen::RowVectorXd::Zero(20), r19 = Eigen::RowVectorXd::Zero(20);
  r3(0) = 0.5;
  r3(1) = r3(3) = r3(4) = r3(5) = 0.125;
  r19(16) = 0.5;
  r19(0) = r19(1) = r19(17) = r19(19) = 0.125;
  EXPECT_EQ(a5.row(3), r3);
  EXPECT_EQ(a5.row(19), r19);
}

TEST(HalfBoxStructure, DftBlocksAreLowerTriangularWithTheSpectrum) {
  for (int n = 3; n <= 12; ++n) {
    const Eigen::MatrixXd& a = subdivision_structure(n).ring_matrix;
    const cd w = std::polar(1.0, -2 * std::numbers::pi / n);
    for (int l = 0; l < n; ++l) {
      Eigen::Matrix4cd d = Eigen::Matrix4cd::Zero();
      for (int k = 0; k < n; ++k) d += std::pow(w, k * l) * a.block(0, 4 * k, 4, 4).cast<cd>();
      // Rounding of the n-term DFT sums: 1e-14.
      for (int i = 0; i < 4; ++i)
        for (int j = i + 1; j < 4; ++j) EXPECT_LT(std::abs(d(i, j)), 1e-14);
      // Diagonal (3.34): Σ ω^{kl} a^k, d_n = 1/4, 1/8, 1/8; for n = 6 (hexagon S1) λ_3 = 1/2 as well.
      const double lam = l == 0 ? 1.0 : (l == 1 || l == n - 1 || (n == 6 && l == 3)) ? 0.5 : 0.25;
      EXPECT_LT(std::abs(d(0, 0) - lam), 1e-14) << n << " " << l;
      EXPECT_LT(std::abs(d(1, 1) - 0.25), 1e-14);
      EXPECT_LT(std::abs(d(2, 2) - 0.125), 1e-14);
      EXPECT_LT(std::abs(d(3, 3) - 0.125), 1e-14);
      EXPECT_LT(std::abs(d(1, 0) - (0.25 + 0.5 * std::cos(2 * std::numbers::pi * l / n))), 1e-14);  // b + 2c cos
    }
  }
}

// Eigenvalues of a (general solver; defective clusters are spread by ~sqrt(eps)) rounded to `tol`.
std::vector<double> rounded_spectrum(const Eigen::MatrixXd& a, double tol) {
  Eigen::EigenSolver<Eigen::MatrixXd> es(a, false);
  std::vector<double> r;
  for (Index i = 0; i < a.rows(); ++i) {
    const cd z = es.eigenvalues()(i);
    double best = -1;
    for (double c : {1.0, 0.5, 0.25, 0.125, 0.0})
      if (std::abs(z - c) < tol) best = c;
    r.push_back(best);
  }
  std::sort(r.begin(), r.end());
  return r;
}

TEST(HalfBoxStructure, SpectrumAndJordanStructure) {
  for (int n = 3; n <= 12; ++n) {
    const SubdivisionStructure& s = subdivision_structure(n);
    const std::vector<double> ring = rounded_spectrum(s.ring_matrix, 1e-5);
    const int halves = n == 6 ? 3 : 2;
    EXPECT_EQ(std::count(ring.begin(), ring.end(), 1.0), 1) << n;
    EXPECT_EQ(std::count(ring.begin(), ring.end(), 0.5), halves) << n;
    EXPECT_EQ(std::count(ring.begin(), ring.end(), 0.25), n == 6 ? 8 : 2 * n - 3) << n;
    EXPECT_EQ(std::count(ring.begin(), ring.end(), 0.125), 2 * n) << n;
    // The patch matrix is an invariant principal block: its spectrum lies in {1, 1/2, 1/4, 1/8}.
    const std::vector<double> patch = rounded_spectrum(s.patch_matrix, 1e-5);
    EXPECT_EQ(std::count(patch.begin(), patch.end(), -1.0), 0) << n;
    EXPECT_EQ(std::count(patch.begin(), patch.end(), 1.0), 1);
    // Jordan structure of 1/4: geometric multiplicity below the algebraic one for n >= 4 except the regular
    // n = 6 (hexagon S1, not (3.37)).
    const Index np = s.patch_matrix.rows();
    Eigen::FullPivLU<Eigen::MatrixXd> lu(s.patch_matrix - 0.25 * Eigen::MatrixXd::Identity(np, np));
    lu.setThreshold(1e-10);
    const long alg = std::count(patch.begin(), patch.end(), 0.25);
    const long geo = np - lu.rank();
    std::printf("n = %2d: patch matrix %ld x %ld, eigenvalue 1/4 algebraic %ld geometric %ld\n", n, long(np), long(np), alg, geo);
    if (n >= 4 && n != 6) {
      EXPECT_LT(geo, alg) << n;
    }
  }
}

TEST(HalfBoxStructure, LimitStencilProjectorAndPowers) {
  for (int n = 3; n <= 12; ++n) {
    const SubdivisionStructure& s = subdivision_structure(n);
    const Index np = s.patch_matrix.rows();
    EXPECT_EQ(np, n == 6 ? 13 : n + 7);
    EXPECT_EQ(s.extended_matrix.rows(), np + 9);
    EXPECT_LT((s.limit_stencil * s.patch_matrix - s.limit_stencil).norm(), 1e-14);
    EXPECT_NEAR(s.limit_stencil.sum(), 1.0, 1e-14);
    const Eigen::MatrixXd& p = s.half_projector;
    EXPECT_LT((p * p - p).norm(), 1e-12);
    EXPECT_LT((s.patch_matrix * p - 0.5 * p).norm(), 1e-12);
    EXPECT_LT((p * s.patch_matrix - 0.5 * p).norm(), 1e-12);
    // Cached powers: A^m by repeated multiplication; A^(2m) = (A^m)^2.
    for (int m : {1, 7, 20, 31}) EXPECT_LT((s.power(2 * m) - s.power(m) * s.power(m)).norm(), 1e-13);
    // Rows of A and Ā sum to 1; the first patch_size rows of Ā are A.
    EXPECT_LT((s.extended_matrix.rowwise().sum() - Eigen::VectorXd::Ones(np + 9)).norm(), 1e-14);
    EXPECT_EQ(s.extended_matrix.topRows(np), s.patch_matrix);
  }
}

// The eigenfunctions of 1/2: linear for n = 6 (regular grid), not linear for an EF (measured second
// derivatives 0.07..0.44 on layer-1 tiles; the thesis only conjectures linearity), which is why second
// derivatives keep the 1/2 part and parametric derivatives have no limit at the EF. The tangent stencils are
// combinations of the left eigenvectors of 1/2 (t P = t) and annihilate constants.
TEST(HalfBoxStructure, HalfEigenfunctions) {
  for (int n = 3; n <= 12; ++n) {
    const SubdivisionStructure& s = subdivision_structure(n);
    double second = 0, grad = 0;
    for (int k = 0; k < 3; ++k) {
      const Eigen::MatrixXd xa = s.picking_matrix(k) * s.extended_matrix * s.half_projector;
      const TileMap& t = s.tiles[static_cast<std::size_t>(k)];
      for (const Eigen::Vector2d& y : {Eigen::Vector2d(0.2, 0.3), Eigen::Vector2d(0.6, 0.1), Eigen::Vector2d(0.1, 0.8)}) {
        BernsteinValues b;
        bernstein_cubic(y(0), y(1), 2, b);
        const auto mt = bezier_matrix().transpose();
        for (const auto* h : {&b.duu, &b.duv, &b.dvv})
          second = std::max(second, ((mt * *h).transpose() * xa).cwiseAbs().maxCoeff());
        const Eigen::RowVectorXd ds = (mt * b.du).transpose() * xa, dt = (mt * b.dv).transpose() * xa;
        const Eigen::RowVectorXd du = t.jacobian(0, 0) * ds + t.jacobian(1, 0) * dt, dv = t.jacobian(0, 1) * ds + t.jacobian(1, 1) * dt;
        grad = std::max({grad, (du - s.tangent_stencils.row(0)).cwiseAbs().maxCoeff(), (dv - s.tangent_stencils.row(1)).cwiseAbs().maxCoeff()});
      }
    }
    std::printf("n = %2d: eigenfunctions of 1/2 on layer-1 tiles: max |second derivative| %.3f, gradient spread %.3f\n", n, second, grad);
    if (n == 6) {
      EXPECT_LT(second, 1e-12);
      EXPECT_LT(grad, 1e-12);
    } else {
      EXPECT_GT(second, 1e-2) << n;
    }
    EXPECT_LT((s.tangent_stencils * s.half_projector - s.tangent_stencils).norm(), 1e-12);
    EXPECT_LT(s.tangent_stencils.rowwise().sum().norm(), 1e-13);
  }
}

// Ineffective eigenvectors: the largest A-invariant subspace whose every tile has zero BB coefficients
// (M X^k Ā A^m w = 0 for all k, m), restricted to nonzero eigenvalues. Thesis: three for n = 6.
TEST(HalfBoxStructure, IneffectiveEigenvectors) {
  for (int n = 3; n <= 12; ++n) {
    const SubdivisionStructure& s = subdivision_structure(n);
    const Index np = s.patch_matrix.rows();
    Eigen::MatrixXd rows(3 * np * kBezierSize, np);
    for (int k = 0; k < 3; ++k)
      for (Index m = 0; m < np; ++m)
        rows.block((k * np + m) * kBezierSize, 0, kBezierSize, np) = bezier_matrix() * s.picking_matrix(k) * s.extended_matrix * s.power(static_cast<int>(m));
    Eigen::FullPivLU<Eigen::MatrixXd> lu(rows);
    lu.setThreshold(1e-10);
    const Eigen::MatrixXd z = lu.kernel();
    int ineffective = 0;
    std::string values;
    if (lu.rank() < np) {
      // A restricted to the kernel: coordinates c with A z = z c.
      const Eigen::MatrixXd c = z.colPivHouseholderQr().solve(s.patch_matrix * z);
      EXPECT_LT((z * c - s.patch_matrix * z).norm(), 1e-10);
      Eigen::EigenSolver<Eigen::MatrixXd> es(c);
      for (Index i = 0; i < c.rows(); ++i)
        if (std::abs(es.eigenvalues()(i)) > 1e-8) {
          ++ineffective;
          values += " " + std::to_string(es.eigenvalues()(i).real());
        }
    }
    std::printf("n = %2d: kernel dimension %ld, ineffective eigenvectors %d:%s\n", n, long(np - lu.rank()), ineffective, values.c_str());
    if (n == 6) {
      EXPECT_EQ(ineffective, 3);
    }
    if (n == 7) {
      EXPECT_EQ(ineffective, 1);
    }
    if (n == 8) {
      EXPECT_EQ(ineffective, 2);
    }
  }
}

TEST(HalfBoxStructure, ThreadSafeCacheAndErrors) {
  std::vector<const SubdivisionStructure*> got(8);
  std::vector<std::thread> th;
  for (int i = 0; i < 8; ++i) th.emplace_back([&got, i] { got[static_cast<std::size_t>(i)] = &subdivision_structure(13 + i % 2); });
  for (auto& t : th) t.join();
  for (int i = 0; i < 8; ++i) EXPECT_EQ(got[static_cast<std::size_t>(i)], &subdivision_structure(13 + i % 2));
  EXPECT_THROW(subdivision_structure(2), iga::UnsupportedError);
  EXPECT_THROW(subdivision_structure(17), iga::UnsupportedError);
}

}  // namespace
