#include "fem/solver.hpp"

#include <Eigen/CholmodSupport>
#include <Eigen/IterativeLinearSolvers>
#include <chrono>
#include <cmath>
#include <iomanip>
#include <sstream>

#include "core/error.hpp"
#include "fem/threads.hpp"

namespace iga::fem {

namespace {

// The fill-reducing ordering. CHOLMOD's default tries AMD and then METIS as well whenever AMD's fill is high, so
// large problems pay for both; METIS's nested dissection costs about 2e-7 s per non-zero of A on this 2-core machine
// (0.6 s for the 3.2e6 of a bicubic problem at 67k dofs: 25 % of the whole run, perf) and saves about 60 % of
// AMD's flops on 2D problems, which the factorisation runs at about 3e10 flop/s. So: AMD, and METIS only when
// AMD's flop count exceeds 1e4 × nnz(A), where the saving outweighs METIS's own time. Measured solve seconds
// (AMD / METIS / CHOLMOD's default, one thread): bicubic 67k dofs 0.85 / 1.45 / 1.62, 265k 8.1 / 6.8 / 7.6;
// quintic 68k 1.68 / 2.82; biquadratic 264k 1.5 / 3.7; Catmull–Clark square_evs 148k 2.5 / 3.4.
template <class Llt>
std::string analyse(const Eigen::SparseMatrix<double>& a, Llt& llt) {
  llt.cholmod().nmethods = 1;
  llt.cholmod().method[0].ordering = CHOLMOD_AMD;
  llt.analyzePattern(a);
  if (llt.cholmod().fl <= 1e4 * static_cast<double>(a.nonZeros())) return "amd";
  llt.cholmod().method[0].ordering = CHOLMOD_METIS;
  llt.analyzePattern(a);
  return "metis";
}

}  // namespace

SolveResult solve(const Eigen::SparseMatrix<double>& a, const Eigen::VectorXd& b, const SolverOptions& options) {
  if (uses_petsc(options.kind)) {
    throw InputError("the petsc and mg solvers solve an assembled LinearSystem (fem::make_linear_system), not an Eigen matrix");
  }
  const auto t0 = std::chrono::steady_clock::now();
  SolveResult r;
  if (a.rows() == 0) {
    r.x.resize(0);
    r.solver = options.kind == SolverKind::Cholmod ? "cholmod-supernodal-llt" : "cg-ichol";
    return r;
  }
  if (!b.allFinite()) throw NumericalError("the right-hand side of the linear system is not finite");
  if (!Eigen::Map<const Eigen::VectorXd>(a.valuePtr(), a.nonZeros()).allFinite()) {
    throw NumericalError("the system matrix is not finite (a degenerate or overflowing geometry?)");
  }
  if (options.kind == SolverKind::Cholmod) {
    r.solver = "cholmod-supernodal-llt";
    Eigen::CholmodSupernodalLLT<Eigen::SparseMatrix<double>, Eigen::Lower> llt;
    llt.cholmod().print = 0;  // failures are reported below in one line, not by CHOLMOD's own warning
    // CHOLMOD's supernodal parallel regions ask for 4 threads: held to --threads.
    within_thread_limit([&] { r.ordering = analyse(a, llt); });
    within_thread_limit([&] { llt.factorize(a); });
    if (llt.cholmod().status == CHOLMOD_OUT_OF_MEMORY) {
      throw NumericalError("CHOLMOD: out of memory factorising the system matrix (" + std::to_string(a.rows()) +
                           " unknowns, " + std::to_string(a.nonZeros()) + " non-zeros); try --solver cg");
    }
    if (llt.info() != Eigen::Success) {
      throw NumericalError("CHOLMOD: the system matrix (" + std::to_string(a.rows()) +
                           " unknowns) is not positive definite; is the problem well posed?");
    }
    within_thread_limit([&] { r.x = llt.solve(b); });
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
  // Scaled norms (stableNorm): a system of entries near 1e200 (--reaction 1e200) has a finite residual whose plain
  // norm overflows, and the ratio was NaN.
  const double bn = b.stableNorm();
  r.residual_norm = (a * r.x - b).stableNorm() / (bn > 0 ? bn : 1.0);
  if (!r.x.allFinite()) throw NumericalError(r.solver + ": the solution is not finite");
  if (!std::isfinite(r.residual_norm)) {
    throw NumericalError(r.solver + ": the residual of the solution is not finite (" + std::to_string(a.rows()) +
                         " unknowns): the system's entries overflow a double; scale the data (coefficients, source)");
  }
  if (!(r.residual_norm <= options.max_residual)) {
    std::ostringstream msg;
    msg << std::setprecision(3) << r.solver << ": relative residual " << r.residual_norm << " of the solution is above "
        << options.max_residual << " (" << a.rows() << " unknowns): the system is too ill-conditioned to trust the result";
    throw NumericalError(msg.str());
  }
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return r;
}

SolverKind parse_solver(const std::string& name) {
  if (name == "cholmod") return SolverKind::Cholmod;
  if (name == "cg") return SolverKind::ConjugateGradient;
  if (name == "petsc") return SolverKind::Petsc;
  if (name == "mg") return SolverKind::Multigrid;
  throw InputError("solver '" + name + "': unknown (known: cholmod, cg, petsc, mg)");
}

}  // namespace iga::fem
