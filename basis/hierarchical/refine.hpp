#pragma once
// Local refinement of hierarchical spaces: the marked elements are split, and so many more that the mesh stays
// admissible of class m (Buffa and Giannelli 2016; Bracco, Giannelli and Vázquez 2018): on every element of
// level l only THB functions of levels l - m + 1 .. l are non-zero, which bounds the functions per element and
// is what the optimal convergence of the adaptive loop rests on.
#include <memory>
#include <span>

#include "basis/hierarchical/hierarchical_space.hpp"

namespace iga::basis::hierarchical {

/// The refined cells of a hierarchical mesh under local refinement, without building spaces: refine(level, cell)
/// splits a leaf and, with admissibility m >= 2, first the cells of level l - m + 1 whose functions would otherwise
/// reach it (the truncated neighbourhood: active cells of level l - m + 1 meeting the support extension of the
/// cell at level l - m + 2), recursively (Buffa and Giannelli 2016). refine_marked and the graded refinement
/// (graded.hpp) rest on it.
class CellRefiner {
 public:
  /// InputError for m = 1 or m < 0.
  CellRefiner(const LevelHierarchy& hierarchy, RefinedCells refined, int admissibility);
  /// Splits leaf (level, cell) after its neighbourhood; returns the number of cells split (0: it already was).
  /// UnsupportedError when a cell would pass the hierarchy's deepest level.
  Index refine(int level, Key cell);
  /// Whether the cell is split / lies in the mesh's region of its level.
  bool is_refined(int level, Key cell) const;
  bool exists(int level, Key cell) const;
  const RefinedCells& refined() const { return refined_; }
  RefinedCells take() { return std::move(refined_); }
  /// The cells split so far, in order.
  const std::vector<LevelCell>& added() const { return added_; }

 private:
  const LevelHierarchy& h_;
  int m_;
  RefinedCells refined_;
  std::vector<LevelCell> added_;
  std::vector<Key> fbuf_, cells_;
};

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

/// The space on `refined`, which is `space`'s refined cells and the `added` ones: built from `space` (what
/// changed is recomputed) when few were added, anew otherwise.
std::shared_ptr<const HierarchicalSpace> refined_space(const HierarchicalSpace& space, RefinedCells refined,
                                                       std::span<const LevelCell> added);

/// Every element refined once (uniform refinement of a hierarchical space).
LocalRefinement refine_all(const HierarchicalSpace& space);

/// The largest level difference l - l' + 1 over elements of level l and the dofs of level l' non-zero on them:
/// the mesh is admissible of class m when this is <= m.
int admissibility_class(const HierarchicalSpace& space);

}  // namespace iga::basis::hierarchical
