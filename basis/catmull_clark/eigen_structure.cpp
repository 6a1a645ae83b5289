#include "basis/catmull_clark/eigen_structure.hpp"

#include <Eigen/Geometry>
#include <Eigen/LU>
#include <algorithm>
#include <cmath>
#include <numbers>
#include <numeric>
#include <string>
#include <vector>

#include "basis/catmull_clark/subdivision_matrix.hpp"
#include "core/error.hpp"

namespace iga::basis::catmull_clark {
namespace {

constexpr int kNumExtras = 7;                 // points of the 4×4 net outside the one-ring
constexpr double kCoincidence = 1e-10;        // |lambda − mu| below this: the same eigenvalue
constexpr double kReconstructionTol = 1e-12;  // relative Frobenius error of V diag(lambda) V^{-1}

struct Mode {
  double lambda;
  Eigen::VectorXd ring;  // 2n+1 one-ring components
};

// Frequency-0 modes: EV = z0, every e_k = z1, every f_k = z2, with (z0, z1, z2) an eigenvector of the 3×3
// block m0 (rows: new EV, new e_0, new f_0 of the constant one-ring modes).
void frequency_zero_modes(int n, const Eigen::MatrixXd& s, std::vector<Mode>& modes) {
  const int nr = 2 * n + 1;
  Eigen::Matrix3d m0;
  for (int c = 0; c < 3; ++c) {
    Eigen::VectorXd basis = Eigen::VectorXd::Zero(nr);
    if (c == 0) basis(0) = 1.0;
    for (int k = 0; k < n && c > 0; ++k) basis(2 * k + c) = 1.0;
    const Eigen::VectorXd image = s * basis;
    m0.col(c) = image.head<3>();
  }
  const double nd = n;
  const double root = std::sqrt(5.0 * nd * nd - 30.0 * nd + 49.0);
  const double mus[3] = {1.0, (3.0 * nd - 7.0 + root) / (8.0 * nd), (3.0 * nd - 7.0 - root) / (8.0 * nd)};
  for (double mu : mus) {
    Eigen::Vector3d z;
    if (mu == 1.0) {
      z = Eigen::Vector3d::Ones();
    } else {
      // The null vector of m0 − mu I from two of its rows (the 3×3 block has simple eigenvalues).
      const Eigen::Vector3d r1 = m0.row(1).transpose() - mu * Eigen::Vector3d::UnitY();
      const Eigen::Vector3d r2 = m0.row(2).transpose() - mu * Eigen::Vector3d::UnitZ();
      z = r1.cross(r2);
      z /= z.cwiseAbs().maxCoeff();
    }
    Eigen::VectorXd ring(nr);
    ring(0) = z(0);
    for (int k = 0; k < n; ++k) {
      ring(2 * k + 1) = z(1);
      ring(2 * k + 2) = z(2);
    }
    modes.push_back({mu, ring});
  }
}

// Frequencies 0 < w < n/2: complex mode e_k = zeta^(wk), f_k = zeta^(wk) (1 + zeta^w) / (4 lambda − 1), zeta =
// exp(2πi/n); its real and imaginary parts are the cosine and sine modes. Frequency n/2: eigenvalue 1/4 with
// e_k = (−1)^k, f = 0 and f_k = (−1)^k, e = 0.
void fourier_modes(int n, std::vector<Mode>& modes) {
  const int nr = 2 * n + 1;
  const auto angle = [n](long m) { return 2.0 * std::numbers::pi * static_cast<double>(m % n) / n; };
  for (int w = 1; 2 * w < n; ++w) {
    const double c = std::cos(angle(w));
    const double plus = (5.0 + c + std::sqrt((1.0 + c) * (9.0 + c))) / 16.0;
    for (double lambda : {plus, 1.0 / (16.0 * plus)}) {  // the product of the two eigenvalues is 1/16
      const double r = 1.0 / (4.0 * lambda - 1.0);
      for (int part = 0; part < 2; ++part) {
        const auto g = [&](int k) {
          const double t = angle(static_cast<long>(w) * k);
          return part == 0 ? std::cos(t) : std::sin(t);
        };
        Eigen::VectorXd ring = Eigen::VectorXd::Zero(nr);
        for (int k = 0; k < n; ++k) {
          ring(2 * k + 1) = g(k);
          ring(2 * k + 2) = r * (g(k) + g(k + 1));
        }
        modes.push_back({lambda, ring});
      }
    }
  }
  if (n % 2 == 0) {
    for (int offset = 1; offset <= 2; ++offset) {
      Eigen::VectorXd ring = Eigen::VectorXd::Zero(nr);
      for (int k = 0; k < n; ++k) ring(2 * k + offset) = (k % 2 == 0) ? 1.0 : -1.0;
      modes.push_back({0.25, ring});
    }
  }
}

// Eigenvectors of the 7×7 block S12 for its known dyadic eigenvalues, as kernels of S12 − mu I.
void extra_modes(const Eigen::MatrixXd& s12, Eigen::VectorXd& mu, Eigen::MatrixXd& w) {
  mu.resize(kNumExtras);
  w.resize(kNumExtras, kNumExtras);
  int col = 0;
  for (const auto& [value, multiplicity] : {std::pair{0.125, 2}, {0.0625, 2}, {0.03125, 2}, {0.015625, 1}}) {
    Eigen::FullPivLU<Eigen::MatrixXd> lu(s12 - value * Eigen::MatrixXd::Identity(kNumExtras, kNumExtras));
    const Eigen::MatrixXd kernel = lu.kernel();
    if (kernel.cols() != multiplicity || col + multiplicity > kNumExtras) {
      throw NumericalError("catmull_clark: unexpected eigenspace of the subdivision matrix's outer block");
    }
    for (int c = 0; c < multiplicity; ++c, ++col) {
      w.col(col) = kernel.col(c) / kernel.col(c).cwiseAbs().maxCoeff();
      mu(col) = value;
    }
  }
  if ((s12 * w - w * mu.asDiagonal()).norm() > 1e-14) {
    throw NumericalError("catmull_clark: inaccurate eigenvectors of the subdivision matrix's outer block");
  }
}

}  // namespace

double subdominant_eigenvalue(int valence) {
  check_valence(valence);
  const double c = std::cos(2.0 * std::numbers::pi / valence);
  return (5.0 + c + std::cos(std::numbers::pi / valence) * std::sqrt(2.0 * (9.0 + c))) / 16.0;
}

EigenStructure eigen_structure(int valence, const Eigen::MatrixXd& a) {
  const int n = valence;
  const int np = num_local_points(n), nr = 2 * n + 1;
  if (a.rows() != np || a.cols() != np) {
    throw InputError("catmull_clark: eigen_structure needs the " + std::to_string(np) + "×" + std::to_string(np) +
                     " subdivision matrix of valence " + std::to_string(n));
  }
  const Eigen::MatrixXd s = a.topLeftCorner(nr, nr);
  const Eigen::MatrixXd s11 = a.bottomLeftCorner(kNumExtras, nr);
  const Eigen::MatrixXd s12 = a.bottomRightCorner(kNumExtras, kNumExtras);

  std::vector<Mode> modes;
  frequency_zero_modes(n, s, modes);
  fourier_modes(n, modes);
  if (static_cast<int>(modes.size()) != nr) throw NumericalError("catmull_clark: one-ring modes incomplete");

  Eigen::VectorXd mu;
  Eigen::MatrixXd w;
  extra_modes(s12, mu, w);
  const Eigen::MatrixXd w_inv = w.inverse();

  // V = [[U0, 0], [U1, W]] in construction order (one-ring modes, then the outer block's).
  Eigen::VectorXd lambda(np);
  Eigen::MatrixXd u0(nr, nr), u1(kNumExtras, nr);
  for (int m = 0; m < nr; ++m) {
    Mode& mode = modes[static_cast<std::size_t>(m)];
    const Eigen::VectorXd rhs = s11 * mode.ring;
    Eigen::VectorXd y = w_inv * rhs;  // (lambda − mu_j) y_j = (W^{-1} S11 u)_j
    for (int j = 0; j < kNumExtras; ++j) {
      if (std::abs(mode.lambda - mu(j)) < kCoincidence) {
        if (std::abs(y(j)) > kCoincidence * (1.0 + rhs.cwiseAbs().maxCoeff())) {
          throw NumericalError("catmull_clark: the subdivision matrix of valence " + std::to_string(n) +
                               " is defective (eigenvalue " + std::to_string(mu(j)) + ")");
        }
        mode.lambda = mu(j);  // the same eigenvalue, exactly dyadic
        y(j) = 0.0;
      } else {
        y(j) /= mode.lambda - mu(j);
      }
    }
    lambda(m) = mode.lambda;
    u0.col(m) = mode.ring;
    // lambda = 1: rows of A sum to one, so the outer part of the constant mode is exactly 1.
    u1.col(m) = mode.lambda == 1.0 ? Eigen::VectorXd::Ones(kNumExtras).eval() : (w * y).eval();
  }
  lambda.tail(kNumExtras) = mu;

  Eigen::FullPivLU<Eigen::MatrixXd> lu0(u0);
  if (!lu0.isInvertible()) throw NumericalError("catmull_clark: one-ring eigenvectors are dependent");
  const Eigen::MatrixXd u0_inv = lu0.inverse();
  Eigen::MatrixXd v = Eigen::MatrixXd::Zero(np, np), v_inv = Eigen::MatrixXd::Zero(np, np);
  v.topLeftCorner(nr, nr) = u0;
  v.bottomLeftCorner(kNumExtras, nr) = u1;
  v.bottomRightCorner(kNumExtras, kNumExtras) = w;
  v_inv.topLeftCorner(nr, nr) = u0_inv;
  v_inv.bottomLeftCorner(kNumExtras, nr) = -w_inv * u1 * u0_inv;
  v_inv.bottomRightCorner(kNumExtras, kNumExtras) = w_inv;

  // Sort descending; the stable sort keeps cosine before sine and column 0 = the constant mode.
  std::vector<int> order(static_cast<std::size_t>(np));
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](int x, int y) { return lambda(x) > lambda(y); });
  EigenStructure out;
  out.values.resize(np);
  out.vectors.resize(np, np);
  out.inverse.resize(np, np);
  for (int c = 0; c < np; ++c) {
    const int src = order[static_cast<std::size_t>(c)];
    out.values(c) = lambda(src);
    out.vectors.col(c) = v.col(src);
    out.inverse.row(c) = v_inv.row(src);
  }

  const double error = (out.vectors * out.values.asDiagonal() * out.inverse - a).norm() / a.norm();
  if (!(error <= kReconstructionTol)) {
    throw NumericalError("catmull_clark: eigen-decomposition of valence " + std::to_string(n) +
                         " reconstructs A only to " + std::to_string(error));
  }
  return out;
}

}  // namespace iga::basis::catmull_clark
