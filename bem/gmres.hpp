#pragma once
// Restarted GMRES (Saad–Schultz) for the dense, non-symmetric collocation systems: Arnoldi with modified
// Gram–Schmidt, Givens rotations on the Hessenberg matrix, no preconditioner, x0 = 0.
#include <Eigen/Core>

namespace iga::bem {

struct GmresResult {
  Eigen::VectorXd x;
  int iterations = 0;          ///< matrix–vector products
  double residual = 0.0;       ///< final ‖b − A x‖ / ‖b‖ (recomputed, not the recurrence's)
  bool converged = false;
  /// σ_max / σ_min of the (m+1) × m Hessenberg matrix of the last Arnoldi cycle: the 2-norm condition of A
  /// restricted to the last Krylov space, a lower bound of κ₂(A) (usually close to it once the cycle is long).
  double condition_estimate = 0.0;
};

/// Stops when ‖b − A x‖ <= tolerance ‖b‖ or after max_iterations products.
GmresResult gmres(const Eigen::MatrixXd& a, const Eigen::VectorXd& b, double tolerance, int restart,
                  int max_iterations);

}  // namespace iga::bem
