#pragma once
// Stam's exact evaluation of the Catmull–Clark basis functions on a quad with one interior extraordinary
// vertex (thesis §3.2.2, (3.46)–(3.48); Stam 1998).
#include <Eigen/Core>

#include "basis/basis_values.hpp"

namespace iga::basis::catmull_clark {

/// The element is a quad c0 c1 c2 c3 (counter-clockwise) whose corner c0 is an interior extraordinary vertex
/// (EV) of valence n and whose other corners are regular interior vertices. Reference coordinates
/// (u, v) in [0,1]^2: u runs along c0 -> c1, v along c0 -> c3, the EV is at (0,0).
///
/// The 2n+8 local control points (rows of every block of evaluate()), named by their grid coordinates (i, j)
/// (exact for n = 4, where the element is [0,1]^2 of the 4×4 net):
///   0: the EV (0,0);
///   2k+1, k = 0..n-1: the k-th edge neighbour of the EV counter-clockwise (1 = c1 = (1,0), 3 = c3 = (0,1),
///        2n-1 = (0,-1));
///   2k+2, k = 0..n-1: the vertex opposite the EV in the quad between edges k and k+1 (2 = c2 = (1,1),
///        2n = (1,-1));
///   2n+1 .. 2n+7: (2,-1), (2,0), (2,1), (2,2), (1,2), (0,2), (-1,2).
///
/// Tiles (Stam's Ω_{k,l}): level l >= 1 is the L-shaped layer 2^-l <= max(u,v) < 2^(1-l) (level 1 also holds
/// max(u,v) = 1), so l = floor(-log2 max(u,v)) + 1, computed exactly from the binary exponent. In the layer,
/// with U = 2^l u, V = 2^l v (exact):
///   tile 1: U >= 1, V < 1   (u in [2^-l, 2^(1-l)], v in [0, 2^-l));      local (s, t) = (U - 1, V)
///   tile 2: U >= 1, V >= 1  (both in [2^-l, 2^(1-l)]);                   local (s, t) = (U - 1, V - 1)
///   tile 3: U < 1,  V >= 1  (u in [0, 2^-l), v in [2^-l, 2^(1-l)]);      local (s, t) = (U, V - 1)
/// A point on a boundary between tiles belongs to the tile on the side of larger u or v: max(u,v) = 2^-l lies
/// in layer l, and U = 1 or V = 1 (with the other >= 1) in tile 2. The basis is C2 across these boundaries, so
/// the choice only decides which formula is used. Points with max(u,v) < 2^-60 are treated as the EV itself.
///
/// Immutable after construction and thread-safe.
class StamEvaluator {
 public:
  /// Deepest level with its own tile formula; max(u,v) < 2^-kMaxLevel is the EV.
  static constexpr int kMaxLevel = 60;
  /// Levels 1..kCachedLevels use precomputed (tile, level) matrices (one 16×(2n+8) product per point and
  /// block); deeper levels apply Λ^(l-1) V^{-1} per point (costs O((2n+8)^2) per point and block).
  static constexpr int kCachedLevels = 24;

  /// Where a point lies: level 1..kMaxLevel and tile 1..3, or level 0 (tile 0) for the EV.
  struct Tile {
    int level = 0;
    int tile = 0;
  };

  /// InputError unless 3 <= valence <= 16.
  explicit StamEvaluator(int valence);

  int valence() const { return n_; }
  int num_points() const { return 2 * n_ + 8; }

  /// The tile of (u, v) in [0,1]^2 by the rule above.
  static Tile locate(double u, double v);

  /// Values and parametric derivatives (d/du, d/dv; with derivatives >= 2 also d2/du2, d2/dudv, d2/dv2) of
  /// the 2n+8 functions at pts (2 × q, each column in [0,1]^2, else InputError), rows in the local ordering,
  /// derivatives with respect to the reference (u, v). derivatives must be 0, 1 or 2 (InputError).
  /// On tile (k, l): (3.47) phi = M44(t_{k,l}(u,v))^T X^k Ā V Λ^{l-1} V^{-1}, first derivatives times 2^l,
  /// second derivatives times 4^l; derivatives are taken from the differenced tile nets (lower-degree
  /// B-splines), and mode contributions whose differenced net vanishes (relative 1e-12: the constant mode, and
  /// for n = 4 the linear modes in second derivatives) are dropped exactly, which keeps derivatives accurate
  /// at deep levels.
  /// At the EV (max(u,v) < 2^-60):
  ///   n = 4: the bicubic B-spline of the 4×4 net and its derivatives at (u, v), exactly;
  ///   n != 4: values = limit_stencil(); du, dv = rows 1, 2 of V^{-1}, the duals of the subdominant
  ///     eigenvectors (Stam's tangent stencils, ∝ sum_k [A_n cos(2πk/n) e_k + (cos(2πk/n) + cos(2π(k+1)/n))
  ///     f_k] and its sine version) normalised as d/du, d/dv are for n = 4 (applied to the characteristic
  ///     net V(:,1), V(:,2) they give (1, 0) and (0, 1)); the true parametric derivatives vanish (n = 3) or
  ///     are unbounded (n >= 5) there, these give the tangent plane. Second derivatives are 0.
  /// Allocation-free when the blocks of out already have the sizes (2n+8) × q.
  void evaluate(const Eigen::Matrix2Xd& pts, int derivatives, BasisValues& out) const;

  /// The limit-point stencil (n² EV + 4 sum e_k + sum f_k) / (n (n + 5)); entries beyond the one-ring are 0.
  const Eigen::VectorXd& limit_stencil() const { return limit_; }

  /// The (2n+8)×(2n+8) subdivision matrix A in the local ordering.
  const Eigen::MatrixXd& subdivision_matrix() const { return a_; }
  /// Eigenvalues of A, sorted descending (0: 1; 1, 2: the subdominant pair, see eigen_structure.hpp).
  const Eigen::VectorXd& eigenvalues() const { return lambda_; }
  /// V with A = V diag(lambda) V^{-1} (real); conventions in eigen_structure.hpp.
  const Eigen::MatrixXd& eigenvectors() const { return v_; }
  /// V^{-1}.
  const Eigen::MatrixXd& inverse_eigenvectors() const { return v_inv_; }
  /// The (2n+17)×(2n+8) extended subdivision matrix Ā (ordering in subdivision_matrix.hpp).
  const Eigen::MatrixXd& extended_subdivision_matrix() const { return a_bar_; }
  /// The 16×(2n+17) picking matrix X^k of tile k = 1, 2, 3: row a + 4b picks the level-1 grid point
  /// (i0 + a, j0 + b) with (i0, j0) = (0,-1), (0,0), (-1,0) for k = 1, 2, 3; the tile's patch is
  /// sum_{a,b} N_a(s) N_b(t) (X^k Ā A^{l-1} P)_{a+4b}, N_0..N_3 the uniform cubic B-splines on [0,1].
  const Eigen::MatrixXd& picking_matrix(int tile) const;

 private:
  template <int Cols>
  void apply(int tile, int level, int column, const Eigen::Matrix<double, Cols, 1>& basis, double scale,
             Eigen::Ref<Eigen::VectorXd> out) const;
  void evaluate_ev(double u, double v, int derivatives, BasisValues& out, Eigen::Index p) const;

  int n_ = 0;
  Eigen::MatrixXd a_, a_bar_, v_, v_inv_, v_inv_t_;
  Eigen::VectorXd lambda_, limit_;
  Eigen::MatrixXd picking_[3];
  // Per tile: the mode-space nets G_k = (D X^k Ā V)^T, (2n+8) × kNetColumns, for the value net and its
  // differenced nets (du, dv, duu, duv, dvv).
  Eigen::MatrixXd modes_[3];
  // Per (tile, level <= kCachedLevels): V^{-T} Λ^{l-1} G_k with the 2^l / 4^l derivative factors.
  Eigen::MatrixXd cached_;
};

/// The evaluator of valence n, built on first use (thread-safe) and kept for the program's lifetime.
/// InputError unless 3 <= valence <= 16.
const StamEvaluator& stam_evaluator(int valence);

}  // namespace iga::basis::catmull_clark
