#pragma once
// Collocation matrices of the 2D Laplace BEM (thesis (4.48)–(4.49)), in the discretisation's internal
// (scaled) coordinates: row i is the boundary integral equation (4.46) at collocation point P_i,
//   c(P_i) u_h(P_i) + Σ_j u_j ∫_Γ φ_j ∂v/∂n dΓ = Σ_j q_j ∫_Γ φ_j v dΓ.
// The free term by the rigid-body trick (§4.3.3): u = 1, q = 0 solves the problem, so
// c(P_i) = −Σ_j ∫_Γ φ_j ∂v/∂n dΓ (the basis is a partition of unity); it enters row i as c_i φ_j(P_i) over the
// dofs j of P_i's element, and H 1 = 0 holds to rounding.
#include <Eigen/Core>

#include "basis/curve/curve_geometry.hpp"
#include "bem/boundary_discretization.hpp"

namespace iga::bem {

struct BemMatrices {
  Eigen::MatrixXd H;          ///< collocation points × dofs: c_i φ_j(P_i) + ∫ φ_j ∂v/∂n dΓ
  Eigen::MatrixXd G;          ///< collocation points × dofs: ∫ φ_j v dΓ (internal units)
  Eigen::VectorXd free_term;  ///< c(P_i) from the row sums
  double seconds = 0.0;       ///< wall-clock assembly time
};

/// H and G by collocation. OpenMP over rows; each row is computed by one thread in a fixed order, so the
/// result does not depend on the number of threads.
BemMatrices assemble(const BoundaryDiscretization& d);

/// c(P) = −∫_Γ ∂v/∂n(P, ·) dΓ for the boundary point P = curve.point(element, t) (corners included): the
/// interior angle at P over 2π (1/2 at a smooth point). Any curve coordinates (the integral is scale free).
double free_term(const basis::CurveGeometry& curve, Index element, double t);

}  // namespace iga::bem
