#pragma once
// Poisson / Laplace (planar) and Laplace–Beltrami (surface) problems -Δu + c u = f with strong Dirichlet
// and natural Neumann conditions: the whole pipeline from a geometry to a solution and its report figures.
#include <Eigen/Core>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "basis/geometry.hpp"
#include "fem/errors.hpp"
#include "fem/function.hpp"
#include "fem/solver.hpp"
#include "quadrature/rule_provider.hpp"

namespace iga::fem {

struct PoissonProblem {
  std::shared_ptr<const Function> source;           ///< f; null means 0
  std::shared_ptr<const Function> dirichlet;        ///< g_D on the Dirichlet parts; null means 0
  std::shared_ptr<const BoundaryFunction> neumann;  ///< g_N = ∂u/∂n on the Neumann parts
  std::vector<int> neumann_parts;                   ///< indices into Space::boundary_part_names()
  /// Optional: a boundary edge is also Neumann when this is > 0 at the physical midpoint of the edge.
  std::shared_ptr<const Function> neumann_where;
  std::shared_ptr<const Function> exact;            ///< optional: enables error norms
  double reaction = 0.0;                            ///< c >= 0
  /// Without Dirichlet boundary and with c = 0 (a closed surface, or Neumann data everywhere) u is defined up
  /// to a constant: with mean_zero the solution with ∫u = 0 is returned (the load is made compatible by
  /// removing its mean, reported as compatibility_defect; error norms compare with exact - mean(exact)).
  bool mean_zero = false;
};

struct PoissonResult {
  Eigen::VectorXd u;                ///< coefficients of the solution in the geometry's space
  Index dofs = 0, free_dofs = 0, dirichlet_dofs = 0, elements = 0, quadrature_points = 0;
  double domain_measure = 0.0;      ///< area (planar) or surface area by the chosen quadrature
  double pattern_seconds = 0.0;     ///< sparsity pattern and colouring
  double assembly_seconds = 0.0;    ///< pattern + element loop + boundary terms + Dirichlet projection
  double solve_seconds = 0.0;
  std::string solver;
  double residual_norm = 0.0;       ///< relative residual of the reduced system
  Index solver_iterations = 0;
  std::optional<ErrorNorms> errors; ///< with an exact solution
  Index neumann_edges = 0, dirichlet_edges = 0;
  bool mean_zero = false;           ///< the mean-zero constraint was applied
  double compatibility_defect = 0;  ///< ∫f + ∫g_N before it was removed (mean_zero only)
};

/// Solves the problem. InputError for an ill-posed set-up (every boundary part Neumann, or no boundary,
/// with c = 0 and no mean-zero constraint), for Neumann parts out of range, or Neumann parts without data.
PoissonResult solve_poisson(const basis::Geometry& geometry, const quadrature::RuleProvider& rules,
                            const PoissonProblem& problem, const SolverOptions& solver = {});

}  // namespace iga::fem
