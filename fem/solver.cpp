#include "fem/solver.hpp"

#include <Eigen/CholmodSupport>
#include <Eigen/IterativeLinearSolvers>
#include <chrono>

#include "core/error.hpp"

namespace iga::fem {

SolveResult solve(const Eigen::SparseMatrix<double>& a, const Eigen::VectorXd& b, const SolverOptions& options) {
  const auto t0 = std::chrono::steady_clock::now();
  SolveResult r;
  if (a.rows() == 0) {
    r.x.resize(0);
    r.solver = options.kind == SolverKind::Cholmod ? "cholmod-supernodal-llt" : "cg-ichol";
    return r;
  }
  if (options.kind == SolverKind::Cholmod) {
    r.solver = "cholmod-supernodal-llt";
    Eigen::CholmodSupernodalLLT<Eigen::SparseMatrix<double>, Eigen::Lower> llt;
    llt.compute(a);
    if (llt.info() != Eigen::Success) {
      throw NumericalError("CHOLMOD: the system matrix (" + std::to_string(a.rows()) +
                           " unknowns) is not positive definite; is the problem well posed?");
    }
    r.x = llt.solve(b);
    if (llt.info() != Eigen::Success) throw NumericalError("CHOLMOD: the solve failed");
  } else {
    r.solver = "cg-ichol";
    Eigen::ConjugateGradient<Eigen::SparseMatrix<double>, Eigen::Lower | Eigen::Upper,
                             Eigen::IncompleteCholesky<double>>
        cg;
    cg.setTolerance(options.tolerance);
    cg.setMaxIterations(options.max_iterations > 0 ? options.max_iterations : 10 * a.rows());
    cg.compute(a);
    if (cg.info() != Eigen::Success) throw NumericalError("CG: the incomplete Cholesky preconditioner failed");
    r.x = cg.solve(b);
    r.iterations = cg.iterations();
    if (cg.info() != Eigen::Success) {
      throw NumericalError("CG did not converge in " + std::to_string(cg.iterations()) + " iterations (residual " +
                           std::to_string(cg.error()) + ")");
    }
  }
  const double bn = b.norm();
  r.residual_norm = (a * r.x - b).norm() / (bn > 0 ? bn : 1.0);
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return r;
}

SolverKind parse_solver(const std::string& name) {
  if (name == "cholmod") return SolverKind::Cholmod;
  if (name == "cg") return SolverKind::ConjugateGradient;
  throw InputError("solver '" + name + "': unknown (known: cholmod, cg)");
}

}  // namespace iga::fem
