#pragma once
// What the two forms of hierarchical Catmull–Clark levels share (levels.hpp: whole refined nets;
// sparse_levels.hpp: cell by cell): cell keys (the children of cell c are 4 c + k, refine_net's numbering, the
// level-0 space's elements are the roots), element frames rotated so that corner c0 is the extraordinary vertex
// (CatmullClarkSpace::rotation) and the child maps that follow from them, degrees and continuity from the kinds.
#include <memory>
#include <string>
#include <vector>

#include "basis/catmull_clark/space.hpp"
#include "basis/hierarchical/level_hierarchy.hpp"

namespace iga::basis::catmull_clark {

class CatmullClarkHierarchy : public hierarchical::LevelHierarchy {
 public:
  using Key = hierarchical::Key;

  std::string name() const override { return "cc"; }
  int max_level() const override { return max_level_; }
  Index num_root_cells() const override { return level0_->num_elements(); }
  Key child(int, Key cell, int slot) const override { return 4 * cell + slot; }
  Key parent(int, Key cell, int& slot) const override {
    slot = static_cast<int>(cell % 4);
    return cell / 4;
  }
  /// Child k covers the quarter at its parent's native corner k in the parent's native orientation; both frames
  /// are rotated by their cells' rotations.
  void child_map(int level, Key cell, int slot, Eigen::Matrix2d& a, Eigen::Vector2d& b) const override;
  int max_local_functions() const override { return max_local_; }
  /// 3 on regular cells (bicubic B-spline patches), none at an extraordinary vertex.
  std::optional<int> polynomial_degree(int level, Key cell) const override;
  std::vector<std::string> boundary_part_names() const override { return level0_->boundary_part_names(); }
  /// 1 across the two sides of an element that meet its extraordinary vertex, 2 elsewhere.
  int continuity(int level, Key cell, int side) const override;

 protected:
  /// InputError for a null space; max_local_functions() covers level 0 and deeper one-rings (2n + 8, n <= 16).
  explicit CatmullClarkHierarchy(std::shared_ptr<const CatmullClarkSpace> level0);
  /// Rotation r of a cell's element frame: corner c_i is the cell's native corner (i + r) % 4.
  virtual int rotation(int level, Key cell) const = 0;

  std::shared_ptr<const CatmullClarkSpace> level0_;
  int max_level_ = 0;
  int max_local_ = 0;
};

}  // namespace iga::basis::catmull_clark
