#pragma once
// The levels of THB splines on one tensor-product B-spline patch (thesis Appendix A): level l has the coarse
// knot vectors with every non-empty interval split into 2^l equal ones (multiplicities of the coarse knots
// kept, new knots simple), bi-degree (p, q) on every level. Knot vectors of deep levels are never stored: knots,
// spans and windows are computed from the coarse breakpoints, so level 20 of a 16-interval patch costs nothing
// until a cell of it is used.
#include <algorithm>
#include <cstdint>
#include <map>
#include <memory>
#include <mutex>
#include <vector>

#include "basis/bspline/knot_vector.hpp"
#include "basis/hierarchical/hierarchical_space.hpp"
#include "basis/hierarchical/level_hierarchy.hpp"

namespace iga::basis::thb {

/// One direction: the coarse knot vector's breakpoints b_0 < ... < b_K with multiplicities, at every level.
class DyadicKnots {
 public:
  explicit DyadicKnots(const bspline::KnotVector& coarse);

  int degree() const { return p_; }
  hierarchical::Key num_intervals(int level) const { return hierarchical::Key{k_} << level; }
  hierarchical::Key num_functions(int level) const { return p_ + num_intervals(level) + extra_.back(); }
  /// The span mu of interval i (t_mu <= x < t_mu+1): its functions are mu - p .. mu.
  hierarchical::Key span(int level, hierarchical::Key interval) const;
  /// Value and multiplicity of breakpoint j = 0..num_intervals(level) (the ends have multiplicity p + 1).
  double breakpoint(int level, hierarchical::Key j) const;
  int multiplicity(int level, hierarchical::Key j) const;
  /// The knots t_{mu-p} .. t_{mu+p+1} of interval i (2p + 2 values) into w.
  void window(int level, hierarchical::Key interval, double* w) const;
  /// First and last interval on which function f is non-zero.
  void support(int level, hierarchical::Key function, hierarchical::Key& first, hierarchical::Key& last) const;
  /// Two-scale relation of interval i and its child 2i + half: k(a, b) with parent-local function a on the child
  /// = Σ_b k(a, b) child-local function b (k = blossoms of the parent's functions at the child's knots).
  void refinement(int level, hierarchical::Key interval, int half, Eigen::MatrixXd& k) const;
  /// The deepest level: 2^-level of a coarse interval stays well above the rounding of its knots (level <= 44),
  /// and cells and functions fit 128-bit keys.
  int max_level() const;

 private:
  /// refinement() through the cache shared by all threads.
  void shared_refinement(int level, hierarchical::Key interval, int half, Eigen::MatrixXd& k) const;

  int p_ = 0;
  Index k_ = 0;                 // coarse intervals
  std::vector<double> b_;       // coarse breakpoints
  std::vector<int> mult_;       // their multiplicities (ends p + 1)
  std::vector<Index> extra_;    // extra_[c] = Σ_{c' = 1..min(c, K-1)} (mult_c' - 1), c = 0..K-1
  std::uint64_t id_ = 0;            // distinct per object, for the per-thread cache of recent relations
  mutable std::mutex cache_mutex_;  // two-scale relations by normalised knot windows
  mutable std::map<std::vector<long long>, Eigen::MatrixXd> cache_;
};

/// The B-spline levels of a patch as a LevelHierarchy: cell ix + nx(l) iy, function jx + nfx(l) jy, child
/// slot a + 2b = cell (2ix + a, 2iy + b) on the sub-square [a/2, (a+1)/2] × [b/2, (b+1)/2]. Level 0 is the
/// patch's TensorSpace: its cells and function indices are TensorSpace's element and dof indices (the
/// hierarchical space numbers its dofs in its own order; HierarchicalSpace::from_level0 maps coefficients).
/// Boundary parts as TensorSpace ("v0", "u1", "v1", "u0").
class DyadicBsplineLevels final : public hierarchical::LevelHierarchy {
 public:
  using Key = hierarchical::Key;
  DyadicBsplineLevels(const bspline::KnotVector& u, const bspline::KnotVector& v);

  std::string name() const override { return "bspline"; }
  int max_level() const override;
  Index num_root_cells() const override { return static_cast<Index>(u_.num_intervals(0) * v_.num_intervals(0)); }
  Key child(int level, Key cell, int slot) const override;
  Key parent(int level, Key cell, int& slot) const override;
  void child_map(int level, Key cell, int slot, Eigen::Matrix2d& a, Eigen::Vector2d& b) const override;
  int local_functions(int level, Key cell, Key* out) const override;
  int max_local_functions() const override { return (u_.degree() + 1) * (v_.degree() + 1); }
  std::optional<int> polynomial_degree(int, Key) const override { return std::max(u_.degree(), v_.degree()); }
  void support(int level, Key function, std::vector<Key>& cells) const override;
  void support_extension(int level, Key cell, std::vector<Key>& cells) const override;
  void refinement(int level, Key cell, int slot, Eigen::MatrixXd& k) const override;
  void evaluate(int level, Key cell, const Eigen::Matrix2Xd& pts, int derivatives, BasisValues& out) const override;
  int boundary_part(int level, Key cell, int side) const override;
  std::vector<std::string> boundary_part_names() const override { return {"v0", "u1", "v1", "u0"}; }
  Key neighbour(int level, Key cell, int side, int& their_side) const override;
  int continuity(int level, Key cell, int side) const override;

  const DyadicKnots& knots_u() const { return u_; }
  const DyadicKnots& knots_v() const { return v_; }
  /// Knot-parameter rectangle (u_a, u_b, v_a, v_b) of a cell.
  Eigen::Vector4d cell_box(int level, Key cell) const;

 private:
  DyadicKnots u_, v_;
};

/// The THB space of a tensor-product patch with nothing refined yet (its elements are the patch's, in order).
std::shared_ptr<const hierarchical::HierarchicalSpace> coarse_thb_space(const bspline::KnotVector& u,
                                                                       const bspline::KnotVector& v);

}  // namespace iga::basis::thb
