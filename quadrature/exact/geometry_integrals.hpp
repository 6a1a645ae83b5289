#pragma once
// Exact area of a planar Catmull–Clark domain and exact enclosed volume of a closed Catmull–Clark surface:
// regular elements by tensor Gauss rules that are exact for the polynomial integrand, elements at
// extraordinary vertices by the subdivision series (irregular_integrals.hpp) applied to their local points.
#include "basis/geometry.hpp"

namespace iga::quadrature::exact {

/// Σ_e ∫_[0,1]² det J = Σ_e ∫ (x_u y_v - y_u x_v) for a planar geometry (dim 2) on a CatmullClarkSpace:
/// signed, positive for a counter-clockwise net. Regular elements: det J has degree (5,5), 3×3 Gauss is
/// exact. Stam elements (interior EV): x_locᵀ (D_uv - D_uvᵀ) y_loc with D_uv = irregular_integrals(n).d[0][1]
/// and x_loc = stam_map · x(dofs). Other EV elements (boundary EVs): the same bilinear form built from their
/// level-0 tiles plus the level series of their repeated subdivision matrix.
/// InputError unless the geometry is planar on a CatmullClarkSpace.
double exact_area(const basis::Geometry& g);

/// V = Σ_e ∫_[0,1]² z (x_u y_v - y_u x_v) for a closed surface (dim 3) on a CatmullClarkSpace (the
/// divergence theorem with F = (0, 0, z); positive for outward orientation of the net). Regular elements:
/// the integrand has degree (8,8), 5×5 Gauss is exact. Stam elements: the triple products value×du×dv
/// (triple(n, -1, 0, 1)) contracted with (z, x, y) - (z, y, x). Other EV elements as in exact_area.
/// InputError unless dim 3 on a CatmullClarkSpace. (For an open surface it returns the same integral, which
/// is then not a volume.)
double exact_volume(const basis::Geometry& g);

}  // namespace iga::quadrature::exact
