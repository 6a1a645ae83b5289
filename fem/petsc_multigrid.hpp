#pragma once
// Geometric multigrid through PETSc's PCMG (SolverKind::Multigrid): the levels of fem/multigrid.hpp as PETSc
// interpolation matrices, Galerkin coarse operators (PᵀAP, PETSc's MatPtAP), a smoother on every level and a
// direct solve on the coarsest. Internal to fem/ (compiled against PETSc).
#include <petscksp.h>

#include "fem/multigrid.hpp"
#include "fem/solver.hpp"

namespace iga::fem::petsc {

/// Makes pc a PCMG with one level per space of options.hierarchy (plus the finest), the finest level's free dofs
/// and their layout given by `finest` (the reduced system's). Defaults, before the options database is read (the
/// "-mg_levels_" and "-mg_coarse_" options override them; README, "Multigrid"): V-cycles, Chebyshev smoothing
/// preconditioned by point Jacobi, 2 steps before and after, LU (redundant on every rank when distributed) on the
/// coarsest level.
void set_multigrid(PC pc, MPI_Comm comm, const SolverOptions& options, int components, const MultigridLevel& finest);

/// What the solve ran, after KSPSolve (the options may have replaced the defaults): levels, smoother and coarse
/// solver into s.
void describe_multigrid(PC pc, SolveResult& s);

}  // namespace iga::fem::petsc
