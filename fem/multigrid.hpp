#pragma once
// The levels of geometric multigrid on the nested spaces of uniform refinement (SolverKind::Multigrid), without
// PETSc: which dofs of each level are free, which process holds each, and the prolongations between the free
// dofs. fem/petsc_multigrid.cpp hands them to PETSc's PCMG.
#include <Eigen/Sparse>
#include <vector>

#include "core/types.hpp"

namespace iga::fem {

/// One level's free dofs in the numbering of its reduced system. The finest level's system may keep rows for its
/// constrained dofs (rows of the identity, which no free dof couples to: fem/petsc_system.cpp with selected
/// conditions); then those rows have no dof here and the level's size is that of the whole system.
struct MultigridLevel {
  /// Per field dof (components × the space's dofs, interleaved: d·i + c): its row in the level's system (on the
  /// coarse levels: its index among the level's free dofs), −1 for a constrained one.
  std::vector<Index> reduced;
  /// ranks + 1 entries: rank r holds the rows [offsets[r], offsets[r + 1]) of the level's system.
  std::vector<Index> offsets;
  /// The level's homogeneous constraints u_k + Σ_i coupling(k, i) u_i = 0 of the constrained field dofs k =
  /// constrained[row] (DirichletConditions: coupled ones; an empty coupling: the constrained dofs are zero).
  std::vector<Index> constrained;
  Eigen::SparseMatrix<double, Eigen::RowMajor> coupling;
  Index size() const { return offsets.back(); }  ///< the rows of the level's system
  int owner(Index reduced_index) const;  ///< the rank holding a reduced index
};

/// Every level, coarsest first, from the finest one (the assembled system's free dofs and their ranks) down
/// through `hierarchy` (basis::Refinement::steps: hierarchy[k] maps the dofs of level k to those of level k + 1).
/// A coarse dof (of component c) is free when its function, prolongated, satisfies the level above's homogeneous
/// constraints (to 1e-10 of its largest coefficient): then it lies in that level's constrained space, and its free
/// coefficients represent it exactly. For spaces whose constrained dofs are those with a non-zero trace
/// (B-splines, NURBS) these are exactly the coarse functions with a zero trace; with coupled constraints
/// (Catmull–Clark, half-box) the coarse functions near the boundary whose combinations alone satisfy them are left
/// out (a smaller coarse space near the boundary, never a wrong one). A coarse dof whose column is empty is left
/// out too. The coarse levels' constraints are selections (their left-out dofs are zero). A free coarse
/// dof goes to the rank holding its largest fine coefficient (the lowest fine index on a tie), and each rank's
/// dofs are numbered consecutively in ascending dof order. InputError when the hierarchy's sizes do not chain up
/// to the finest level's.
std::vector<MultigridLevel> multigrid_levels(const std::vector<Eigen::SparseMatrix<double>>& hierarchy, int components,
                                             MultigridLevel finest);

/// The prolongation between two levels' free dofs: p ⊗ I_components (field dof d·j + c to d·i + c), rows the fine
/// level's reduced indices, columns the coarse level's.
Eigen::SparseMatrix<double, Eigen::RowMajor> reduced_prolongation(const Eigen::SparseMatrix<double>& p, int components,
                                                                  const MultigridLevel& coarse, const MultigridLevel& fine);

}  // namespace iga::fem
