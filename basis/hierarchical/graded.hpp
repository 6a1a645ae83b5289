#pragma once
// A priori graded refinement toward the irregular cells of a hierarchical mesh (ElementKind Family::Irregular:
// Catmull–Clark elements at an extraordinary vertex), planned on the refined cells alone: no space is built
// between the steps, so grading by L levels costs one build of the final space, not L (--grade-evs).
#include <functional>
#include <vector>

#include "basis/hierarchical/hierarchical_space.hpp"

namespace iga::basis::hierarchical {

struct GradedCells {
  RefinedCells refined;                        ///< after the last step
  std::vector<std::vector<LevelCell>> steps;   ///< the cells each step split, in order
  Index marked = 0;                            ///< cells split because they were near an irregular one
  Index added = 0;                             ///< further cells split to keep the mesh admissible
};

/// `levels` steps from `start`'s mesh; step k (from 0) splits the cells within rings(k) rings of the irregular
/// leaves (ring 1: the cells of the leaf's level sharing a function with one, i.e. its support extension; ring
/// j + 1: sharing one with a cell of ring j; a ring cell outside its level's region stands for the leaf that
/// contains it), with admissibility class `admissibility` (CellRefiner). The irregular leaves of step k + 1 are
/// the irregular children of those of step k. Empty steps when `start` has no irregular leaf.
GradedCells graded_cells(const HierarchicalSpace& start, int levels, const std::function<int(int step)>& rings,
                         int admissibility);

}  // namespace iga::basis::hierarchical
