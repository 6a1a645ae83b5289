#pragma once
// Strong Dirichlet conditions: boundary data projected in L2 onto the functions that live on the boundary.
#include <Eigen/Sparse>
#include <span>
#include <vector>

#include "fem/assembler.hpp"

namespace iga::fem {

/// Prescribed values u(dofs[k]) = values(k), dofs ascending; or, when `coupling` is non-empty,
/// u(dofs[k]) = values(k) − Σ_j coupling(k, j) u(j) with coupling (dofs × num_dofs) zero on the dof columns.
struct DirichletConditions {
  std::vector<Index> dofs;
  Eigen::VectorXd values;
  Eigen::SparseMatrix<double, Eigen::RowMajor> coupling;
};

/// Largest ratio of the LDLᵀ pivots of the boundary mass matrix M_SS, scaled to unit diagonal, that
/// project_dirichlet accepts (independent traces measured at most 7.3e3, nearly dependent ones 9.4e7 and more).
inline constexpr double kMaxDirichletPivotRatio = 1e6;

/// The L2 projection of g onto the traces of the functions that are non-zero on `edges`, through their trace space
/// (basis::TraceSpace: which functions live on the edges, and a maximal independent set S of their restrictions).
/// When the restrictions are independent (B-splines, Catmull–Clark): M_SS g_S = (∫_Γ g φ_s)_S with
/// M_SS(i, j) = ∫_Γ φ_i φ_j, plain prescribed values. When they are not (a receding boundary, e.g. polyhedral
/// splines, where a boundary curve depends on two rows of control points): every other trace
/// φ_j|Γ = Σ_s A_sj φ_s|Γ (TraceSpace::dependent()), and the condition is the affine constraint u_S + A u_J = γ
/// with the same γ: the trace of u_h is the projection of g, and u_J stays free (so a function whose trace is in
/// the trace space, e.g. an affine solution, is kept exactly). Empty edges give empty conditions.
/// NumericalError when M_SS is singular or its pivot ratio exceeds kMaxDirichletPivotRatio (traces that are
/// independent only at ever smaller scales: the clamped Catmull–Clark boundary at a boundary EV).
DirichletConditions project_dirichlet(const Assembler& assembler, std::span<const basis::BoundaryEdge> edges,
                                      std::shared_ptr<const Function> g);

/// Conditions on one component: `scalar` (of the space's dofs, as project_dirichlet gives them on a scalar
/// assembler) as conditions on component c of a field of d interleaved components (dof d·i + c; coupling columns
/// mapped alike).
DirichletConditions component_conditions(const DirichletConditions& scalar, int c, int d);
/// Several sets of conditions (on different components or parts) as one, dofs ascending. InputError when two sets
/// constrain the same dof (one component prescribed twice where two parts meet: give that component one
/// condition over both parts).
DirichletConditions merge_conditions(const std::vector<DirichletConditions>& sets, Index num_dofs);

/// Homogeneous linear conditions R u = 0 (rows of R over num_dofs dofs; redundant rows allowed) as conditions
/// u_S = −coupling u with one dof of S per independent row: Gauss–Jordan elimination with partial pivoting over the
/// columns R touches, the dofs in `prefer` tried first as pivots (in that order), the others ascending; rows scaled to
/// unit largest entry, a pivot below `tolerance` of that makes its column free. The coupling is zero on S's columns.
/// Dense in the touched columns: for conditions along boundaries (a slope held on an edge), not whole domains.
DirichletConditions linear_conditions(const Eigen::SparseMatrix<double, Eigen::RowMajor>& r,
                                      const std::vector<Index>& prefer, double tolerance = 1e-10);

/// The system for the free dofs: A_ff u_f = b_f - A_fd g_d; with coupled conditions u = u0 + T w and
/// Tᵀ A T w = Tᵀ (b − A u0), T = identity on the free dofs and −coupling on the constrained ones.
struct ReducedSystem {
  Eigen::SparseMatrix<double> a;
  Eigen::VectorXd b;
  std::vector<Index> free;  ///< global index of each reduced unknown
  Eigen::SparseMatrix<double> t;  ///< num_dofs × free (coupled conditions only)
  Eigen::VectorXd u0;             ///< coupled conditions only
};
ReducedSystem eliminate(const Eigen::SparseMatrix<double>& a, const Eigen::VectorXd& b,
                        const DirichletConditions& bc);
/// The full vector from the free part and the conditions.
Eigen::VectorXd expand(const ReducedSystem& sys, const Eigen::VectorXd& u_free, const DirichletConditions& bc,
                       Index num_dofs);

}  // namespace iga::fem
