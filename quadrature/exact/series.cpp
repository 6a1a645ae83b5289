#include "quadrature/exact/series.hpp"

#include <cmath>
#include <limits>

#include "core/error.hpp"

namespace iga::quadrature::exact {

namespace {

constexpr int kMaxDoublings = 64;
constexpr double kTol = 1e-17;  // relative size of the last increment
constexpr double kDecay = 1e-3;  // the scaled power must have decayed this much (no transient left)
// After 2^kStall terms an increment still this large (relative) means divergence (or a rate > 0.999).
constexpr int kStall = 12;
constexpr double kStallSize = 1e-3;

double tensor_norm(const Tensor3& t) {
  double s = 0;
  for (const auto& m : t) s += m.squaredNorm();
  return std::sqrt(s);
}

[[noreturn]] void not_converged(const char* what) {
  throw NumericalError(std::string("exact integration: the geometric series (") + what +
                       ") does not converge (s |lambda_i lambda_j| >= 1 on a pair the integrand does not annihilate)");
}

}  // namespace

Eigen::VectorXd linear_series(const Eigen::MatrixXd& a, const Eigen::VectorXd& c, double s) {
  // The scale is folded into the matrix (s^j A^j = (s A)^j), so that no scalar power over- or underflows.
  Eigen::VectorXd y = c;
  Eigen::MatrixXd p = s * a.transpose();
  for (int k = 0; k < kMaxDoublings; ++k) {
    const Eigen::VectorXd inc = p * y;
    y += inc;
    if (inc.norm() <= kTol * y.norm() && p.norm() <= kDecay) return y;
    if (k >= kStall && inc.norm() > kStallSize * y.norm()) break;
    p = (p * p).eval();
    if (!p.allFinite()) break;
  }
  not_converged("linear");
}

Eigen::MatrixXd stein(const Eigen::MatrixXd& a, const Eigen::MatrixXd& c, const Eigen::MatrixXd& b, double s) {
  Eigen::MatrixXd x = c;
  Eigen::MatrixXd p = s * a, q = b;
  for (int k = 0; k < kMaxDoublings; ++k) {
    const Eigen::MatrixXd inc = p.transpose() * x * q;
    x += inc;
    if (inc.norm() <= kTol * x.norm() && p.norm() * q.norm() <= kDecay) return x;
    if (k >= kStall && inc.norm() > kStallSize * x.norm()) break;
    p = (p * p).eval();
    q = (q * q).eval();
    if (!p.allFinite() || !q.allFinite()) break;
  }
  not_converged("Stein");
}

Eigen::MatrixXd stein(const Eigen::MatrixXd& a, const Eigen::MatrixXd& c, double s) { return stein(a, c, a, s); }

Eigen::MatrixXd deflate_constant(const Eigen::MatrixXd& a, const Eigen::VectorXd& w) {
  return a - Eigen::VectorXd::Ones(a.rows()) * w.transpose();
}

Eigen::MatrixXd deflate_modes(const Eigen::MatrixXd& a, const Eigen::MatrixXd& right, const Eigen::MatrixXd& left,
                              const Eigen::VectorXd& lambda) {
  return a - right * lambda.asDiagonal() * left;
}

Tensor3 contract(const Tensor3& t, const Eigen::MatrixXd& p, const Eigen::MatrixXd& q, const Eigen::MatrixXd& r) {
  const Eigen::Index n = p.cols();
  std::vector<Eigen::MatrixXd> m(t.size());
  for (std::size_t i = 0; i < t.size(); ++i) m[i].noalias() = q.transpose() * t[i] * r;
  Tensor3 out(static_cast<std::size_t>(n), Eigen::MatrixXd::Zero(q.cols(), r.cols()));
  for (Eigen::Index a = 0; a < n; ++a) {
    Eigen::MatrixXd& o = out[static_cast<std::size_t>(a)];
    for (std::size_t i = 0; i < t.size(); ++i) {
      const double w = p(static_cast<Eigen::Index>(i), a);
      if (w != 0.0) o += w * m[i];
    }
  }
  return out;
}

Tensor3 triple_series(const Tensor3& c, const Eigen::MatrixXd& p0, const Eigen::MatrixXd& q0,
                      const Eigen::MatrixXd& r0, double s) {
  Tensor3 x = c;
  Eigen::MatrixXd p = s * p0, q = q0, r = r0;
  for (int k = 0; k < kMaxDoublings; ++k) {
    const Tensor3 inc = contract(x, p, q, r);
    for (std::size_t i = 0; i < x.size(); ++i) x[i] += inc[i];
    const double ni = tensor_norm(inc), nx = tensor_norm(x);
    if (ni <= kTol * nx && p.norm() * q.norm() * r.norm() <= kDecay) return x;
    if (k >= kStall && ni > kStallSize * nx) break;
    p = (p * p).eval();
    q = (q * q).eval();
    r = (r * r).eval();
    if (!p.allFinite() || !q.allFinite() || !r.allFinite()) break;
  }
  not_converged("triple");
}

}  // namespace iga::quadrature::exact
