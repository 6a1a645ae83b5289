#pragma once
// What the assembler precomputes once per space: the sparsity pattern and an element colouring.
#include <Eigen/Sparse>
#include <vector>

#include "basis/space.hpp"

namespace iga::fem {

struct AssemblyPlan {
  /// Compressed column-major pattern (both triangles) with explicit zeros: entry (i, j) exists when
  /// functions i and j share an element.
  Eigen::SparseMatrix<double> pattern;
  /// Elements grouped by colour: no two elements of one colour share a dof, so one colour can be
  /// scattered in parallel without races, and every global entry is summed in the same order for any
  /// thread count (reproducible assembly). Greedy colouring in element order.
  std::vector<std::vector<Index>> colors;
};

AssemblyPlan make_assembly_plan(const basis::Space& space);

}  // namespace iga::fem
