#include "basis/bspline/extraction.hpp"

namespace iga::basis::bspline {

Eigen::MatrixXd extraction_operator(const KnotVector& kv, Index mu) {
  return extraction_operator(kv.knots().data() + (mu - kv.degree()), kv.degree());
}

Eigen::MatrixXd extraction_operator(const double* window, int p) {
  const double a = window[p];
  const double b = window[p + 1];
  Eigen::MatrixXd c(p + 1, p + 1);
  std::vector<double> args(static_cast<std::size_t>(p));
  for (int j = 0; j <= p; ++j) {
    for (int k = 0; k < p; ++k) args[static_cast<std::size_t>(k)] = k < p - j ? a : b;
    c.col(j) = blossom_row(window, p, args.data());
  }
  return c;
}

std::vector<Eigen::MatrixXd> extraction_operators(const KnotVector& kv) {
  std::vector<Eigen::MatrixXd> ops;
  ops.reserve(kv.interval_spans().size());
  for (Index mu : kv.interval_spans()) ops.push_back(extraction_operator(kv, mu));
  return ops;
}

}  // namespace iga::basis::bspline
