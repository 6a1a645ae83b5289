#include "basis/hierarchical/graded.hpp"

#include <algorithm>
#include <utility>

#include "basis/hierarchical/refine.hpp"

namespace iga::basis::hierarchical {

namespace {

// The cells of level `level` within `rings` rings of `seeds` (of that level), seeds included, sorted.
std::vector<Key> rings_around(const LevelHierarchy& h, int level, std::vector<Key> seeds, int rings) {
  std::sort(seeds.begin(), seeds.end());
  seeds.erase(std::unique(seeds.begin(), seeds.end()), seeds.end());
  std::unordered_set<Key, KeyHash> seen(seeds.begin(), seeds.end());
  std::vector<Key> all = seeds, frontier = std::move(seeds), next, extension;
  for (int ring = 0; ring < rings && !frontier.empty(); ++ring) {
    next.clear();
    for (Key c : frontier) {
      h.support_extension(level, c, extension);
      for (Key n : extension) {
        if (seen.insert(n).second) next.push_back(n);
      }
    }
    all.insert(all.end(), next.begin(), next.end());
    frontier.swap(next);
  }
  std::sort(all.begin(), all.end());
  return all;
}

}  // namespace

GradedCells graded_cells(const HierarchicalSpace& start, int levels, const std::function<int(int)>& rings,
                         int admissibility) {
  const LevelHierarchy& h = start.hierarchy();
  std::vector<LevelCell> seeds;
  for (Index e = 0; e < start.num_elements(); ++e) {
    if (start.kind(e).family == Family::Irregular) seeds.push_back({start.level(e), start.cell(e)});
  }
  CellRefiner refiner(h, start.refined(), admissibility);
  GradedCells out;
  for (int step = 0; step < levels && !seeds.empty(); ++step) {
    // The leaves to split: per level of the seeds, the cells of their rings, each replaced by the leaf holding it.
    std::vector<LevelCell> marked;
    std::sort(seeds.begin(), seeds.end(), [](const LevelCell& a, const LevelCell& b) {
      return a.level != b.level ? a.level < b.level : a.cell < b.cell;
    });
    for (std::size_t i = 0; i < seeds.size();) {
      const int level = seeds[i].level;
      std::vector<Key> of_level;
      for (; i < seeds.size() && seeds[i].level == level; ++i) of_level.push_back(seeds[i].cell);
      for (Key c : rings_around(h, level, std::move(of_level), rings(step))) {
        int l = level, slot = 0;
        while (l > 0 && !refiner.exists(l, c)) c = h.parent(l--, c, slot);
        if (!refiner.is_refined(l, c)) marked.push_back({l, c});
      }
    }
    const std::size_t before = refiner.added().size();
    for (const LevelCell& m : marked) {
      if (refiner.refine(m.level, m.cell) > 0) ++out.marked;
    }
    out.steps.emplace_back(refiner.added().begin() + static_cast<std::ptrdiff_t>(before), refiner.added().end());
    // The next step's seeds: the irregular children of this step's.
    std::vector<LevelCell> children;
    for (const LevelCell& s : seeds) {
      for (int slot = 0; slot < 4; ++slot) {
        const Key c = h.child(s.level, s.cell, slot);
        if (h.kind(s.level + 1, c).family == Family::Irregular) children.push_back({s.level + 1, c});
      }
    }
    seeds.swap(children);
  }
  out.added = static_cast<Index>(refiner.added().size()) - out.marked;
  out.refined = refiner.take();
  return out;
}

}  // namespace iga::basis::hierarchical
