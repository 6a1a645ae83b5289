// Building a HierarchicalSpace: the depth-first pass over the forest (whole, or only where a refinement changed
// something), the dof numbering, and the prolongation from the space an incremental build started from.
#include <algorithm>
#include <atomic>
#include <cmath>

#include "basis/hierarchical/hierarchical_space.hpp"
#include "core/error.hpp"

namespace iga::basis::hierarchical {

namespace {

// A function of one level: whether its support lies in Ω^l ("inside") and in Ω^{l+1} ("inside_next"), and its
// provisional dof (or -1) once known.
struct FunctionState {
  signed char inside = -1, inside_next = -1;
  Index dof = -2;  // -2: not decided, -1: not active
};

// Rows of m whose entries are all below `tiny` (functions that vanish on the cell after truncation) are
// removed, with their ids.
void drop_zero_rows(std::vector<Index>& ids, Eigen::MatrixXd& m) {
  constexpr double tiny = 1e-14;
  Index kept = 0;
  for (Index r = 0; r < m.rows(); ++r) {
    if (m.row(r).cwiseAbs().maxCoeff() > tiny) {
      if (kept != r) {
        m.row(kept) = m.row(r);
        ids[static_cast<std::size_t>(kept)] = ids[static_cast<std::size_t>(r)];
      }
      ++kept;
    }
  }
  ids.resize(static_cast<std::size_t>(kept));
  m.conservativeResize(kept, Eigen::NoChange);
}

bool contains(const std::vector<std::unordered_set<Key, KeyHash>>& sets, int level, Key cell) {
  return level < static_cast<int>(sets.size()) && sets[static_cast<std::size_t>(level)].count(cell) > 0;
}

std::uint64_t next_serial() {
  static std::atomic<std::uint64_t> serial{0};
  return ++serial;
}

}  // namespace

void HierarchicalSpace::build() { traverse(nullptr, nullptr, nullptr); }

HierarchicalSpace::HierarchicalSpace(const HierarchicalSpace& previous, RefinedCells refined,
                                     std::span<const LevelCell> added)
    : hierarchy_(previous.hierarchy_), refined_(std::move(refined)) {
  trim_and_check_depth();
  std::size_t count = 0, previous_count = 0;
  for (const auto& level : refined_) count += level.size();
  for (const auto& level : previous.refined_) previous_count += level.size();
  if (count != previous_count + added.size()) {
    throw InputError("hierarchical space: " + std::to_string(count) + " refined cells are not the previous space's " +
                     std::to_string(previous_count) + " and the " + std::to_string(added.size()) + " added");
  }
  for (const LevelCell& c : added) {
    if (!is_refined(c.level, c.cell) || previous.is_refined(c.level, c.cell) || !exists(c.level, c.cell)) {
      throw InputError("hierarchical space: added cell " + to_string(c.cell) + " of level " + std::to_string(c.level) +
                       " is not a newly refined cell of the refined region");
    }
  }
  build_from(previous, added);
}

void HierarchicalSpace::build_from(const HierarchicalSpace& previous, std::span<const LevelCell> added) {
  const LevelHierarchy& h = *hierarchy_;
  // A function's selection (supp ⊆ Ω^l, ⊄ Ω^{l+1}) and its truncation change only when its support meets a
  // newly refined cell (level l) or one of its children (level l + 1): the cells of the newly refined cells'
  // support extensions (which hold the children's, LevelHierarchy::support_extension) and every leaf below them
  // are recomputed, and the paths down to them.
  CellSets dirty(refined_.size() + 2), on_path(refined_.size() + 2);
  std::vector<Key> cells;
  for (const LevelCell& added_cell : added) {
    const int level = added_cell.level;
    h.support_extension(level, added_cell.cell, cells);
    for (Key c : cells) {
      if (!dirty[static_cast<std::size_t>(level)].insert(c).second) continue;
      int slot = 0;
      for (int l = level; l > 0; --l) {
        c = h.parent(l, c, slot);
        if (!on_path[static_cast<std::size_t>(l - 1)].insert(c).second) break;
      }
    }
  }
  // Every refined leaf gives way to four: room for the copies without regrowing.
  const std::size_t more = 3 * added.size();
  elements_.reserve(previous.elements_.size() + more);
  copied_from_.reserve(elements_.capacity());
  dofs_.reserve(previous.dofs_.size() + more * static_cast<std::size_t>(previous.max_local_));
  block_map_.assign(previous.blocks_.size(), -1);
  traverse(&previous, &dirty, &on_path);
  block_map_ = std::vector<int>();
  previous_serial_ = previous.serial_;
}

Index HierarchicalSpace::dof_of(int level, Key function, std::vector<Key>& cells) const {
  hierarchy_->support(level, function, cells);
  for (Key c : cells) {
    const Index e = element_of(level, c);
    if (e < 0) continue;
    // An active function is a row of every leaf of its level in its support.
    for (Index d : dofs(e)) {
      if (dof_level_[static_cast<std::size_t>(d)] == level && dof_function_[static_cast<std::size_t>(d)] == function) return d;
    }
    return -1;
  }
  return -1;
}

void HierarchicalSpace::copy_subtree(const HierarchicalSpace& previous, int level, Key cell) {
  const LevelHierarchy& h = *hierarchy_;
  // Depth-first order: the subtree's leaves are consecutive, from its first (slot 0 down) to its last (slot 3).
  Key first = cell, last = cell;
  int first_level = level, last_level = level;
  while (previous.is_refined(first_level, first)) first = h.child(first_level++, first, 0);
  while (previous.is_refined(last_level, last)) last = h.child(last_level++, last, 3);
  const Index e0 = previous.element_of(first_level, first), e1 = previous.element_of(last_level, last);
  if (e0 < 0 || e1 < e0) {
    throw NumericalError("hierarchical space: cell " + to_string(cell) + " of level " + std::to_string(level) +
                         " has no leaves in the previous space");
  }
  for (Index e = e0; e <= e1; ++e) {
    Element el = previous.elements_[static_cast<std::size_t>(e)];
    const auto list = previous.dofs(e);
    const Index begin = static_cast<Index>(dofs_.size());
    dofs_.insert(dofs_.end(), list.begin(), list.end());  // previous ids are this build's provisional ids
    if (el.coeff != nullptr) {
      int& mapped = block_map_[static_cast<std::size_t>(el.block)];
      if (mapped < 0) {
        mapped = static_cast<int>(blocks_.size());
        blocks_.push_back(previous.blocks_[static_cast<std::size_t>(el.block)]);
      }
      el.block = mapped;
    }
    el.dof_begin = begin;
    el.dof_end = static_cast<Index>(dofs_.size());
    elements_.push_back(el);
    copied_from_.push_back(e);
  }
}

void HierarchicalSpace::traverse(const HierarchicalSpace* previous, const CellSets* dirty, const CellSets* on_path) {
  const LevelHierarchy& h = *hierarchy_;
  serial_ = next_serial();
  const int nf = h.max_local_functions();
  // Provisional dof ids: the previous space's dofs keep theirs, new ones follow; finish() renumbers.
  std::vector<int> level_of = previous ? previous->dof_level_ : std::vector<int>();
  std::vector<Key> function_of = previous ? previous->dof_function_ : std::vector<Key>();
  std::vector<std::unordered_map<Key, FunctionState, KeyHash>> state(refined_.size() + 2);
  std::vector<Key> scratch;
  auto function_state = [&](int level, Key f) -> FunctionState& {
    FunctionState& s = state[static_cast<std::size_t>(level)][f];
    if (s.inside < 0) {
      h.support(level, f, scratch);
      bool inside = true, next = true;
      for (Key c : scratch) {
        if (inside && !exists(level, c)) inside = false;
        if (next && !is_refined(level, c)) next = false;
      }
      s.inside = inside ? 1 : 0;
      s.inside_next = next ? 1 : 0;
    }
    return s;
  };
  auto activate = [&](int level, Key f) {
    if (previous) {
      const Index d = previous->dof_of(level, f, scratch);
      if (d >= 0) return d;
    }
    level_of.push_back(level);
    function_of.push_back(f);
    return static_cast<Index>(level_of.size()) - 1;
  };
  std::vector<Key> fbuf(static_cast<std::size_t>(nf)), child_buf(static_cast<std::size_t>(nf));
  std::vector<char> active(static_cast<std::size_t>(nf));
  Eigen::MatrixXd k;
  // At a cell of level l, `rows` are the dofs of coarser levels that do not vanish there and m their coefficients
  // in the level's local functions; the level's active functions join as unit rows. Going to a child: m K, then
  // truncation (columns of the child level's functions with supp ⊆ Ω^{l+1} are zeroed).
  auto visit = [&](auto&& self, int level, Key cell, bool below_dirty, std::vector<Index> rows,
                   Eigen::MatrixXd m) -> void {
    if (previous && !below_dirty) {
      if (contains(*dirty, level, cell)) {
        below_dirty = true;
      } else if (!contains(*on_path, level, cell)) {
        copy_subtree(*previous, level, cell);
        return;
      }
    }
    const int nloc = h.local_functions(level, cell, fbuf.data());
    const Index inherited = static_cast<Index>(rows.size());
    for (int j = 0; j < nloc; ++j) {
      const Key f = fbuf[static_cast<std::size_t>(j)];
      FunctionState& s = function_state(level, f);
      if (s.dof == -2) s.dof = s.inside && !s.inside_next ? activate(level, f) : -1;
      if (s.dof >= 0) rows.push_back(s.dof);
      active[static_cast<std::size_t>(j)] = s.dof >= 0;
    }
    const Index total = static_cast<Index>(rows.size());
    m.conservativeResize(total, nloc);
    if (inherited == 0) m.setZero();
    m.bottomRows(total - inherited).setZero();
    for (int j = 0, r = static_cast<int>(inherited); j < nloc; ++j) {
      if (active[static_cast<std::size_t>(j)]) m(r++, j) = 1.0;
    }
    if (!is_refined(level, cell)) {
      drop_zero_rows(rows, m);
      add_leaf(level, cell, rows, m, inherited == 0 && total == nloc);
      if (previous) copied_from_.push_back(-1);
      return;
    }
    for (int slot = 0; slot < 4; ++slot) {
      const Key child = h.child(level, cell, slot);
      h.refinement(level, cell, slot, k);
      Eigen::MatrixXd mc = m * k;
      const int nc = h.local_functions(level + 1, child, child_buf.data());
      for (int j = 0; j < nc; ++j) {
        if (function_state(level + 1, child_buf[static_cast<std::size_t>(j)]).inside) mc.col(j).setZero();
      }
      std::vector<Index> rc = rows;
      drop_zero_rows(rc, mc);
      self(self, level + 1, child, below_dirty, std::move(rc), std::move(mc));
    }
  };
  for (Index c = 0; c < h.num_root_cells(); ++c) visit(visit, 0, Key{c}, false, {}, Eigen::MatrixXd());
  release_blocks();
  finish(level_of, function_of);
}

std::size_t HierarchicalSpace::coefficients_used() const {
  std::size_t n = 0;
  for (const Element& el : elements_) {
    if (el.coeff != nullptr) n += static_cast<std::size_t>(el.dof_end - el.dof_begin) * static_cast<std::size_t>(el.num_local);
  }
  return n;
}

std::size_t HierarchicalSpace::coefficients_held() const {
  std::size_t n = 0;
  for (const auto& b : blocks_) n += b->used;
  return n;
}

double* HierarchicalSpace::allocate_coefficients(std::size_t n, int& block) {
  if (filling_ == nullptr || filling_->capacity - filling_->used < n) {
    // Blocks grow geometrically from 4096 to 2^17 coefficients (1 MiB); pages are touched only when written.
    constexpr std::size_t smallest = std::size_t{1} << 12, largest = std::size_t{1} << 17;
    const std::size_t last = filling_ == nullptr ? 0 : filling_->capacity;
    auto b = std::make_shared<CoefficientBlock>();
    b->capacity = std::max(n, std::clamp(2 * last, smallest, largest));
    b->data = std::make_unique_for_overwrite<double[]>(b->capacity);
    filling_ = b.get();
    filling_block_ = static_cast<int>(blocks_.size());
    blocks_.push_back(std::move(b));
  }
  block = filling_block_;
  double* out = filling_->data.get() + filling_->used;
  filling_->used += n;
  return out;
}

void HierarchicalSpace::release_blocks() {
  const std::size_t shared = blocks_.size();
  std::vector<std::size_t> live(shared, 0);
  auto size_of = [](const Element& el) {
    return static_cast<std::size_t>(el.dof_end - el.dof_begin) * static_cast<std::size_t>(el.num_local);
  };
  for (const Element& el : elements_) {
    if (el.coeff != nullptr) live[static_cast<std::size_t>(el.block)] += size_of(el);
  }
  std::vector<char> sparse(shared, 0);
  for (std::size_t b = 0; b < shared; ++b) {
    sparse[b] = blocks_[b].get() != filling_ && 2 * live[b] < blocks_[b]->used;  // own blocks are full of live leaves
  }
  for (Element& el : elements_) {
    if (el.coeff == nullptr || static_cast<std::size_t>(el.block) >= shared || !sparse[static_cast<std::size_t>(el.block)]) continue;
    const std::size_t n = size_of(el);
    double* to = allocate_coefficients(n, el.block);
    std::copy(el.coeff, el.coeff + n, to);
    el.coeff = to;
  }
  // Only the blocks some leaf points into stay.
  std::vector<int> kept(blocks_.size(), -1);
  for (const Element& el : elements_) {
    if (el.coeff != nullptr) kept[static_cast<std::size_t>(el.block)] = 1;
  }
  std::vector<std::shared_ptr<const CoefficientBlock>> blocks;
  for (std::size_t b = 0; b < blocks_.size(); ++b) {
    if (kept[b] < 0) continue;
    kept[b] = static_cast<int>(blocks.size());
    blocks.push_back(std::move(blocks_[b]));
  }
  blocks_ = std::move(blocks);
  for (Element& el : elements_) {
    if (el.coeff != nullptr) el.block = kept[static_cast<std::size_t>(el.block)];
  }
  filling_ = nullptr;
  filling_block_ = -1;
}

void HierarchicalSpace::add_leaf(int level, Key cell, const std::vector<Index>& rows, const Eigen::MatrixXd& m,
                                 bool identity) {
  Element el;
  el.level = level;
  el.cell = cell;
  el.num_local = static_cast<int>(m.cols());
  el.dof_begin = static_cast<Index>(dofs_.size());
  dofs_.insert(dofs_.end(), rows.begin(), rows.end());
  el.dof_end = static_cast<Index>(dofs_.size());
  if (!identity) {
    double* to = allocate_coefficients(static_cast<std::size_t>(m.size()), el.block);
    std::copy(m.data(), m.data() + m.size(), to);
    el.coeff = to;
  }
  elements_.push_back(el);
}

void HierarchicalSpace::finish(const std::vector<int>& level_of, const std::vector<Key>& function_of) {
  std::vector<Index> number(level_of.size(), -1);
  Index next = 0;
  for (Index& d : dofs_) {
    Index& n = number[static_cast<std::size_t>(d)];
    if (n < 0) n = next++;
    d = n;
  }
  const auto count = static_cast<std::size_t>(next);
  dof_level_.assign(count, 0);
  dof_function_.assign(count, 0);
  for (std::size_t p = 0; p < number.size(); ++p) {
    if (number[p] < 0) continue;
    dof_level_[static_cast<std::size_t>(number[p])] = level_of[p];
    dof_function_[static_cast<std::size_t>(number[p])] = function_of[p];
  }
  dof_home_.assign(count, -1);
  dof_home_local_.assign(count, -1);
  leaf_index_.assign(refined_.size() + 1, {});
  {
    std::vector<std::size_t> per_level(leaf_index_.size(), 0);
    for (const Element& el : elements_) ++per_level[static_cast<std::size_t>(el.level)];
    for (std::size_t l = 0; l < per_level.size(); ++l) leaf_index_[l].reserve(per_level[l]);
  }
  max_local_ = 0;
  num_levels_ = 1;
  for (Index e = 0; e < num_elements(); ++e) {
    const Element& el = elements_[static_cast<std::size_t>(e)];
    leaf_index_[static_cast<std::size_t>(el.level)][el.cell] = e;
    const Index n = el.dof_end - el.dof_begin;
    max_local_ = std::max(max_local_, n);
    num_levels_ = std::max(num_levels_, el.level + 1);
    for (Index r = 0; r < n; ++r) {
      const auto d = static_cast<std::size_t>(dofs_[static_cast<std::size_t>(el.dof_begin + r)]);
      if (dof_level_[d] != el.level || dof_home_[d] >= 0) continue;
      // The first leaf of the dof's level where it is a row: there its row is a unit row (its local function).
      dof_home_[d] = e;
      Index j = r;
      if (el.coeff != nullptr) {
        const Eigen::Map<const Eigen::MatrixXd> c(el.coeff, n, el.num_local);
        c.row(r).cwiseAbs().maxCoeff(&j);
      }
      dof_home_local_[d] = static_cast<int>(j);
    }
  }
  for (std::size_t d = 0; d < count; ++d) {
    if (dof_home_[d] < 0) throw NumericalError("hierarchical space: dof " + std::to_string(d) + " has no leaf of its level");
  }
}

Eigen::MatrixXd HierarchicalSpace::element_coefficients(const Element& el) const {
  if (el.coeff == nullptr) return Eigen::MatrixXd::Identity(el.num_local, el.num_local);
  return Eigen::Map<const Eigen::MatrixXd>(el.coeff, el.dof_end - el.dof_begin, el.num_local);
}

Eigen::SparseMatrix<double> HierarchicalSpace::prolongation_from_previous(const HierarchicalSpace& previous) const {
  const LevelHierarchy& h = *hierarchy_;
  std::vector<Eigen::Triplet<double>> entries;
  entries.reserve(static_cast<std::size_t>(num_dofs()));
  Eigen::MatrixXd k, cur;
  std::vector<int> slots;
  Index cur_element = -1, previous_leaf = -1;
  for (Index d = 0; d < num_dofs(); ++d) {
    const Index e = dof_home_[static_cast<std::size_t>(d)];
    const Element& el = elements_[static_cast<std::size_t>(e)];
    const auto list = dofs(e);
    const Index from = copied_from_[static_cast<std::size_t>(e)];
    if (from >= 0) {
      // A copied leaf: the dof's function is the previous space's function in the same row, unchanged there.
      const auto row = static_cast<std::size_t>(std::find(list.begin(), list.end(), d) - list.begin());
      entries.emplace_back(d, previous.dofs(from)[row], 1.0);
      continue;
    }
    if (e != cur_element) {
      // The previous space's leaf containing the cell, and its functions refined down to it.
      int level = el.level;
      Key cell = el.cell;
      slots.clear();
      while ((previous_leaf = previous.element_of(level, cell)) < 0) {
        if (level == 0) throw NumericalError("hierarchical prolongation: the spaces are not nested");
        int slot = 0;
        cell = h.parent(level--, cell, slot);
        slots.push_back(slot);
      }
      cur = previous.element_coefficients(previous.elements_[static_cast<std::size_t>(previous_leaf)]);
      for (auto s = slots.rbegin(); s != slots.rend(); ++s) {
        h.refinement(level, cell, *s, k);
        cur = (cur * k).eval();
        cell = h.child(level++, cell, *s);
      }
      cur_element = e;
    }
    const int j = dof_home_local_[static_cast<std::size_t>(d)];
    const auto rows = previous.dofs(previous_leaf);
    for (std::size_t r = 0; r < rows.size(); ++r) {
      const double v = cur(static_cast<Index>(r), j);
      if (std::abs(v) > 1e-15) entries.emplace_back(d, rows[r], v);
    }
  }
  Eigen::SparseMatrix<double> p(num_dofs(), previous.num_dofs());
  p.setFromTriplets(entries.begin(), entries.end());
  return p;
}

}  // namespace iga::basis::hierarchical
