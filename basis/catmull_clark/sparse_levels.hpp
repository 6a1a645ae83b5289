#pragma once
// The levels of hierarchical Catmull–Clark splines held cell by cell (issue 34): a cell of level l exists once
// something asks for it, as its neighbourhood (local_mesh.hpp: the faces of its level that share a vertex with
// it, with keys) derived from its parent's by one local Catmull–Clark step. Nothing is built per level, so the
// depth is limited by the keys (128 bits: at least 50 levels on a net of 10^4 faces) and by double precision (the
// deepest level's edges, 2^-l of the net's shortest, at least 64 rounding units of its coordinates: 42 levels on
// l_shape.obj), and memory grows with the cells that are used, not with 4^l.
//
// The same spaces as CatmullClarkLevels (levels.hpp: whole refined nets), for the clamped rule or a closed net,
// where every cell of the domain has its whole one-ring in the extended net (ghost_net.hpp) and the levels'
// functions are Catmull–Clark's interior ones. Cell keys are CatmullClarkLevels' (child k of cell c is 4 c + k,
// the domain's faces are the roots); function keys are local_mesh.hpp's vertex keys (level 0: the control net's
// vertices, CatmullClarkSpace's dofs). A cell's functions are evaluated by a CatmullClarkSpace on one element built
// once per topology of the neighbourhood (in practice one per valence): the cell's neighbourhood renumbered by
// canonical_mesh is that space's net, its element 0 the cell, so values, frames (corner c0 at the extraordinary
// vertex) and methods (Stam's at interior vertices) are CatmullClarkSpace's.
//
// Cells are made on first use, under a lock, and never change or move afterwards: evaluation is thread-safe.
#include <atomic>
#include <cstdint>
#include <memory>
#include <mutex>
#include <shared_mutex>
#include <unordered_map>
#include <vector>

#include "basis/catmull_clark/hierarchy_base.hpp"
#include "basis/catmull_clark/local_mesh.hpp"
#include "basis/catmull_clark/space.hpp"
#include "basis/hierarchical/level_hierarchy.hpp"

namespace iga::basis::catmull_clark {

class SparseCatmullClarkLevels final : public CatmullClarkHierarchy {
 public:
  /// Level 0 is `level0` (clamped rule, or a closed net: InputError otherwise). Its net has quads only and at most
  /// one EV per face (every CatmullClarkSpace's control_mesh() has).
  explicit SparseCatmullClarkLevels(std::shared_ptr<const CatmullClarkSpace> level0);
  ~SparseCatmullClarkLevels() override;

  /// Whether a space can be level 0 (the clamped rule or a net without boundary).
  static bool supports(const CatmullClarkSpace& level0);

  int local_functions(int level, Key cell, Key* out) const override;
  void support(int level, Key function, std::vector<Key>& cells) const override;
  void refinement(int level, Key cell, int slot, Eigen::MatrixXd& k) const override;
  void evaluate(int level, Key cell, const Eigen::Matrix2Xd& pts, int derivatives, BasisValues& out) const override;
  ElementKind kind(int level, Key cell) const override;
  int boundary_part(int level, Key cell, int side) const override;
  Key neighbour(int level, Key cell, int side, int& their_side) const override;

  /// Cells made so far, over all levels (what the memory grows with).
  std::size_t cells_made() const;

 private:
  struct Cell;
  struct Template;
  const Cell& cell(int level, Key key) const;
  std::unique_ptr<Cell> make_cell(int level, Key key) const;
  void finish(int level, Cell& c) const;
  const Template& template_for(const CanonicalMesh& canonical) const;
  // A cell of `level` having `vertex` as its native corner `corner`.
  Key corner_cell(int level, Key vertex, int& corner) const;
  bool in_domain(int level, Key face) const;
  int native_part(int level, Key cell, int native_side) const;

  int rotation(int level, Key cell) const override;
  const RefinedMesh& refined(int level, Key cell) const;

  std::uint64_t id_ = 0;  // tells this object's entries in refined()'s per-thread cache from another's
  KeyBounds bounds_;
  std::vector<std::vector<Index>> vertex_faces_;  // level 0: faces of the extended net at each vertex
  std::vector<Index> support_offsets_, support_cells_;  // level 0: vertex -> elements whose dofs contain it
  std::vector<int> part_;                               // level 0: 4 per element, native sides: part or -1
  mutable std::shared_mutex mutex_;
  mutable std::vector<std::unordered_map<Key, std::unique_ptr<Cell>, hierarchical::KeyHash>> cells_;  // levels >= 1
  // Levels >= 1: the supports found so far (support() refines a coarse cell's neighbourhood to find one; the
  // hierarchical builds ask for the same functions again at every step).
  mutable std::vector<std::unordered_map<Key, std::vector<Key>, hierarchical::KeyHash>> supports_;
  // Level 0 (domain and ghost faces of the extended net), looked up without a lock once made.
  mutable std::vector<std::unique_ptr<Cell>> roots_;
  std::unique_ptr<std::atomic<const Cell*>[]> root_ready_;
  mutable std::mutex template_mutex_;
  mutable std::vector<std::unique_ptr<Template>> templates_;
};

}  // namespace iga::basis::catmull_clark
