#include "basis/bspline/bernstein.hpp"

namespace iga::basis::bspline {

namespace {
// All Bernstein polynomials of degree k at t into rows 0..k of `b` (b has at least k+1 rows).
void raise_to(int k, const Eigen::Ref<const Eigen::RowVectorXd>& t, Eigen::MatrixXd& b) {
  const Eigen::Index q = t.size();
  b.resize(k + 1, q);
  b.row(0).setOnes();
  for (int d = 1; d <= k; ++d) {
    // Update in place from the top so that row i-1 still holds degree d-1.
    b.row(d) = t.cwiseProduct(b.row(d - 1));
    for (int i = d - 1; i >= 1; --i) {
      b.row(i) = (1.0 - t.array()).matrix().cwiseProduct(b.row(i)) + t.cwiseProduct(b.row(i - 1));
    }
    b.row(0) = (1.0 - t.array()).matrix().cwiseProduct(b.row(0));
  }
}
}  // namespace

void bernstein(int p, const Eigen::Ref<const Eigen::RowVectorXd>& t, int derivatives, Eigen::MatrixXd& values,
               Eigen::MatrixXd* d1, Eigen::MatrixXd* d2) {
  const Eigen::Index q = t.size();
  raise_to(p, t, values);
  if (derivatives >= 1) {
    d1->resize(p + 1, q);
    if (p == 0) {
      d1->setZero();
    } else {
      thread_local Eigen::MatrixXd lower;
      raise_to(p - 1, t, lower);
      for (int i = 0; i <= p; ++i) {
        d1->row(i).setZero();
        if (i >= 1) d1->row(i) += lower.row(i - 1);
        if (i <= p - 1) d1->row(i) -= lower.row(i);
        d1->row(i) *= p;
      }
    }
  }
  if (derivatives >= 2) {
    d2->resize(p + 1, q);
    if (p <= 1) {
      d2->setZero();
    } else {
      thread_local Eigen::MatrixXd lower2;
      raise_to(p - 2, t, lower2);
      for (int i = 0; i <= p; ++i) {
        d2->row(i).setZero();
        if (i >= 2) d2->row(i) += lower2.row(i - 2);
        if (i >= 1 && i - 1 <= p - 2) d2->row(i) -= 2.0 * lower2.row(i - 1);
        if (i <= p - 2) d2->row(i) += lower2.row(i);
        d2->row(i) *= static_cast<double>(p * (p - 1));
      }
    }
  }
}

}  // namespace iga::basis::bspline
