#pragma once
// Local refinement of hierarchical spaces: the marked elements are split, and so many more that the mesh stays
// admissible of class m (Buffa and Giannelli 2016; Bracco, Giannelli and Vázquez 2018): on every element of
// level l only THB functions of levels l - m + 1 .. l are non-zero, which bounds the functions per element and
// is what the optimal convergence of the adaptive loop rests on.
#include <memory>
#include <span>

#include "basis/hierarchical/hierarchical_space.hpp"

namespace iga::basis::hierarchical {

struct LocalRefinement {
  std::shared_ptr<const HierarchicalSpace> space;
  Index marked = 0;  ///< distinct marked elements refined
  Index added = 0;   ///< further elements refined to keep the mesh admissible
};

/// Refines the marked elements (indices of `space`) and, with admissibility m >= 2, the cells of level
/// l - m + 1 near each refined cell of level l whose functions would otherwise reach it (the truncated
/// neighbourhood: active cells of level l - m + 1 meeting the support extension of the cell at level l - m + 2),
/// recursively. admissibility = 0 refines exactly the marked elements. The result is a new space; `space` is
/// unchanged. InputError for an element index out of range or m = 1; UnsupportedError when a cell would pass the
/// hierarchy's deepest level.
LocalRefinement refine_marked(const HierarchicalSpace& space, std::span<const Index> marked, int admissibility);

/// Every element refined once (uniform refinement of a hierarchical space).
LocalRefinement refine_all(const HierarchicalSpace& space);

/// The largest level difference l - l' + 1 over elements of level l and the dofs of level l' non-zero on them:
/// the mesh is admissible of class m when this is <= m.
int admissibility_class(const HierarchicalSpace& space);

}  // namespace iga::basis::hierarchical
