#pragma once
// Truncated hierarchical splines (THB; thesis Appendix A; Giannelli, Jüttler, Speleers 2012) on the nested
// levels of a LevelHierarchy, as a Space the assembler uses unchanged.
//
// The mesh is a forest of cells: the cells of level 0, and the four children of every refined cell. Ω^l is the
// union of the cells of level l that exist (level 0: the domain). Elements are the leaves (cells that are not
// refined), in depth-first order of the forest. The functions (Kraft's selection rule):
//   H^l = { B^l_f : supp B^l_f ⊆ Ω^l and supp B^l_f ⊄ Ω^{l+1} },
// each truncated at every finer level m: its level-m coefficients of the B^m with supp ⊆ Ω^m are dropped.
// On every leaf, each function is stored as its coefficients in the leaf level's local functions (per-element
// extraction: the level's evaluator then gives values and derivatives).
//
// Dofs are numbered by first appearance in the elements' dof lists, in element order. Each dof's "home" is a leaf of its own level in its
// support; reading there the function's local coefficient is a dual functional of the THB basis (Speleers and
// Manni 2016): this gives exact coefficients of coarse-level splines (the geometry) and the prolongation
// between nested hierarchical spaces.
#include <Eigen/Core>
#include <Eigen/Sparse>
#include <functional>
#include <cstdint>
#include <memory>
#include <span>
#include <unordered_map>
#include <unordered_set>
#include <vector>

#include "basis/hierarchical/level_hierarchy.hpp"
#include "basis/space.hpp"

namespace iga::basis::hierarchical {

/// The refined cells of each level (level l: cells of level l whose four children exist).
using RefinedCells = std::vector<std::unordered_set<Key, KeyHash>>;
/// A cell of one level.
struct LevelCell {
  int level = 0;
  Key cell = 0;
};

class HierarchicalSpace final : public Space {
 public:
  /// InputError when a refined cell of level l >= 1 is not in Ω^l (its parent is not refined).
  HierarchicalSpace(std::shared_ptr<const LevelHierarchy> hierarchy, RefinedCells refined);
  /// The same space as HierarchicalSpace(previous.hierarchy_ptr(), refined), built from `previous` (refined ⊇
  /// previous.refined(), `added` the cells refined since): a function's selection or truncation can change only
  /// if its support meets a newly refined cell or one of its children, so only the subtrees under the newly
  /// refined cells' support extensions are recomputed (with the paths down to them); every other leaf keeps its
  /// element data, copied. prolongation_from(previous) then computes only the rows of the dofs whose home leaf was
  /// recomputed (the others are unit rows). InputError when `added` does not account for the new refined cells.
  HierarchicalSpace(const HierarchicalSpace& previous, RefinedCells refined, std::span<const LevelCell> added);

  std::string name() const override { return hierarchy_->name(); }
  Index num_dofs() const override { return static_cast<Index>(dof_level_.size()); }
  Index num_elements() const override { return static_cast<Index>(elements_.size()); }
  ElementKind kind(Index e) const override;
  std::span<const Index> dofs(Index e) const override;
  Index max_local_dofs() const override { return max_local_; }
  void evaluate(Index e, const Eigen::Matrix2Xd& pts, int derivatives, BasisValues& out) const override;
  std::vector<BoundaryEdge> boundary_edges() const override;
  std::vector<std::string> boundary_part_names() const override { return hierarchy_->boundary_part_names(); }
  std::vector<InteriorEdge> interior_edges() const override;
  int level(Index e) const override { return elements_[static_cast<std::size_t>(e)].level; }
  bool builds_level(int level) const override {
    return level <= hierarchy_->max_level() && !hierarchy_->level_built(level);
  }
  /// The hierarchy's polynomial_degree of the element's cell.
  std::optional<int> polynomial_degree(Index e) const override;

  const LevelHierarchy& hierarchy() const { return *hierarchy_; }
  const std::shared_ptr<const LevelHierarchy>& hierarchy_ptr() const { return hierarchy_; }
  const RefinedCells& refined() const { return refined_; }
  /// Cell (of its level) of element e.
  Key cell(Index e) const { return elements_[static_cast<std::size_t>(e)].cell; }
  /// Levels with elements: 1 + the deepest leaf level.
  int num_levels() const { return num_levels_; }
  /// Level of dof d, and the index of its function among its level's functions.
  int dof_level(Index d) const { return dof_level_[static_cast<std::size_t>(d)]; }
  Key dof_function(Index d) const { return dof_function_[static_cast<std::size_t>(d)]; }
  /// The element that is cell `cell` of level `level`, or -1 when that cell is no leaf.
  Index element_of(int level, Key cell) const;
  /// Whether cell `cell` of level `level` exists (lies in Ω^level) / is refined.
  bool exists(int level, Key cell) const;
  bool is_refined(int level, Key cell) const;
  /// The leaf containing cell `cell` of level `level` (the cell itself or an ancestor); -1 when the cell is
  /// refined.
  Index leaf_containing(int level, Key cell) const;

  /// Coefficients (num_dofs × columns) in this space of the level-0 spline with coefficients c0 (one row per
  /// level-0 function, ordered by level-0 function index). Exact: the spline lies in the space.
  Eigen::MatrixXd from_level0(const Eigen::MatrixXd& c0, Index level0_functions) const;
  /// Prolongation from a coarser hierarchical space on the same hierarchy (every cell it refines, this one
  /// refines too): fine coefficients = P × coarse coefficients. InputError when the spaces are not nested.
  Eigen::SparseMatrix<double> prolongation_from(const HierarchicalSpace& coarse) const;
  /// prolongation_from(coarse) × c without forming the matrix (num_dofs × c.cols()): for control points.
  Eigen::MatrixXd coefficients_from(const HierarchicalSpace& coarse, const Eigen::MatrixXd& c) const;
  /// Truncation coefficients the leaves use, and those the space holds in its blocks (shared with the spaces it was
  /// built from or that were built from it): held <= 2 × used (release_blocks).
  std::size_t coefficients_used() const;
  std::size_t coefficients_held() const;
  /// Whether this space was built from `previous` by the incremental constructor (prolongation_from(previous)
  /// then costs what the change costs).
  bool built_from(const HierarchicalSpace& previous) const {
    return previous_serial_ != 0 && previous.serial_ == previous_serial_;
  }

 private:
  struct Element {
    int level = 0;
    Key cell = 0;
    Index dof_begin = 0, dof_end = 0;  // into dofs_
    const double* coeff = nullptr;     // (dofs × local functions) column-major, in blocks_[block]; null: identity
    int block = -1;
    int num_local = 0;                 // level-local functions on the cell
  };
  // The leaves' coefficients are written once into blocks that never move: a space built from another shares the
  // blocks its copied leaves point into instead of copying them; a shared block less than half of which is still
  // in use is compacted away (release_blocks), so the blocks hold at most about twice the space's coefficients.
  struct CoefficientBlock {
    std::unique_ptr<double[]> data;
    std::size_t capacity = 0, used = 0;
  };
  using CellSets = std::vector<std::unordered_set<Key, KeyHash>>;
  /// Drops empty deepest levels of refined_; UnsupportedError when it is deeper than the hierarchy can index.
  void trim_and_check_depth();
  void build();
  void build_from(const HierarchicalSpace& previous, std::span<const LevelCell> added);
  /// The depth-first pass that makes the elements (hierarchical_build.cpp); with `previous`, the subtrees that
  /// hold no cell of `dirty` and no path to one are copied from it.
  void traverse(const HierarchicalSpace* previous, const CellSets* dirty, const CellSets* on_path);
  /// Appends a leaf: its dofs (`rows`, provisional ids) and their coefficients in the level's local functions
  /// (`m`, not stored when the identity).
  void add_leaf(int level, Key cell, const std::vector<Index>& rows, const Eigen::MatrixXd& m, bool identity);
  /// Appends the previous space's leaves under cell `cell` of level `level` (a subtree both spaces share; their
  /// coefficient blocks are shared, block_map_ says where each previous block sits in blocks_).
  void copy_subtree(const HierarchicalSpace& previous, int level, Key cell);
  /// Room for n coefficients in the block being filled (a new one when it is full); `block` gets its index.
  double* allocate_coefficients(std::size_t n, int& block);
  /// After a build: the leaves of shared blocks less than half in use get their coefficients copied into this
  /// space's own blocks; blocks no leaf uses are let go.
  void release_blocks();
  /// The dof of function `function` of level `level`, or -1 when it is not active (`cells`: scratch).
  Index dof_of(int level, Key function, std::vector<Key>& cells) const;
  /// After a build: dofs renumbered by first appearance in the elements' lists (dof_level_/dof_function_ are
  /// indexed by the build's provisional ids), their homes, the leaf index, max_local_ and num_levels_.
  void finish(const std::vector<int>& level_of, const std::vector<Key>& function_of);
  /// The leaf's coefficients (its dofs × its level's local functions).
  Eigen::MatrixXd element_coefficients(const Element& el) const;
  /// prolongation_from(previous) when this space was built from it: unit rows for dofs at home in copied leaves.
  Eigen::SparseMatrix<double> prolongation_from_previous(const HierarchicalSpace& previous) const;
  /// Coefficients of a spline in this space from its local coefficients on the first cells (down every path
  /// of the forest) where source(level, cell, v) gives them, refined down to the leaves.
  Eigen::MatrixXd coefficients_by_descent(Index columns,
                                          const std::function<bool(int, Key, Eigen::MatrixXd&)>& source) const;

  std::shared_ptr<const LevelHierarchy> hierarchy_;
  RefinedCells refined_;
  std::vector<Element> elements_;
  std::vector<Index> dofs_;
  std::vector<std::shared_ptr<const CoefficientBlock>> blocks_;
  CoefficientBlock* filling_ = nullptr;  // during a build: this space's block being filled, blocks_[filling_block_]
  int filling_block_ = -1;
  std::vector<int> block_map_;           // during a build from a previous space: its block b is blocks_[block_map_[b]]
  std::vector<int> dof_level_;
  std::vector<Key> dof_function_;
  std::vector<Index> dof_home_;   // element
  std::vector<int> dof_home_local_;  // local index of the function among the home leaf's level functions
  std::vector<std::unordered_map<Key, Index, KeyHash>> leaf_index_;  // per level: cell -> element
  Index max_local_ = 0;
  int num_levels_ = 1;
  std::uint64_t serial_ = 0;           // distinct for every space built in the process
  std::uint64_t previous_serial_ = 0;  // the space this one was built from (0: none)
  std::vector<Index> copied_from_;     // per element: the previous space's element it copies, or -1
};

}  // namespace iga::basis::hierarchical
