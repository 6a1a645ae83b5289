#pragma once
// Residual-based a posteriori error estimator for -Δu + c u = f (thesis §4.1.6; Verfürth's residual estimator):
//   η_K² = h_K² ‖f + Δu_h − c u_h‖²_K + ½ Σ_{E ⊂ ∂K interior, C0} h_E ‖[∂u_h/∂n]‖²_E
//          + Σ_{E ⊂ ∂K ∩ Γ_N} h_E ‖g_N − ∂u_h/∂n‖²_E,
// with h_K = |K|^½ (the element's area, or surface area) and h_E the physical length of E. Jumps are taken only
// across interior edges where the space is C0 (Space::interior_edges, continuity 0): across smoother edges the
// normal flux of u_h is continuous. On surfaces Δ is the Laplace–Beltrami operator.
#include <Eigen/Core>

#include "fem/poisson.hpp"

namespace iga::fem {

struct Estimate {
  Eigen::VectorXd indicators;  ///< η_K per element
  double total = 0.0;          ///< η = (Σ η_K²)^½
  double residual = 0.0;       ///< (Σ h_K² ‖R_K‖²)^½: the element-residual part of η
  double jump = 0.0;           ///< the jump part (½ per side, summed over both)
  double neumann = 0.0;        ///< the Neumann-residual part
  Index jump_edges = 0;        ///< interior C0 edge pieces that contributed
  double seconds = 0.0;
};

/// The estimator for the solver's solution (solve() must have run). Element residuals are parallel and
/// deterministic; edges are summed serially in Space::interior_edges() order.
Estimate estimate_residual(const PoissonSolver& solver);

}  // namespace iga::fem
