#pragma once
// The collocation BEM solve (thesis (4.49)): H u = G q with the known half of (u, q) moved to the right-hand
// side, Ax = b, x_j = q_j on Dirichlet dofs and u_j on Neumann dofs.
//
// Known coefficients: on each Dirichlet segment u_j by interpolation of problem.dirichlet at the segment's
// collocation points (a square, Schoenberg–Whitney system per segment); on each Neumann segment q_j likewise
// from problem.neumann(x, n) with the outward unit normal n. Data are evaluated at physical points (z = 0).
//
// Pure Neumann (no Dirichlet dof): u is determined up to a constant (H 1 = 0). The system is bordered,
// [A 1; wᵀ 0] [u; λ] = [b; ∫_Γ exact dΓ] with w_j = ∫_Γ φ_j dΓ, i.e. ∫_Γ u_h dΓ = ∫_Γ exact dΓ when
// problem.exact is given and ∫_Γ u_h dΓ = 0 otherwise (λ absorbs the discrete incompatibility of q).
#include <Eigen/Core>
#include <memory>
#include <string>

#include "bem/assembly.hpp"
#include "bem/boundary_discretization.hpp"
#include "fem/compatibility.hpp"
#include "fem/function.hpp"

namespace iga::bem {

struct Problem {
  std::shared_ptr<const fem::Function> dirichlet;         ///< u on Dirichlet segments (user units)
  std::shared_ptr<const fem::BoundaryFunction> neumann;   ///< ∂u/∂n on Neumann segments (user units)
  std::shared_ptr<const fem::Function> exact;             ///< optional: fixes the constant of pure Neumann
};

struct SolveOptions {
  enum class Solver { Auto, LU, GMRES } solver = Solver::Auto;
  double gmres_tolerance = 1e-12;  ///< relative residual
  int gmres_restart = 200;
  int gmres_max_iterations = 2000;
  /// GMRES preconditioner: block Jacobi on runs of at most this many consecutive dofs of one segment (the
  /// near field of each collocation point); 0 = none.
  Index gmres_block = 64;
  Index lu_limit = 4000;  ///< Auto: LU up to this many unknowns, GMRES above
  /// Pure Neumann: data whose ∫g is not zero within fem::kCompatibilityTolerance of ∫|g| are refused
  /// (InputError) unless this is set; the border's λ then absorbs the defect.
  bool remove_incompatible = false;
};

struct Solution {
  Eigen::VectorXd u, q;  ///< coefficients on d.space() in user units (q = ∂u/∂n of the user's coordinates)
  double assembly_seconds = 0.0, solve_seconds = 0.0;
  /// LU: 1 / PartialPivLU::rcond(), Eigen's estimate of the 1-norm condition κ₁(A). GMRES: the 2-norm
  /// condition of the preconditioned A M⁻¹ on the last Krylov space (gmres.hpp), a lower bound of κ₂(A M⁻¹)
  /// (with gmres_block = 0, of κ₂(A); κ₁ / n <= κ₂ <= n κ₁).
  double condition_estimate = 0.0;
  double scale = 1.0;  ///< the discretisation's internal scale factor
  int gmres_iterations = 0;
  std::string solver;  ///< "lu" or "gmres"
  Index collocation_points = 0;
  bool pure_neumann = false;           ///< no Dirichlet dof: the bordered system
  fem::Compatibility compatibility;    ///< pure Neumann: ∫g and ∫|g| and the verdict
};

/// Assembles H and G and solves. InputError when Dirichlet dofs exist and problem.dirichlet is missing, or
/// Neumann dofs and problem.neumann, or (pure Neumann) for data with ∫g ≠ 0 (fem::check_compatibility); NumericalError on a non-finite result or a GMRES run that does not
/// reach the tolerance.
Solution solve(const BoundaryDiscretization& d, const Problem& problem, const SolveOptions& options = {});

/// The system matrix A of H u = G q with the unknowns x_j = q_j (Dirichlet dof j: column −G_j) and u_j
/// (Neumann dof j: column H_j), before the pure-Neumann border (internal units).
Eigen::MatrixXd system_matrix(const BoundaryDiscretization& d, const BemMatrices& m);

/// The known coefficients of a segment: interpolation of `values` (one per collocation point, in the order of
/// d.collocation_points()) on every segment; used by solve() for u on Dirichlet and q on Neumann segments.
Eigen::VectorXd interpolate_at_collocation(const BoundaryDiscretization& d, const Eigen::VectorXd& values);

}  // namespace iga::bem
