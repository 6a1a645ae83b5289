#include "basis/hierarchical/refine.hpp"

#include <algorithm>
#include <numeric>

#include "core/error.hpp"

namespace iga::basis::hierarchical {

CellRefiner::CellRefiner(const LevelHierarchy& hierarchy, RefinedCells refined, int admissibility)
    : h_(hierarchy), m_(admissibility), refined_(std::move(refined)) {
  if (admissibility == 1 || admissibility < 0) {
    throw InputError("local refinement: admissibility class must be 0 (none) or >= 2, got " + std::to_string(admissibility));
  }
  fbuf_.resize(static_cast<std::size_t>(h_.max_local_functions()));
}

Index CellRefiner::refine(int level, Key cell) {
  if (is_refined(level, cell)) return 0;
  if (level + 1 > h_.max_level()) {
    throw UnsupportedError("local refinement: level " + std::to_string(level + 1) + " is deeper than the " +
                           std::to_string(h_.max_level()) + " levels the '" + h_.name() + "' hierarchy " + h_.depth_limit());
  }
  Index count = 0;
  const int k = level - m_ + 2;  // level of the support extension
  if (m_ >= 2 && k >= 1) {
    // The cell's ancestor at level k, the supports of the level-k functions on it, their parents (level k - 1).
    Key anc = cell;
    int slot = 0;
    for (int l = level; l > k; --l) anc = h_.parent(l, anc, slot);
    const int n = h_.local_functions(k, anc, fbuf_.data());
    std::vector<Key> parents;
    for (int j = 0; j < n; ++j) {
      h_.support(k, fbuf_[static_cast<std::size_t>(j)], cells_);
      for (Key c : cells_) parents.push_back(h_.parent(k, c, slot));
    }
    std::sort(parents.begin(), parents.end());
    parents.erase(std::unique(parents.begin(), parents.end()), parents.end());
    for (Key p : parents) {
      // Bring the cell of level k - 1 into the mesh (coarser leaves containing it first), then refine it.
      while (!exists(k - 1, p)) {
        int l = k - 1;
        Key c = p;
        while (!exists(l, c)) c = h_.parent(l--, c, slot);
        count += refine(l, c);
      }
      count += refine(k - 1, p);
    }
  }
  if (refined_.size() <= static_cast<std::size_t>(level)) refined_.resize(static_cast<std::size_t>(level) + 1);
  refined_[static_cast<std::size_t>(level)].insert(cell);
  added_.push_back({level, cell});
  return count + 1;
}

bool CellRefiner::is_refined(int level, Key cell) const {
  return level < static_cast<int>(refined_.size()) && refined_[static_cast<std::size_t>(level)].count(cell) > 0;
}

bool CellRefiner::exists(int level, Key cell) const {
  if (level == 0) return cell >= 0 && cell < h_.num_root_cells();
  int slot = 0;
  return is_refined(level - 1, h_.parent(level, cell, slot));
}

LocalRefinement refine_marked(const HierarchicalSpace& space, std::span<const Index> marked, int admissibility) {
  CellRefiner r(space.hierarchy(), space.refined(), admissibility);
  std::vector<Index> elements(marked.begin(), marked.end());
  std::sort(elements.begin(), elements.end());
  elements.erase(std::unique(elements.begin(), elements.end()), elements.end());
  for (Index e : elements) {
    if (e < 0 || e >= space.num_elements()) {
      throw InputError("local refinement: element " + std::to_string(e) + " does not exist (the space has " +
                       std::to_string(space.num_elements()) + ")");
    }
  }
  Index total = 0;
  for (Index e : elements) total += r.refine(space.level(e), space.cell(e));
  LocalRefinement out;
  out.marked = static_cast<Index>(elements.size());
  out.added = total - out.marked;
  const std::vector<LevelCell> added = r.added();
  out.space = refined_space(space, r.take(), added);
  return out;
}

std::shared_ptr<const HierarchicalSpace> refined_space(const HierarchicalSpace& space, RefinedCells refined,
                                                       std::span<const LevelCell> added) {
  // Building from `space` costs what the change costs; with a quarter of the elements refined it is still 1.2×
  // faster than a new build (bench-thb-refine, 16,000 of 65,536 bi-quadratic elements: 0.24 s against 0.29 s), and
  // uniform refinement, which touches every cell, builds anew.
  if (4 * static_cast<Index>(added.size()) < space.num_elements()) {
    return std::make_shared<const HierarchicalSpace>(space, std::move(refined), added);
  }
  return std::make_shared<const HierarchicalSpace>(space.hierarchy_ptr(), std::move(refined));
}

LocalRefinement refine_all(const HierarchicalSpace& space) {
  std::vector<Index> all(static_cast<std::size_t>(space.num_elements()));
  std::iota(all.begin(), all.end(), Index{0});
  return refine_marked(space, all, 0);
}

int admissibility_class(const HierarchicalSpace& space) {
  int worst = 1;
  for (Index e = 0; e < space.num_elements(); ++e) {
    for (Index d : space.dofs(e)) worst = std::max(worst, space.level(e) - space.dof_level(d) + 1);
  }
  return worst;
}

}  // namespace iga::basis::hierarchical
