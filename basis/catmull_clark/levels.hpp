#pragma once
// The levels of hierarchical Catmull–Clark subdivision splines (thesis §4.2.5, Fig. 4.20): level l is the
// CatmullClarkSpace of the control net refined l times by Catmull–Clark (OpenSubdiv's uniform refinement,
// refine_net), and the two-scale relation is the subdivision matrix S_l (fine vertices × coarse vertices,
// fine positions = S_l · coarse positions): a level-l vertex function φ_v = Σ_w S_l(w, v) φ_w^{l+1}.
//
// Cells of level l are the faces (elements) of the level-l space; the children of face f are the faces
// 4f + k of level l + 1 (refine_net: child k is the quarter at the parent's corner k, in the parent's native
// corner order), so child slot k is OpenSubdiv's child k. Both levels rotate their elements so that corner
// c0 is the extraordinary vertex (CatmullClarkSpace::rotation), so the map from a child's reference square to
// its parent's depends on the rotations of both: child_map(level, cell, slot, ...).
//
// Levels are built on first use (a level's net, its space, the inverse dof → elements map and the boundary
// table), under a mutex; a built level never moves or changes, so evaluation is thread-safe. Level l has
// 4^l × faces(level 0) elements and costs about 2.9 kB per element (measured RSS, square_evs.obj levels 1–5:
// level 5, 147456 elements, builds in 4 s; the space's 16 × 16 regular operators dominate); max_level() is the
// deepest level with at most kMaxFaces elements.
#include <Eigen/Sparse>
#include <atomic>
#include <memory>
#include <mutex>
#include <vector>

#include "basis/catmull_clark/hierarchy_base.hpp"
#include "basis/catmull_clark/space.hpp"
#include "basis/hierarchical/hierarchical_space.hpp"
#include "basis/hierarchical/level_hierarchy.hpp"

namespace iga::basis::catmull_clark {

class CatmullClarkLevels final : public CatmullClarkHierarchy {
 public:
  // Cells and functions of a level fit Index here (kMaxFaces).
  /// The element budget of one level (2^20: about 3 GB for that level alone).
  static constexpr Index kMaxFaces = Index{1} << 20;

  /// Level 0 is `level0` itself (its control net, elements, dofs, boundary parts). Its net has quads only and
  /// at most one EV per face (every CatmullClarkSpace's control_mesh() has), so refinement needs no global step.
  explicit CatmullClarkLevels(std::shared_ptr<const CatmullClarkSpace> level0);
  ~CatmullClarkLevels() override;

  int local_functions(int level, Key cell, Key* out) const override;
  void support(int level, Key function, std::vector<Key>& cells) const override;
  void refinement(int level, Key cell, int slot, Eigen::MatrixXd& k) const override;
  void evaluate(int level, Key cell, const Eigen::Matrix2Xd& pts, int derivatives, BasisValues& out) const override;
  ElementKind kind(int level, Key cell) const override { return space(level).kind(cell); }
  int boundary_part(int level, Key cell, int side) const override;
  Key neighbour(int level, Key cell, int side, int& their_side) const override;

  /// The space of level l (built on first use; UnsupportedError beyond max_level()).
  const CatmullClarkSpace& space(int level) const;
  /// S_l: level-l vertices × level-(l-1) vertices (level >= 1).
  const Eigen::SparseMatrix<double, Eigen::RowMajor>& subdivision(int level) const;
  /// Levels built so far.
  int built_levels() const;
  bool level_built(int level) const override { return level < built_levels(); }
  std::string depth_limit() const override;

 private:
  struct Level;
  const Level& level(int l) const;
  std::unique_ptr<Level> make_level(const Level& coarse) const;
  /// UnsupportedError when level m (4^m times level 0's faces) is predicted not to fit in the available memory.
  void check_level_memory(int m) const;
  static void fill_support(Level& level);

  int rotation(int level, Key cell) const override { return space(level).rotation(cell); }

  mutable std::mutex mutex_;
  mutable std::vector<std::unique_ptr<Level>> owned_;              // max_level_ + 1 slots, filled in order
  std::unique_ptr<std::atomic<const Level*>[]> ready_;             // published levels
};

/// The hierarchical space on a Catmull–Clark space with nothing refined yet (its elements are the space's, in
/// order; dof d is vertex dof_function(d) of the control net). Its levels are made cell by cell
/// (SparseCatmullClarkLevels) where they can be (the clamped rule, closed nets), else whole nets (CatmullClarkLevels).
std::shared_ptr<const hierarchical::HierarchicalSpace> coarse_hierarchical_space(
    std::shared_ptr<const CatmullClarkSpace> level0);

}  // namespace iga::basis::catmull_clark
