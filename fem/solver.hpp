#pragma once
// Sparse symmetric positive definite solves: CHOLMOD (supernodal Cholesky, through Eigen), Eigen's conjugate
// gradient with an incomplete Cholesky preconditioner, or a PETSc KSP on a distributed system — algebraic
// multigrid (GAMG) by default, or geometric multigrid (PCMG) on the nested spaces of uniform refinement
// (fem/linear_system.hpp, the one interface the Poisson pipeline uses for all of them).
#include <Eigen/Sparse>
#include <memory>
#include <string>
#include <vector>

#include "core/types.hpp"

namespace iga::fem {

/// Multigrid: PETSc's CG preconditioned by PCMG, its levels the nested spaces of SolverOptions::hierarchy (a
/// PETSc system, as Petsc).
enum class SolverKind { Cholmod, ConjugateGradient, Petsc, Multigrid };

/// The solvers that run on a PETSc system (they need an open fem::ParallelSession).
inline bool uses_petsc(SolverKind kind) { return kind == SolverKind::Petsc || kind == SolverKind::Multigrid; }

/// How a distributed run parted its elements (fem/partition.hpp), for its report.
struct PartitionFacts {
  std::string method;         ///< "curve", "ptscotch" or "metis" (empty: not distributed)
  double seconds = 0.0;       ///< the partition's wall time, the slowest rank's
  Index interface_dofs = 0;   ///< dofs touched by elements of more than one rank: the cut
};

struct SolverOptions {
  SolverKind kind = SolverKind::Cholmod;
  double tolerance = 1e-12;   ///< CG and PETSc's KSP: relative residual (unpreconditioned norm)
  Index max_iterations = 0;   ///< CG and KSP: 0 = 10 × size
  /// PETSc: options in PETSc's own syntax ("-ksp_type cg -pc_type hypre"), inserted before the KSP reads its
  /// options, so they override the defaults (CG + GAMG) as do those of the PETSC_OPTIONS environment.
  std::string petsc_options;
  /// PETSc: how the elements are parted among the ranks (fem::parse_partition: "curve", "ptscotch" or "metis").
  std::string partition = "curve";
  /// Any solver: a solution whose relative residual ||A x - b|| / ||b|| is above this is refused
  /// (NumericalError with the residual), never returned as if it were the answer.
  double max_residual = 1e-6;
  /// Multigrid: the prolongations between the nested spaces, coarsest first (basis::Refinement::steps): the
  /// last maps onto the assembled space. The field's components (Assembler::components) use each one per
  /// component. Empty: one level, the coarse solve alone.
  std::shared_ptr<const std::vector<Eigen::SparseMatrix<double>>> hierarchy;
  /// PETSc solvers: the iteration starts from this solution (coefficients of every dof of the field; its free
  /// ones are used), e.g. the previous adaptive step's prolongated. Null: from zero. The other solvers ignore it.
  std::shared_ptr<const Eigen::VectorXd> initial_guess;
};

/// What a multigrid solve ran, for its report.
struct MultigridFacts {
  int levels = 0;             ///< the levels of the hierarchy, the finest included (0: no multigrid)
  std::string smoother;       ///< the finest level's, "chebyshev+jacobi x2": KSP + PC and steps per smoothing
  std::string coarse_solver;  ///< the coarsest level's KSP + PC ("preonly+lu")
};

struct SolveResult {
  Eigen::VectorXd x;
  std::string solver;          ///< "cholmod-supernodal-llt", "cg-ichol" or "petsc-<ksp>-<pc>"
  std::string ordering;        ///< the direct solver's fill-reducing ordering: "amd" or "metis" (empty for CG)
  double residual_norm = 0.0;  ///< ||A x - b|| / ||b|| (absolute when b = 0)
  Index iterations = 0;        ///< CG or KSP iterations (0 for the direct solver)
  MultigridFacts multigrid;    ///< what a multigrid ran (levels 0 for the other solvers)
  double seconds = 0.0;        ///< conditions applied + factorisation + solve (PETSc: the maximum over ranks)
  Index free_dofs = 0;         ///< the reduced system's size (set by LinearSystem::solve)
  int ranks = 1;               ///< processes that held the system
  std::vector<Index> elements_per_rank, dofs_per_rank;  ///< owned elements and dofs of each rank (PETSc)
  std::vector<int> element_owner;  ///< per element, the rank that assembled it (PETSc)
  PartitionFacts partition;        ///< how the elements were parted (PETSc on more than one rank)
};

/// Solves A x = b for symmetric positive definite A (both triangles stored). NumericalError when the
/// matrix or right-hand side is not finite, the matrix is not positive definite, CG does not converge, or
/// the solution is not finite or has a relative residual above options.max_residual. Kind Petsc: InputError (a
/// PETSc solve goes through make_linear_system, fem/linear_system.hpp).
SolveResult solve(const Eigen::SparseMatrix<double>& a, const Eigen::VectorXd& b, const SolverOptions& options);

/// "cholmod", "cg", "petsc" or "mg"; InputError otherwise.
SolverKind parse_solver(const std::string& name);

}  // namespace iga::fem
