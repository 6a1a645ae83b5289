#pragma once
// Exact area of a planar domain and exact enclosed volume of a closed surface, for any space whose elements
// are polynomial or offer a subdivision view (Catmull–Clark, half-box, polyhedral, B-splines): polynomial
// elements by Gauss rules exact for the polynomial integrand, infinitely piecewise elements by the
// subdivision series (subdivision_integrals.hpp) applied to their coefficients.
#include "basis/geometry.hpp"

namespace iga::quadrature::exact {

/// Σ_e ∫ (x_u y_v − y_u x_v) over each element's reference domain for a planar geometry (dim 2): signed,
/// positive for a counter-clockwise net. Polynomial elements of degree <= `degree` per direction (quads) or in
/// total (triangles): det J has degree 2·degree − 1 per direction (2·degree − 2 in total), integrated by
/// `degree`-point Gauss (the collapsed rule on triangles). Infinitely piecewise elements: xᵀ (D − Dᵀ) y with
/// D = ∫ ∂u φ_a ∂v φ_b from the element's subdivision view. InputError unless dim 2; UnsupportedError naming
/// an irregular element that offers no subdivision view.
double exact_area(const basis::Geometry& g, int degree = 3);

/// V = Σ_e ∫ z (x_u y_v − y_u x_v) for a closed surface (dim 3; the divergence theorem with F = (0, 0, z),
/// positive for outward orientation). Polynomial elements: the integrand has degree 3·degree − 1 per direction
/// (3·degree − 2 in total): ceil(3·degree/2)-point Gauss. Infinitely piecewise elements: the triple products
/// value × d/du × d/dv contracted with (z, x, y) − (z, y, x). InputError unless dim 3. (For an open surface
/// it returns the same integral, which is then not a volume.)
double exact_volume(const basis::Geometry& g, int degree = 3);

}  // namespace iga::quadrature::exact
