#include "bem/gmres.hpp"

#include <Eigen/SVD>
#include <algorithm>
#include <Eigen/LU>
#include <cmath>
#include <limits>

namespace iga::bem {

namespace {

// M⁻¹ of the block diagonal of A, applied in place.
class BlockJacobi {
 public:
  BlockJacobi(const Eigen::MatrixXd& a, const std::vector<Eigen::Index>& starts) {
    for (std::size_t k = 0; k < starts.size(); ++k) {
      const Eigen::Index s = starts[k], e = k + 1 < starts.size() ? starts[k + 1] : a.rows();
      Eigen::PartialPivLU<Eigen::MatrixXd> lu(a.block(s, s, e - s, e - s));
      const bool usable = lu.rcond() > 1e-14;
      blocks_.push_back({s, e - s, std::move(lu), usable});
    }
  }
  void apply(Eigen::VectorXd& x) const {
    for (const Block& b : blocks_) {
      if (b.usable) x.segment(b.start, b.size) = b.lu.solve(x.segment(b.start, b.size));
    }
  }

 private:
  struct Block {
    Eigen::Index start, size;
    Eigen::PartialPivLU<Eigen::MatrixXd> lu;
    bool usable;
  };
  std::vector<Block> blocks_;
};

}  // namespace

GmresResult gmres(const Eigen::MatrixXd& a, const Eigen::VectorXd& b, double tolerance, int restart,
                  int max_iterations, const std::vector<Eigen::Index>& block_starts) {
  const BlockJacobi precond(a, block_starts);
  const Eigen::Index n = b.size();
  GmresResult res;
  res.x = Eigen::VectorXd::Zero(n);
  const double bnorm = b.norm();
  if (bnorm == 0.0) {
    res.converged = true;
    return res;
  }
  const int m = std::max(1, std::min<int>(restart, static_cast<int>(n)));
  Eigen::MatrixXd v(n, m + 1), hess(m + 1, m), h_raw(m + 1, m);  // h_raw: unrotated, for the estimate
  Eigen::VectorXd cs(m), sn(m), s(m + 1), w(n);
  while (res.iterations < max_iterations) {
    const Eigen::VectorXd r = b - a * res.x;
    const double beta = r.norm();
    if (beta <= tolerance * bnorm) {
      res.converged = true;
      break;
    }
    v.col(0) = r / beta;
    s.setZero();
    s(0) = beta;
    hess.setZero();
    h_raw.setZero();
    int k = 0;
    while (k < m && res.iterations < max_iterations) {
      w = v.col(k);
      precond.apply(w);
      w = a * w;
      ++res.iterations;
      for (int i = 0; i <= k; ++i) {  // modified Gram–Schmidt
        hess(i, k) = w.dot(v.col(i));
        w -= hess(i, k) * v.col(i);
      }
      hess(k + 1, k) = w.norm();
      h_raw.col(k) = hess.col(k);
      if (hess(k + 1, k) > 0.0) v.col(k + 1) = w / hess(k + 1, k);
      for (int i = 0; i < k; ++i) {  // the previous rotations, then a new one
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
      ++k;
      if (std::abs(s(k)) <= tolerance * bnorm || h_raw(k, k - 1) == 0.0) break;
    }
    const Eigen::VectorXd y = hess.topLeftCorner(k, k).triangularView<Eigen::Upper>().solve(s.head(k));
    Eigen::VectorXd dx = v.leftCols(k) * y;
    precond.apply(dx);
    res.x += dx;
    const Eigen::JacobiSVD<Eigen::MatrixXd> svd(h_raw.topLeftCorner(k + 1, k));
    const Eigen::VectorXd sv = svd.singularValues();
    res.condition_estimate =
        sv(sv.size() - 1) > 0.0 ? sv(0) / sv(sv.size() - 1) : std::numeric_limits<double>::infinity();
  }
  res.residual = (b - a * res.x).norm() / bnorm;
  res.converged = res.converged || res.residual <= tolerance;
  return res;
}

}  // namespace iga::bem
