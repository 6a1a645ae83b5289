#pragma once
// The nested spaces V^0 ⊂ V^1 ⊂ ... of one refinement scheme, described cell by cell: what a hierarchical
// (THB) space needs of a scheme (thesis Appendix A; §4.2.5 for subdivision splines). Level l has cells (the
// elements of V^l) and functions (its basis); every cell of level l has four children of level l+1 that tile
// it; the functions of level l are combinations of those of level l+1 (two-scale relation), given cell by
// cell. Tensor-product B-splines on dyadically refined knots implement it in basis/thb; the hierarchical space
// itself (hierarchical_space.hpp) only talks to this interface.
#include <Eigen/Core>
#include <algorithm>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "basis/basis_values.hpp"
#include "basis/element_kind.hpp"
#include "core/types.hpp"

namespace iga::basis::hierarchical {

/// A cell or function within its level. 128 bits: level 40 of a 16 × 16 patch has 2^88 cells, and the corner
/// singularity of an L-shape needs some 30 levels for 1e6 dofs at degree 2 (about 45 at degree 3).
__extension__ typedef __int128 Key;
struct KeyHash {
  std::size_t operator()(Key k) const {
    const auto lo = static_cast<unsigned long long>(k), hi = static_cast<unsigned long long>(k >> 64);
    return std::hash<unsigned long long>()(lo ^ (hi * 0x9E3779B97F4A7C15ULL + (lo << 6) + (lo >> 2)));
  }
};
/// Decimal form of a key, for messages.
std::string to_string(Key k);

class LevelHierarchy {
 public:
  virtual ~LevelHierarchy() = default;

  /// Space::name() of the hierarchical spaces built on it (the backend's name).
  virtual std::string name() const = 0;
  /// The deepest level the scheme can index (cells and functions of deeper levels would overflow Key, or knots would round together).
  virtual int max_level() const = 0;
  /// Why max_level() is the deepest, completing "the N levels the '<name>' hierarchy ..." in messages.
  virtual std::string depth_limit() const { return "can index (and resolve in double precision)"; }
  /// Whether level l is ready without a build. Hierarchies that build a whole level on first use (Catmull–Clark: a
  /// level has 4^l times the elements of level 0) say false for the levels not built yet, so that the adaptive
  /// loop's time forecast (io::StepForecast) can count the build in the step that needs it.
  virtual bool level_built(int level) const {
    (void)level;
    return true;
  }
  /// Cells of level 0, numbered 0..num_root_cells()-1 (deeper levels are never enumerated).
  virtual Index num_root_cells() const = 0;
  /// Cell c of level l + 1 in slot 0..3 of cell `cell` of level l. Child slot k covers the reference
  /// sub-square child_map() gives.
  virtual Key child(int level, Key cell, int slot) const = 0;
  /// Parent (level - 1) of a cell of level >= 1, and the slot the cell has in it.
  virtual Key parent(int level, Key cell, int& slot) const = 0;
  /// The affine map from the reference square of the child in `slot` of cell `cell` of level `level` to the
  /// cell's reference square: x_parent = a x + b. It may depend on the cell, not only on the slot: schemes whose
  /// elements are rotated (Catmull–Clark: corner 0 is the extraordinary vertex) give a child a frame rotated
  /// against its parent's.
  virtual void child_map(int level, Key cell, int slot, Eigen::Matrix2d& a, Eigen::Vector2d& b) const = 0;

  /// The level's functions that are non-zero on the cell, in the local order of evaluate() (at most
  /// max_local_functions()); returns their number.
  virtual int local_functions(int level, Key cell, Key* out) const = 0;
  virtual int max_local_functions() const = 0;
  /// The cells of the level on which the function is non-zero (its support), in any order.
  virtual void support(int level, Key function, std::vector<Key>& cells) const = 0;
  /// The support extension of a cell: the cells of the level on which some function non-zero on the cell is
  /// non-zero (the union of their supports), in any order, each once. Incremental builds of hierarchical spaces
  /// rest on it, and on its nesting: the support extension of a child lies in the children of the cells of its
  /// parent's (true of dyadic B-splines of any degree and of Catmull–Clark, checked by
  /// tests/basis/test_hierarchical_incremental).
  virtual void support_extension(int level, Key cell, std::vector<Key>& cells) const {
    std::vector<Key> functions(static_cast<std::size_t>(max_local_functions())), one;
    functions.resize(static_cast<std::size_t>(local_functions(level, cell, functions.data())));
    cells.clear();
    for (Key f : functions) {
      support(level, f, one);
      cells.insert(cells.end(), one.begin(), one.end());
    }
    std::sort(cells.begin(), cells.end());
    cells.erase(std::unique(cells.begin(), cells.end()), cells.end());
  }
  /// Two-scale relation on one child: parent-local function i restricted to the child in `slot` equals
  /// Σ_j k(i, j) × child-local function j (k: parent local × child local).
  virtual void refinement(int level, Key cell, int slot, Eigen::MatrixXd& k) const = 0;
  /// The level's local functions on the cell at reference points (unit square), with parametric
  /// derivatives up to `derivatives` (BasisValues conventions).
  virtual void evaluate(int level, Key cell, const Eigen::Matrix2Xd& pts, int derivatives,
                        BasisValues& out) const = 0;
  virtual ElementKind kind(int, Key) const { return {}; }
  /// Space::polynomial_degree of the cell's functions (std::nullopt: infinitely piecewise or unknown).
  virtual std::optional<int> polynomial_degree(int, Key) const { return std::nullopt; }

  /// Boundary: the part of side `side` of the cell (side numbering as basis::side_point on the square), or
  /// -1 when the side is interior.
  virtual int boundary_part(int level, Key cell, int side) const = 0;
  virtual std::vector<std::string> boundary_part_names() const = 0;
  /// The cell of the same level across an interior side, and its side there (the shared side runs the other
  /// way on it).
  virtual Key neighbour(int level, Key cell, int side, int& their_side) const = 0;
  /// Smoothness of the level's functions across an interior side (0: only C0).
  virtual int continuity(int level, Key cell, int side) const = 0;
};

}  // namespace iga::basis::hierarchical
