#pragma once
// The biharmonic equation Δ²u = f on planar domains (a Kirchhoff plate's D Δ²w = q with f = q / D) as a
// fem::Problem: for any space in H² (C1 across every interior edge: B-splines/NURBS of degree >= 2 with single
// interior knots, THB, Catmull–Clark, polyhedral and half-box splines). u = g on the whole boundary, strongly (the
// L2 projection onto the traces, as for Poisson); per boundary part either clamped (∂u/∂n = h, by Nitsche's
// method with a local penalty) or simply supported (Δu = m, natural). The forms: pde/biharmonic/forms.hpp.
#include <memory>
#include <vector>

#include "fem/function.hpp"
#include "fem/problem.hpp"

namespace iga::pde {

struct BiharmonicData {
  std::shared_ptr<const fem::Function> source;         ///< f; null: 0
  std::shared_ptr<const fem::Function> value;          ///< g = u on the whole boundary; null: 0
  std::shared_ptr<const fem::BoundaryFunction> slope;  ///< h = ∂u/∂n (outward) on the clamped parts; null: 0
  std::shared_ptr<const fem::Function> moment;         ///< m = Δu on the simply supported parts; null: 0
  std::vector<int> simply_supported;                   ///< boundary parts (Space::boundary_part_names() indices)
  std::shared_ptr<const fem::Function> exact;          ///< optional: the error norms L2, H1, H2 and ‖Δe‖
  /// Nitsche's penalty for ∂u/∂n = h: γ > 0 gives β = γ / h_side; 0 (default) β_K from each element's local
  /// eigenvalue estimate (fem::local_penalties with Δ on both sides), coercive by construction.
  double nitsche_penalty = 0.0;
};

/// Data whose boundary values all come from an exact solution u (g = u, h = ∇u·n, m = Δu from u's Hessians).
BiharmonicData biharmonic_data_from_exact(std::shared_ptr<const fem::Function> exact,
                                          std::shared_ptr<const fem::Function> source,
                                          std::vector<int> simply_supported = {});

/// The problem for the pipeline (fem::ProblemSolver, fem::solve_problem). Its check() refuses, with one line:
/// a surface (planar domains only), a boundary part index that does not exist, a penalty that is negative or not
/// finite, an element of degree below 2, and a C0 interior edge (a repeated knot), naming its elements and
/// physical midpoint.
std::shared_ptr<const fem::Problem> make_biharmonic(BiharmonicData data);

}  // namespace iga::pde
