#pragma once
// Exact evaluation of a Catmull–Clark face at an extraordinary vertex (interior or boundary) by repeated
// local subdivision with cached matrix powers.
//
// The face's local points are its unfolded one-ring L0 (corner c0 = the EV). One symbolic Catmull–Clark
// step of L0 gives the four sub-faces; the three away from the EV are regular bicubic tiles (phantom points
// where they reach the boundary), the one at the EV has the one-ring L1 = A0 L0. From level 1 on the
// configuration repeats: L_{l+1} = A L_l with one matrix A per configuration (EV valence, interior or
// boundary, and the position of the face in the EV's fan). A point with max(u, v) in [2^-(l+1), 2^-l) lies
// in tile k of level l (k = 1: u >= h > v, 2: u, v >= h, 3: v >= h > u, h = 2^-(l+1)) and is evaluated as
// the bicubic patch on E_k A^(l-1) A0 L0 (E0_k L0 for l = 0). The products E_k A^j are cached for
// j < kLevels; points with max(u, v) < 2^-(kLevels+1), and the EV itself, get the limit-point stencil as
// values and zero derivatives (the parametric derivative at an EV is 0 or unbounded).
#include <Eigen/Core>
#include <array>
#include <memory>
#include <vector>

#include "basis/basis_values.hpp"
#include "basis/catmull_clark/quad_mesh.hpp"
#include "basis/subdivision_view.hpp"

namespace iga::basis::catmull_clark {

inline constexpr int kLevels = 64;

/// The repeating part: one per configuration of the level-1 one-ring (shared between elements).
struct IrregularConfig {
  Eigen::MatrixXd subdivision;                            ///< A (m × m)
  std::vector<std::array<Eigen::MatrixXd, 3>> tile_ops;  ///< [j][k-1] = E_k A^j (16 × m), j < kLevels
  /// [j][k-1] = E_k B^j with B = A - 1 w^T (the constant mode removed exactly): derivatives use these, so
  /// that their rounding error decays like λ^j instead of growing like 2^j (Σ ∇φ = 0 to rounding at depth).
  std::vector<std::array<Eigen::MatrixXd, 3>> tile_ops_deriv;
  Eigen::VectorXd limit;  ///< limit-point stencil w of the EV on L1 (m): w^T A = w^T, Σ w = 1
  SubdivisionView view;   ///< the same for exact integration (exact_view.hpp): A, w, E_k = tile_ops[0]
};

/// Cached by the combinatorics of the level-1 one-ring; thread-safe.
std::shared_ptr<const IrregularConfig> irregular_config(const QuadMesh& level1);

/// One element at an EV, with the operators already multiplied by the element's map from its dofs to L0.
struct IrregularElement {
  std::array<Eigen::MatrixXd, 3> level0;  ///< tile k of level 0: 16 × dofs
  Eigen::MatrixXd level1;                 ///< A0 G: m × dofs
  Eigen::MatrixXd level1_deriv;           ///< (A0 - 1 w^T A0) G: the same without the constant mode
  Eigen::VectorXd limit;                  ///< limit stencil in the dofs
  std::shared_ptr<const IrregularConfig> config;
};

/// ring = unfold_one_ring(net, face, rotation) with the EV at corner 0; to_dofs (|L0| × dofs) maps the
/// element's dof coefficients to the ring's points.
IrregularElement make_irregular_element(const OneRing& ring, const Eigen::MatrixXd& to_dofs);

/// Values and derivatives (dofs × points) at pts, batched by level and tile.
void evaluate_irregular(const IrregularElement& el, const Eigen::Matrix2Xd& pts, int derivatives,
                        BasisValues& out);

}  // namespace iga::basis::catmull_clark
