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
  /// Per dof: 1 when more than kDenseDofElements elements share it (an enrichment function spread over a fixed
  /// disc, whatever the refinement). Dense dofs are left out of the colouring, which would otherwise need one
  /// colour per element of the disc; the assembler reduces the entries between two dense dofs (and their load)
  /// after each colour, in element order, so assembly stays race-free and reproducible.
  std::vector<char> dense;
};

/// Elements sharing a dof beyond which it is dense (AssemblyPlan::dense). A spline function touches at most
/// (p+1)² elements (16 bicubic, 36 quintic; hierarchical spaces a few more).
inline constexpr Index kDenseDofElements = 256;

/// with_pattern = false: the colouring and dense dofs only (pattern 0 × 0), for a sink that keeps its own
/// pattern (a distributed matrix: then no process holds the whole pattern).
/// components = d > 1: the plan of a field with d components over the space (DESIGN.md item 2), dofs interleaved
/// (global dof d·i + c is component c of function i): the pattern couples every component of i with every
/// component of j when i and j share an element, dense flags are per field dof, the colouring is the space's.
AssemblyPlan make_assembly_plan(const basis::Space& space, bool with_pattern = true, int components = 1);

}  // namespace iga::fem
