#pragma once
// The boundary solution as functions on Γ and its errors against an exact solution (user units throughout).
#include "bem/boundary_discretization.hpp"
#include "bem/solve.hpp"
#include "fem/function.hpp"

namespace iga::bem {

/// u_h and q_h = (∂u/∂n)_h at parameter t ∈ [0, 1] of BEM element e.
double evaluate_u(const BoundaryDiscretization& d, const Solution& s, Index e, double t);
double evaluate_q(const BoundaryDiscretization& d, const Solution& s, Index e, double t);

/// ‖q_h − ∇u·n‖_{L2(Γ)} with the exact gradient of `exact` (its gradients(); closed form or finite
/// difference, see fem::Function), Gauss with p + 6 points per BEM element.
double flux_l2_error(const BoundaryDiscretization& d, const Solution& s, const fem::Function& exact);
/// ‖u_h − u‖_{L2(Γ)}.
double u_l2_error(const BoundaryDiscretization& d, const Solution& s, const fem::Function& exact);
/// ‖∇u·n‖_{L2(Γ)} and ‖u‖_{L2(Γ)}, for relative errors.
double flux_l2_norm(const BoundaryDiscretization& d, const fem::Function& exact);
double u_l2_norm(const BoundaryDiscretization& d, const fem::Function& exact);

}  // namespace iga::bem
