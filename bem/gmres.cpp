#include "bem/gmres.hpp"

#include <Eigen/SVD>
#include <algorithm>
#include <cmath>

namespace iga::bem {

GmresResult gmres(const Eigen::MatrixXd& a, const Eigen::VectorXd& b, double tolerance, int restart,
                  int max_iterations) {
  const Eigen::Index n = b.size();
  GmresResult res;
  res.x = Eigen::VectorXd::Zero(n);
  const double bnorm = b.norm();
  if (bnorm == 0.0) {
    res.converged = true;
    return res;
  }
  const int m = std::max(1, std::min<int>(restart, static_cast<int>(n)));
  Eigen::MatrixXd v(n, m + 1), hess = Eigen::MatrixXd::Zero(m + 1, m);
  Eigen::VectorXd cs(m), sn(m), s(m + 1), w(n);
  while (res.iterations < max_iterations) {
    const Eigen::VectorXd r = b - a * res.x;
    double beta = r.norm();
    if (beta <= tolerance * bnorm) {
      res.converged = true;
      break;
    }
    v.col(0) = r / beta;
    s.setZero();
    s(0) = beta;
    hess.setZero();
    Eigen::MatrixXd h_raw = Eigen::MatrixXd::Zero(m + 1, m);  // unrotated, for the condition estimate
    int k = 0;
    for (; k < m && res.iterations < max_iterations; ++k) {
      w.noalias() = a * v.col(k);
      ++res.iterations;
      for (int i = 0; i <= k; ++i) {
        hess(i, k) = w.dot(v.col(i));
        w -= hess(i, k) * v.col(i);
      }
      hess(k + 1, k) = w.norm();
      h_raw.col(k) = hess.col(k);
      if (hess(k + 1, k) > 0.0) v.col(k + 1) = w / hess(k + 1, k);
      for (int i = 0; i < k; ++i) {
        const double t = cs(i) * hess(i, k) + sn(i) * hess(i + 1, k);
        hess(i + 1, k) = -sn(i) * hess(i, k) + cs(i) * hess(i + 1, k);
        hess(i, k) = t;
      }
      const double rr = std::hypot(hess(k, k), hess(k + 1, k));
      cs(k) = hess(k, k) / rr;
      sn(k) = hess(k + 1, k) / rr;
      hess(k, k) = rr;
      hess(k + 1, k) = 0.0;
      s(k + 1) = -sn(k) * s(k);
      s(k) = cs(k) * s(k);
      if (std::abs(s(k + 1)) <= tolerance * bnorm || h_raw(k + 1, k) == 0.0) {
        ++k;
        break;
      }
    }
    const Eigen::VectorXd y =
        hess.topLeftCorner(k, k).triangularView<Eigen::Upper>().solve(s.head(k));
    res.x += v.leftCols(k) * y;
    const Eigen::JacobiSVD<Eigen::MatrixXd> svd(h_raw.topLeftCorner(k + 1, k));
    const Eigen::VectorXd sv = svd.singularValues();
    res.condition_estimate = sv(sv.size() - 1) > 0.0 ? sv(0) / sv(sv.size() - 1) : INFINITY;
  }
  res.residual = (b - a * res.x).norm() / bnorm;
  res.converged = res.converged || res.residual <= tolerance;
  return res;
}

}  // namespace iga::bem
