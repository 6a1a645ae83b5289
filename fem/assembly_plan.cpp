#include "fem/assembly_plan.hpp"

#include <algorithm>
#include <limits>

#include "core/error.hpp"

namespace iga::fem {

AssemblyPlan make_assembly_plan(const basis::Space& space) {
  const Index n = space.num_dofs();
  const Index ne = space.num_elements();
  // dof -> elements (CSR).
  std::vector<Index> start(static_cast<std::size_t>(n + 1), 0);
  for (Index e = 0; e < ne; ++e) {
    for (Index d : space.dofs(e)) ++start[static_cast<std::size_t>(d + 1)];
  }
  for (Index i = 0; i < n; ++i) start[i + 1] += start[i];
  std::vector<Index> elems(static_cast<std::size_t>(start[n]));
  {
    std::vector<Index> pos(start.begin(), start.end() - 1);
    for (Index e = 0; e < ne; ++e) {
      for (Index d : space.dofs(e)) elems[static_cast<std::size_t>(pos[d]++)] = e;
    }
  }
  // Columns: the union of the dofs of the elements around each dof.
  std::vector<std::vector<int>> cols(static_cast<std::size_t>(n));
#pragma omp parallel
  {
    std::vector<char> mark(static_cast<std::size_t>(n), 0);
#pragma omp for schedule(static)
    for (Index j = 0; j < n; ++j) {
      auto& col = cols[static_cast<std::size_t>(j)];
      for (Index k = start[j]; k < start[j + 1]; ++k) {
        for (Index d : space.dofs(elems[static_cast<std::size_t>(k)])) {
          if (!mark[d]) {
            mark[d] = 1;
            col.push_back(static_cast<int>(d));
          }
        }
      }
      for (int d : col) mark[d] = 0;
      std::sort(col.begin(), col.end());
    }
  }
  std::size_t nnz = 0;
  for (const auto& c : cols) nnz += c.size();
  if (nnz > static_cast<std::size_t>(std::numeric_limits<int>::max())) {
    throw UnsupportedError("sparsity pattern with " + std::to_string(nnz) + " entries exceeds 32-bit indices");
  }
  AssemblyPlan plan;
  Eigen::SparseMatrix<double>& a = plan.pattern;
  a.resize(n, n);
  a.resizeNonZeros(static_cast<Index>(nnz));
  int* outer = a.outerIndexPtr();
  int* inner = a.innerIndexPtr();
  outer[0] = 0;
  for (Index j = 0; j < n; ++j) {
    const auto& c = cols[static_cast<std::size_t>(j)];
    std::copy(c.begin(), c.end(), inner + outer[j]);
    outer[j + 1] = outer[j] + static_cast<int>(c.size());
  }
  std::fill(a.valuePtr(), a.valuePtr() + nnz, 0.0);
  cols.clear();

  // Greedy colouring: an element takes the smallest colour no element sharing a dof with it has.
  std::vector<int> color(static_cast<std::size_t>(ne), -1);
  std::vector<char> used;
  for (Index e = 0; e < ne; ++e) {
    for (Index d : space.dofs(e)) {
      for (Index k = start[d]; k < start[d + 1]; ++k) {
        const int c = color[static_cast<std::size_t>(elems[static_cast<std::size_t>(k)])];
        if (c >= 0) {
          if (static_cast<std::size_t>(c) >= used.size()) used.resize(static_cast<std::size_t>(c) + 1, 0);
          used[static_cast<std::size_t>(c)] = 1;
        }
      }
    }
    int c = 0;
    while (static_cast<std::size_t>(c) < used.size() && used[static_cast<std::size_t>(c)]) ++c;
    color[static_cast<std::size_t>(e)] = c;
    std::fill(used.begin(), used.end(), 0);
    if (static_cast<std::size_t>(c) >= plan.colors.size()) plan.colors.resize(static_cast<std::size_t>(c) + 1);
    plan.colors[static_cast<std::size_t>(c)].push_back(e);
  }
  return plan;
}

}  // namespace iga::fem
