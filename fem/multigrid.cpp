#include "fem/multigrid.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "core/error.hpp"

namespace iga::fem {

int MultigridLevel::owner(Index reduced_index) const {
  return static_cast<int>(std::upper_bound(offsets.begin(), offsets.end(), reduced_index) - offsets.begin()) - 1;
}

namespace {

// p ⊗ I_d: field dof d·j + c to d·i + c.
Eigen::SparseMatrix<double> field_prolongation(const Eigen::SparseMatrix<double>& p, int d) {
  if (d == 1) return p;
  std::vector<Eigen::Triplet<double>> t;
  t.reserve(static_cast<std::size_t>(d * p.nonZeros()));
  for (Index j = 0; j < p.outerSize(); ++j) {
    for (Eigen::SparseMatrix<double>::InnerIterator it(p, j); it; ++it) {
      for (Index c = 0; c < d; ++c) t.emplace_back(d * it.row() + c, d * j + c, it.value());
    }
  }
  Eigen::SparseMatrix<double> out(d * p.rows(), d * p.cols());
  out.setFromTriplets(t.begin(), t.end());
  return out;
}

// The coarse level below `fine` through p (fine dofs × coarse dofs of one component).
MultigridLevel coarser(const Eigen::SparseMatrix<double>& p, int d, const MultigridLevel& fine) {
  const Eigen::SparseMatrix<double> pf = field_prolongation(p, d);
  const Index n = pf.cols();
  const int ranks = static_cast<int>(fine.offsets.size()) - 1;
  // The constraints' residual of every coarse function: C pf, C = (selection of the constrained rows) + coupling.
  Eigen::SparseMatrix<double> select(static_cast<Index>(fine.constrained.size()), pf.rows());
  {
    std::vector<Eigen::Triplet<double>> t;
    for (std::size_t k = 0; k < fine.constrained.size(); ++k) t.emplace_back(static_cast<Index>(k), fine.constrained[k], 1.0);
    select.setFromTriplets(t.begin(), t.end());
  }
  Eigen::SparseMatrix<double> residual = select * pf;
  if (fine.coupling.nonZeros() > 0) residual += Eigen::SparseMatrix<double>(fine.coupling * pf);
  std::vector<int> owner(static_cast<std::size_t>(n), -1);  // −1: not free
  for (Index j = 0; j < n; ++j) {
    double largest = 0.0;
    Index at = -1;
    for (Eigen::SparseMatrix<double>::InnerIterator it(pf, j); it; ++it) {
      const Index row = fine.reduced[static_cast<std::size_t>(it.row())];
      const double a = std::abs(it.value());
      if (row >= 0 && a > 0.0 && (a > largest || (a == largest && row < at))) {
        largest = a;
        at = row;
      }
    }
    if (at < 0) continue;
    bool satisfied = true;
    for (Eigen::SparseMatrix<double>::InnerIterator it(residual, j); it && satisfied; ++it) {
      satisfied = std::abs(it.value()) <= 1e-10 * largest;
    }
    if (satisfied) owner[static_cast<std::size_t>(j)] = fine.owner(at);
  }
  MultigridLevel out;
  out.offsets.assign(static_cast<std::size_t>(ranks) + 1, 0);
  for (int o : owner) {
    if (o >= 0) ++out.offsets[static_cast<std::size_t>(o) + 1];
  }
  for (int r = 0; r < ranks; ++r) out.offsets[static_cast<std::size_t>(r) + 1] += out.offsets[static_cast<std::size_t>(r)];
  std::vector<Index> next(out.offsets.begin(), out.offsets.end() - 1);
  out.reduced.assign(owner.size(), -1);
  for (std::size_t k = 0; k < owner.size(); ++k) {
    if (owner[k] >= 0) {
      out.reduced[k] = next[static_cast<std::size_t>(owner[k])]++;
    } else {
      out.constrained.push_back(static_cast<Index>(k));
    }
  }
  return out;
}

}  // namespace

std::vector<MultigridLevel> multigrid_levels(const std::vector<Eigen::SparseMatrix<double>>& hierarchy, int components,
                                             MultigridLevel finest) {
  const Index d = components;
  std::vector<MultigridLevel> levels(hierarchy.size() + 1);
  levels.back() = std::move(finest);
  for (std::size_t k = hierarchy.size(); k-- > 0;) {
    const Eigen::SparseMatrix<double>& p = hierarchy[k];
    const MultigridLevel& fine = levels[k + 1];
    if (d * p.rows() != static_cast<Index>(fine.reduced.size())) {
      throw InputError("multigrid: the prolongation onto level " + std::to_string(k + 1) + " has " +
                       std::to_string(p.rows()) + " rows for a level of " + std::to_string(fine.reduced.size() / static_cast<std::size_t>(d)) +
                       " dofs");
    }
    levels[k] = coarser(p, components, fine);
  }
  return levels;
}

Eigen::SparseMatrix<double, Eigen::RowMajor> reduced_prolongation(const Eigen::SparseMatrix<double>& p, int components,
                                                                  const MultigridLevel& coarse, const MultigridLevel& fine) {
  const Eigen::SparseMatrix<double> pf = field_prolongation(p, components);
  std::vector<Eigen::Triplet<double>> t;
  t.reserve(static_cast<std::size_t>(pf.nonZeros()));
  for (Index j = 0; j < pf.outerSize(); ++j) {
    const Index col = coarse.reduced[static_cast<std::size_t>(j)];
    if (col < 0) continue;
    for (Eigen::SparseMatrix<double>::InnerIterator it(pf, j); it; ++it) {
      const Index row = fine.reduced[static_cast<std::size_t>(it.row())];
      if (row >= 0 && it.value() != 0.0) t.emplace_back(row, col, it.value());
    }
  }
  Eigen::SparseMatrix<double, Eigen::RowMajor> out(fine.size(), coarse.size());
  out.setFromTriplets(t.begin(), t.end());
  return out;
}

}  // namespace iga::fem
