#include "basis/bspline/knot_insertion.hpp"

#include <algorithm>

#include "core/error.hpp"

namespace iga::basis::bspline {

Eigen::SparseMatrix<double> refinement_matrix(const KnotVector& coarse, const KnotVector& fine) {
  const int p = coarse.degree();
  if (fine.degree() != p) throw InputError("knot insertion: the fine knot vector has another degree");
  if (fine.front() != coarse.front() || fine.back() != coarse.back()) {
    throw InputError("knot insertion: the knot vectors have different domains");
  }
  if (!std::includes(fine.knots().begin(), fine.knots().end(), coarse.knots().begin(), coarse.knots().end())) {
    throw InputError("knot insertion: the fine knot vector does not contain every coarse knot");
  }
  const Index n = fine.num_basis();
  std::vector<Eigen::Triplet<double>> entries;
  entries.reserve(static_cast<std::size_t>(n * (p + 1)));
  for (Index j = 0; j < n; ++j) {
    const Index mu = coarse.span(fine[j]);
    const Eigen::VectorXd row = blossom_row(coarse, mu, &fine.knots()[static_cast<std::size_t>(j + 1)]);
    for (int i = 0; i <= p; ++i) {
      if (row(i) != 0.0) entries.emplace_back(j, mu - p + i, row(i));
    }
  }
  Eigen::SparseMatrix<double> r(n, coarse.num_basis());
  r.setFromTriplets(entries.begin(), entries.end());
  return r;
}

KnotVector insert_midpoints(const KnotVector& kv) {
  std::vector<double> t;
  t.reserve(kv.knots().size() + kv.interval_spans().size());
  const Index m = kv.size();
  for (Index i = 0; i < m; ++i) {
    t.push_back(kv[i]);
    if (i + 1 < m && kv[i] < kv[i + 1] && i >= kv.degree() && i < kv.num_basis()) {
      t.push_back(0.5 * (kv[i] + kv[i + 1]));
    }
  }
  return KnotVector(kv.degree(), std::move(t));
}

}  // namespace iga::basis::bspline
