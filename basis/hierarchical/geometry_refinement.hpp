#pragma once
// Local refinement of a geometry on a hierarchical space, for the backends' registry entries
// (Backend::refine_marked): the same steps for every LevelHierarchy.
#include <functional>
#include <memory>
#include <span>

#include "basis/hierarchical/hierarchical_space.hpp"
#include "basis/registry.hpp"

namespace iga::basis::hierarchical {

/// The permutation (hierarchical dofs × level-0 dofs) from a single-level space's dofs to those of the
/// unrefined hierarchical space on it (dof d ↔ its level-0 function dof_function(d)).
Eigen::SparseMatrix<double> level0_permutation(const HierarchicalSpace& coarse, Index level0_dofs);

/// Refines the marked elements of `coarse` (admissibility class m; every element with m = 0 when all are
/// marked) and prolongates the control points of `geometry`, which lie on `coarse` after `to_coarse` (empty:
/// already on it). Facts "marked", "added", "levels". Without with_prolongation the prolongation is left empty.
Refinement refine_marked_geometry(const Geometry& geometry, const std::shared_ptr<const HierarchicalSpace>& coarse,
                                  const Eigen::SparseMatrix<double>& to_coarse, std::span<const Index> marked,
                                  int admissibility, BackendFacts& facts, bool with_prolongation);

/// A priori grading toward the irregular elements of `coarse` (graded_cells: `levels` steps, rings(k) rings at
/// step k, admissibility class `admissibility`), the control points prolongated as in refine_marked_geometry.
/// Without keep_steps one space is built, the final one, and the prolongation is left empty; with keep_steps
/// every step's space is built and its prolongation kept in Refinement::steps (their product: `prolongation`,
/// from the dofs of `geometry`). Facts "graded_levels" (steps taken: fewer when there is no irregular element),
/// "marked", "added", "levels".
Refinement refine_graded_geometry(const Geometry& geometry, const std::shared_ptr<const HierarchicalSpace>& coarse,
                                  const Eigen::SparseMatrix<double>& to_coarse, int levels,
                                  const std::function<int(int)>& rings, int admissibility, BackendFacts& facts,
                                  bool keep_steps);

/// `steps` uniform refinements (every element split) of a geometry on a hierarchical space, with the composed
/// prolongation.
Refinement refine_all_geometry(const Geometry& geometry, int steps, BackendFacts& facts);

}  // namespace iga::basis::hierarchical
