#include "fem/system_sink.hpp"

#include <algorithm>

namespace iga::fem {

CscSink::CscSink(const AssemblyPlan& plan, Eigen::SparseMatrix<double>& a, Eigen::VectorXd& b)
    : plan_(plan), a_(a), b_(b) {
  a_ = plan.pattern;
  b_ = Eigen::VectorXd::Zero(plan.pattern.rows());
  std::size_t slots = 0;
  for (const std::vector<Index>& colour : plan.colors) slots = std::max(slots, colour.size());
  pending_.resize(slots);
}

void CscSink::add(Index slot, std::span<const Index> dofs, const Eigen::MatrixXd& k, const Eigen::VectorXd& f) {
  // No other element of this colour touches these rows or columns. Rows are visited in ascending dof order, so
  // each column is one forward walk through its sorted row indices.
  const int* outer = a_.outerIndexPtr();
  const int* inner = a_.innerIndexPtr();
  double* values = a_.valuePtr();
  const std::vector<char>& dense = plan_.dense;
  const Index nloc = static_cast<Index>(dofs.size());
  thread_local std::vector<Index> order;
  order.resize(static_cast<std::size_t>(nloc));
  for (Index al = 0; al < nloc; ++al) order[static_cast<std::size_t>(al)] = al;
  if (!std::is_sorted(dofs.begin(), dofs.end())) {
    std::sort(order.begin(), order.end(), [&](Index x, Index y) { return dofs[x] < dofs[y]; });
  }
  const int first_row = static_cast<int>(dofs[order[0]]);
  std::vector<std::pair<std::ptrdiff_t, double>>& later = pending_[static_cast<std::size_t>(slot)];
  later.clear();
  const bool any_dense =
      std::any_of(dofs.begin(), dofs.end(), [&](Index d) { return dense[static_cast<std::size_t>(d)] != 0; });
  for (Index bl = 0; bl < nloc; ++bl) {
    const Index j = dofs[bl];
    const bool dense_column = any_dense && dense[static_cast<std::size_t>(j)];
    const int* pos = std::lower_bound(inner + outer[j], inner + outer[j + 1], first_row);
    for (Index al : order) {
      const int row = static_cast<int>(dofs[al]);
      while (*pos < row) ++pos;
      if (dense_column && dense[static_cast<std::size_t>(row)]) {
        later.emplace_back(pos - inner, k(al, bl));
      } else {
        values[pos - inner] += k(al, bl);
      }
    }
    if (dense_column) {
      later.emplace_back(-1 - static_cast<std::ptrdiff_t>(j), f(bl));
    } else {
      b_(j) += f(bl);
    }
  }
}

void CscSink::end_colour(Index count) {
  double* values = a_.valuePtr();
  for (std::size_t i = 0; i < static_cast<std::size_t>(count); ++i) {
    for (const auto& [at, v] : pending_[i]) {
      if (at >= 0) {
        values[at] += v;
      } else {
        b_(-1 - at) += v;
      }
    }
    pending_[i].clear();
  }
}

}  // namespace iga::fem
