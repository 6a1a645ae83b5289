#pragma once
// Restarted GMRES (Saad–Schultz) for the dense, non-symmetric collocation systems: Arnoldi with modified
// Gram–Schmidt, Givens rotations on the Hessenberg matrix, x0 = 0, right block-Jacobi preconditioning:
// A M⁻¹ y = b, x = M⁻¹ y with M the block diagonal of A on the given blocks (LU of each block; a singular
// block is left unpreconditioned). The residual that is tested is that of the original system,
// ‖b − A x‖ = ‖b − A M⁻¹ y‖.
#include <Eigen/Core>
#include <vector>

namespace iga::bem {

struct GmresResult {
  Eigen::VectorXd x;
  int iterations = 0;          ///< matrix–vector products
  double residual = 0.0;       ///< final ‖b − A x‖ / ‖b‖ (recomputed, not the recurrence's)
  bool converged = false;
  /// σ_max / σ_min of the (m+1) × m Hessenberg matrix of the last Arnoldi cycle: the 2-norm condition of the
  /// preconditioned A M⁻¹ restricted to the last Krylov space, a lower bound of κ₂(A M⁻¹).
  double condition_estimate = 0.0;
};

/// block_starts: first row of every diagonal block, ascending, starting at 0 (empty: no preconditioner).
/// Stops when ‖b − A x‖ <= tolerance ‖b‖ or after max_iterations products.
GmresResult gmres(const Eigen::MatrixXd& a, const Eigen::VectorXd& b, double tolerance, int restart,
                  int max_iterations, const std::vector<Eigen::Index>& block_starts = {});

}  // namespace iga::bem
