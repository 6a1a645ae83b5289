#include "basis/catmull_clark/levels.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "basis/catmull_clark/sparse_levels.hpp"
#include "basis/catmull_clark/topology.hpp"
#include "core/error.hpp"
#include "core/memory.hpp"

namespace iga::basis::catmull_clark {

using hierarchical::Key;


struct CatmullClarkLevels::Level {
  std::shared_ptr<const CatmullClarkSpace> space;
  Eigen::SparseMatrix<double, Eigen::RowMajor> subdivision;  // this level × previous level (level >= 1)
  std::vector<Index> support_offsets, support_cells;         // vertex → elements whose dofs contain it
  std::vector<int> part;                                     // 4 per element (rotated sides): part or -1
};

// The inverse dof map of a level: vertex v → the elements whose dofs contain it.
void CatmullClarkLevels::fill_support(Level& lv) {
  const CatmullClarkSpace& s = *lv.space;
  const Index nv = s.num_dofs(), nf = s.num_elements();
  lv.support_offsets.assign(static_cast<std::size_t>(nv) + 1, 0);
  for (Index e = 0; e < nf; ++e) {
    for (Index d : s.dofs(e)) ++lv.support_offsets[static_cast<std::size_t>(d) + 1];
  }
  for (Index v = 0; v < nv; ++v) lv.support_offsets[static_cast<std::size_t>(v) + 1] += lv.support_offsets[static_cast<std::size_t>(v)];
  lv.support_cells.resize(static_cast<std::size_t>(lv.support_offsets.back()));
  std::vector<Index> fill(lv.support_offsets.begin(), lv.support_offsets.end() - 1);
  for (Index e = 0; e < nf; ++e) {
    for (Index d : s.dofs(e)) lv.support_cells[static_cast<std::size_t>(fill[static_cast<std::size_t>(d)]++)] = e;
  }
}

CatmullClarkLevels::CatmullClarkLevels(std::shared_ptr<const CatmullClarkSpace> level0)
    : CatmullClarkHierarchy(std::move(level0)) {
  const Index faces = level0_->num_elements();
  if (faces > kMaxFaces) {
    throw UnsupportedError("Catmull–Clark levels: the control net has " + std::to_string(faces) +
                           " faces, more than the budget of " + std::to_string(kMaxFaces) + " per level");
  }
  while ((faces << (2 * (max_level_ + 1))) <= kMaxFaces) ++max_level_;
  owned_.resize(static_cast<std::size_t>(max_level_) + 1);
  ready_ = std::make_unique<std::atomic<const Level*>[]>(static_cast<std::size_t>(max_level_) + 1);
  for (int l = 0; l <= max_level_; ++l) ready_[static_cast<std::size_t>(l)].store(nullptr, std::memory_order_relaxed);

  auto first = std::make_unique<Level>();
  first->space = level0_;
  first->part.assign(static_cast<std::size_t>(4 * faces), -1);
  for (const BoundaryEdge& e : level0_->boundary_edges()) {
    first->part[static_cast<std::size_t>(4 * e.element + e.side)] = e.part;
  }
  fill_support(*first);
  owned_[0] = std::move(first);
  ready_[0].store(owned_[0].get(), std::memory_order_release);
}

CatmullClarkLevels::~CatmullClarkLevels() = default;

int CatmullClarkLevels::built_levels() const {
  int n = 0;
  while (n <= max_level_ && ready_[static_cast<std::size_t>(n)].load(std::memory_order_acquire) != nullptr) ++n;
  return n;
}

std::unique_ptr<CatmullClarkLevels::Level> CatmullClarkLevels::make_level(const Level& coarse) const {
  const CatmullClarkSpace& cs = *coarse.space;
  SpaceRefinement r = refine_space(cs, 1);
  if (r.space->num_elements() != 4 * cs.num_elements()) {
    throw std::logic_error("Catmull–Clark levels: a refined all-quad net does not have 4 faces per face");
  }
  auto out = std::make_unique<Level>();
  out->space = std::move(r.space);
  if (out->space->refinement_steps() != 0) throw NumericalError("Catmull–Clark levels: a refined net needed a global step");
  out->subdivision = r.prolongation;
  const CatmullClarkSpace& fs = *out->space;
  fill_support(*out);
  // Boundary parts inherited from the parent: child k's native edges k and k - 1 lie on the parent's edges
  // k and k - 1; the others are interior.
  out->part.assign(static_cast<std::size_t>(4 * fs.num_elements()), -1);
  Index boundary_sides = 0;
  for (Index f = 0; f < cs.num_elements(); ++f) {
    const int rp = cs.rotation(f);
    for (int k = 0; k < 4; ++k) {
      const Index c = 4 * f + k;
      const int rc = fs.rotation(c);
      for (int j : {k, (k + 3) % 4}) {
        const int part = coarse.part[static_cast<std::size_t>(4 * f + (j - rp + 4) % 4)];
        if (part < 0) continue;
        out->part[static_cast<std::size_t>(4 * c + (j - rc + 4) % 4)] = part;
        ++boundary_sides;
      }
    }
  }
  const std::vector<BoundaryEdge> edges = fs.boundary_edges();
  bool consistent = static_cast<Index>(edges.size()) == boundary_sides;
  for (const BoundaryEdge& e : edges) consistent = consistent && out->part[static_cast<std::size_t>(4 * e.element + e.side)] >= 0;
  if (!consistent) throw std::logic_error("Catmull–Clark levels: boundary of a refined net does not match its parent's");
  return out;
}

// A whole level holds its refined net, its space (a 16 × 16 operator per regular element) and its subdivision
// matrix: measured 2.85 kB of resident memory per face on l_shape.obj (levels 6 and 7: +0.56 and +2.24 GB, the
// adaptive loop's peak RSS); refused below that, so a level it refuses could not have been built.
void CatmullClarkLevels::check_level_memory(int m) const {
  constexpr double kBytesPerFace = 2500.0;
  const double faces = static_cast<double>(level0_->num_elements()) * std::pow(4.0, m);
  const double available = available_memory();
  if (kBytesPerFace * faces <= available) return;
  throw UnsupportedError("Catmull–Clark levels: level " + std::to_string(m) + " (the whole net refined " + std::to_string(m) +
                         " times, " + std::to_string(static_cast<long long>(faces)) + " faces) would need about " +
                         gib_text(kBytesPerFace * faces) + " of memory, more than the " + gib_text(available) +
                         " available (--cc-boundary clamped makes the levels cell by cell)");
}

std::string CatmullClarkLevels::depth_limit() const {
  return "builds (whole refined nets of at most " + std::to_string(kMaxFaces) +
         " faces each: the natural rule on an open net; --cc-boundary clamped makes the levels cell by cell)";
}

const CatmullClarkLevels::Level& CatmullClarkLevels::level(int l) const {
  if (l < 0 || l > max_level_) {
    throw UnsupportedError("Catmull–Clark levels: level " + std::to_string(l) + " is beyond the deepest level " +
                           std::to_string(max_level_) + " (at most " + std::to_string(kMaxFaces) +
                           " elements per level)");
  }
  if (const Level* p = ready_[static_cast<std::size_t>(l)].load(std::memory_order_acquire)) return *p;
  const std::lock_guard<std::mutex> lock(mutex_);
  for (int m = 1; m <= l; ++m) {
    if (owned_[static_cast<std::size_t>(m)]) continue;
    check_level_memory(m);
    owned_[static_cast<std::size_t>(m)] = make_level(*owned_[static_cast<std::size_t>(m) - 1]);
    ready_[static_cast<std::size_t>(m)].store(owned_[static_cast<std::size_t>(m)].get(), std::memory_order_release);
  }
  return *owned_[static_cast<std::size_t>(l)];
}

const CatmullClarkSpace& CatmullClarkLevels::space(int l) const { return *level(l).space; }

const Eigen::SparseMatrix<double, Eigen::RowMajor>& CatmullClarkLevels::subdivision(int l) const {
  if (l < 1) throw InputError("Catmull–Clark levels: level 0 has no subdivision matrix");
  return level(l).subdivision;
}

int CatmullClarkLevels::local_functions(int l, Key cell, Key* out) const {
  const auto d = space(l).dofs(cell);
  std::copy(d.begin(), d.end(), out);
  return static_cast<int>(d.size());
}

void CatmullClarkLevels::support(int l, Key function, std::vector<Key>& cells) const {
  const Level& lv = level(l);
  cells.assign(lv.support_cells.begin() + lv.support_offsets[static_cast<std::size_t>(function)],
               lv.support_cells.begin() + lv.support_offsets[static_cast<std::size_t>(function) + 1]);
}

void CatmullClarkLevels::refinement(int l, Key cell, int slot, Eigen::MatrixXd& k) const {
  const auto dp = space(l).dofs(cell);
  const auto dc = space(l + 1).dofs(4 * cell + slot);
  const auto& s = subdivision(l + 1);
  k.setZero(static_cast<Eigen::Index>(dp.size()), static_cast<Eigen::Index>(dc.size()));
  for (std::size_t j = 0; j < dc.size(); ++j) {
    for (Eigen::SparseMatrix<double, Eigen::RowMajor>::InnerIterator it(s, dc[j]); it; ++it) {
      const auto at = std::lower_bound(dp.begin(), dp.end(), static_cast<Index>(it.col()));  // dofs are sorted
      if (at != dp.end() && *at == it.col()) k(at - dp.begin(), static_cast<Eigen::Index>(j)) = it.value();
    }
  }
}

void CatmullClarkLevels::evaluate(int l, Key cell, const Eigen::Matrix2Xd& pts, int derivatives, BasisValues& out) const {
  space(l).evaluate(cell, pts, derivatives, out);
}

int CatmullClarkLevels::boundary_part(int l, Key cell, int side) const {
  return level(l).part[static_cast<std::size_t>(4 * cell + side)];
}

Key CatmullClarkLevels::neighbour(int l, Key cell, int side, int& their_side) const {
  const CatmullClarkSpace& s = space(l);
  const mesh::PolyMesh& net = s.control_mesh();
  const Index h = net.face_half_edge(cell) + (side + s.rotation(cell)) % 4;
  const Index t = net.half_edge(h).twin;
  if (t < 0 || net.half_edge(t).face >= s.num_elements()) {  // the boundary (or a ghost face beyond it)
    their_side = -1;
    return -1;
  }
  const Index g = net.half_edge(t).face;
  their_side = (static_cast<int>(t - net.face_half_edge(g)) - s.rotation(g) + 4) % 4;
  return g;
}

std::shared_ptr<const hierarchical::HierarchicalSpace> coarse_hierarchical_space(
    std::shared_ptr<const CatmullClarkSpace> level0) {
  std::shared_ptr<const hierarchical::LevelHierarchy> levels;
  if (SparseCatmullClarkLevels::supports(*level0)) {
    levels = std::make_shared<const SparseCatmullClarkLevels>(std::move(level0));
  } else {
    levels = std::make_shared<const CatmullClarkLevels>(std::move(level0));
  }
  return std::make_shared<const hierarchical::HierarchicalSpace>(std::move(levels), hierarchical::RefinedCells{});
}

}  // namespace iga::basis::catmull_clark
