#pragma once
// u inside the domain from the boundary solution (thesis (4.50)):
//   u(P) = Σ_j q_j ∫_Γ φ_j v dΓ − Σ_j u_j ∫_Γ φ_j ∂v/∂n dΓ,
// with the same quadrature as the collocation matrices: points close to the boundary are handled by adaptive
// subdivision of the near elements. The quadrature error is ~1e-13 down to distances δ ~ 1e-5 of the
// diameter and grows like 1e-18/δ below (the node parameters carry an absolute rounding of ~1e-16: measured
// 3e-13 at δ = 1e-6, 6e-10 at δ = 1e-10, test_bem_quadrature); the discretisation error of u_h near Γ is that
// of u_h on Γ (test_bem_solve).
#include <Eigen/Core>

#include "bem/boundary_discretization.hpp"
#include "bem/solve.hpp"

namespace iga::bem {

/// points: 2 × m in user units. Points outside the domain get (approximately) 0, the value of the
/// representation formula there (c(P) = 0). Points on the boundary (closer than ~1e-14 of the diameter):
/// InputError naming the point; evaluate u_h there with errors.hpp's evaluate_u instead.
Eigen::VectorXd evaluate_interior(const BoundaryDiscretization& d, const Solution& solution,
                                  const Eigen::Matrix2Xd& points);

}  // namespace iga::bem
