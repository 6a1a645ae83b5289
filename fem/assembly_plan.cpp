#include "fem/assembly_plan.hpp"

#include <algorithm>
#include <limits>

#include "core/error.hpp"

namespace iga::fem {

namespace {

// The columns of each dof: the union of the dofs of the elements around it. Two passes (count, then fill in
// place) with a per-thread stamp array, so nothing is allocated per column.
void fill_pattern(const basis::Space& space, const std::vector<Index>& start, const std::vector<Index>& elems,
                  Eigen::SparseMatrix<double>& a) {
  const Index n = space.num_dofs();
  a.resize(n, n);
  std::vector<Index> count(static_cast<std::size_t>(n), 0);
  auto for_each_neighbour = [&](Index j, std::vector<Index>& stamp, auto&& visit) {
    for (Index k = start[j]; k < start[j + 1]; ++k) {
      for (Index d : space.dofs(elems[static_cast<std::size_t>(k)])) {
        if (stamp[static_cast<std::size_t>(d)] != j) {
          stamp[static_cast<std::size_t>(d)] = j;
          visit(d);
        }
      }
    }
  };
#pragma omp parallel
  {
    std::vector<Index> stamp(static_cast<std::size_t>(n), -1);
#pragma omp for schedule(static)
    for (Index j = 0; j < n; ++j) for_each_neighbour(j, stamp, [&](Index) { ++count[static_cast<std::size_t>(j)]; });
  }
  Index nnz = 0;
  for (Index j = 0; j < n; ++j) nnz += count[static_cast<std::size_t>(j)];
  if (nnz > static_cast<Index>(std::numeric_limits<int>::max())) {
    throw UnsupportedError("sparsity pattern with " + std::to_string(nnz) + " entries exceeds 32-bit indices");
  }
  a.resizeNonZeros(nnz);
  int* outer = a.outerIndexPtr();
  int* inner = a.innerIndexPtr();
  outer[0] = 0;
  for (Index j = 0; j < n; ++j) outer[j + 1] = outer[j] + static_cast<int>(count[static_cast<std::size_t>(j)]);
#pragma omp parallel
  {
    std::vector<Index> stamp(static_cast<std::size_t>(n), -1);
#pragma omp for schedule(static)
    for (Index j = 0; j < n; ++j) {
      int* pos = inner + outer[j];
      for_each_neighbour(j, stamp, [&](Index d) { *pos++ = static_cast<int>(d); });
      std::sort(inner + outer[j], pos);
    }
  }
  std::fill(a.valuePtr(), a.valuePtr() + nnz, 0.0);
}

void colour(const basis::Space& space, const std::vector<Index>& start, const std::vector<Index>& elems,
            AssemblyPlan& plan) {
  const Index n = space.num_dofs();
  const Index ne = space.num_elements();
  // Greedy colouring: an element takes the smallest colour no element sharing a (non-dense) dof with it has.
  plan.dense.assign(static_cast<std::size_t>(n), 0);
  for (Index d = 0; d < n; ++d) plan.dense[static_cast<std::size_t>(d)] = start[d + 1] - start[d] > kDenseDofElements;
  std::vector<int> color(static_cast<std::size_t>(ne), -1);
  std::vector<char> used;
  for (Index e = 0; e < ne; ++e) {
    for (Index d : space.dofs(e)) {
      if (plan.dense[static_cast<std::size_t>(d)]) continue;
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
}

// The scalar pattern s (n × n) as the pattern of d interleaved components: entry (d·i + a, d·j + b) for every
// entry (i, j) of s and a, b < d. Rows stay sorted within each column.
void expand_pattern(const Eigen::SparseMatrix<double>& s, int d, Eigen::SparseMatrix<double>& a) {
  const Index n = s.rows();
  const Index nnz = static_cast<Index>(s.nonZeros()) * d * d;
  if (nnz > static_cast<Index>(std::numeric_limits<int>::max())) {
    throw UnsupportedError("sparsity pattern with " + std::to_string(nnz) + " entries exceeds 32-bit indices");
  }
  a.resize(d * n, d * n);
  a.resizeNonZeros(nnz);
  int* outer = a.outerIndexPtr();
  int* inner = a.innerIndexPtr();
  outer[0] = 0;
  for (Index j = 0; j < n; ++j) {
    const int begin = s.outerIndexPtr()[j], end = s.outerIndexPtr()[j + 1];
    for (int b = 0; b < d; ++b) {
      const Index column = d * j + b;
      int* pos = inner + outer[column];
      for (int k = begin; k < end; ++k) {
        for (int c = 0; c < d; ++c) *pos++ = static_cast<int>(d * s.innerIndexPtr()[k] + c);
      }
      outer[column + 1] = static_cast<int>(pos - inner);
    }
  }
  std::fill(a.valuePtr(), a.valuePtr() + nnz, 0.0);
}

}  // namespace

AssemblyPlan make_assembly_plan(const basis::Space& space, bool with_pattern, int components) {
  if (components < 1) throw InputError("assembly plan: components must be >= 1, got " + std::to_string(components));
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
  AssemblyPlan plan;
  if (with_pattern) fill_pattern(space, start, elems, plan.pattern);
  colour(space, start, elems, plan);
  if (components > 1) {
    if (with_pattern) {
      Eigen::SparseMatrix<double> scalar;
      scalar.swap(plan.pattern);
      expand_pattern(scalar, components, plan.pattern);
    }
    std::vector<char> dense(plan.dense.size() * static_cast<std::size_t>(components));
    for (std::size_t i = 0; i < dense.size(); ++i) dense[i] = plan.dense[i / static_cast<std::size_t>(components)];
    plan.dense.swap(dense);
  }
  return plan;
}

}  // namespace iga::fem
