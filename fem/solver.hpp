#pragma once
// Sparse symmetric positive definite solves: CHOLMOD (supernodal Cholesky, through Eigen) or Eigen's
// conjugate gradient with an incomplete Cholesky preconditioner.
#include <Eigen/Sparse>
#include <string>

#include "core/types.hpp"

namespace iga::fem {

enum class SolverKind { Cholmod, ConjugateGradient };

struct SolverOptions {
  SolverKind kind = SolverKind::Cholmod;
  double tolerance = 1e-12;   ///< CG: relative residual
  Index max_iterations = 0;   ///< CG: 0 = 10 × size
  /// Any solver: a solution whose relative residual ||A x - b|| / ||b|| is above this is refused
  /// (NumericalError with the residual), never returned as if it were the answer.
  double max_residual = 1e-6;
};

struct SolveResult {
  Eigen::VectorXd x;
  std::string solver;          ///< "cholmod-supernodal-llt" or "cg-ichol"
  std::string ordering;        ///< the direct solver's fill-reducing ordering: "amd" or "metis" (empty for CG)
  double residual_norm = 0.0;  ///< ||A x - b|| / ||b|| (absolute when b = 0)
  Index iterations = 0;        ///< CG iterations (0 for the direct solver)
  double seconds = 0.0;        ///< factorisation + solve
};

/// Solves A x = b for symmetric positive definite A (both triangles stored). NumericalError when the
/// matrix or right-hand side is not finite, the matrix is not positive definite, CG does not converge, or
/// the solution is not finite or has a relative residual above options.max_residual.
SolveResult solve(const Eigen::SparseMatrix<double>& a, const Eigen::VectorXd& b, const SolverOptions& options);

/// "cholmod" or "cg"; InputError otherwise.
SolverKind parse_solver(const std::string& name);

}  // namespace iga::fem
