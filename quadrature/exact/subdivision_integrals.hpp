#pragma once
// Exact integrals over an infinitely piecewise element from its scheme-neutral subdivision view
// (basis/subdivision_view.hpp; thesis §4.2.1, (4.28)–(4.34); Appendix C): on every tile the integrand is a
// polynomial of the scheme's regular patch, integrated exactly by a Gauss rule on the patch domain; the layers
// are summed by geometric matrix series (series.hpp). Layer l has area factor 4^-(l-1) and each first
// derivative 2^(l-1) relative to layer 1, so a product with #d derivatives has ratio s = 2^#d / 4; derivative
// factors use A − 1 wᵀ (the constant mode removed exactly, its derivatives being zero).
// Works for Catmull–Clark (bicubic tiles) and half-box (cubic triangles) elements alike.
#include <Eigen/Core>

#include "basis/subdivision_view.hpp"
#include "quadrature/exact/series.hpp"
#include "quadrature/exact/tile_integrals.hpp"

namespace iga::quadrature::exact {

/// ∫_element φ_a for the element's dofs (vector of dofs(e).size()).
Eigen::VectorXd element_integral(const basis::SubdivisionElement& el);
/// G(a, b) = ∫_element F_a G_b, factors -1 (value), 0 (d/du), 1 (d/dv) in element coordinates.
Eigen::MatrixXd element_gram(const basis::SubdivisionElement& el, Factor f, Factor g);
/// T[a](b, c) = ∫_element F_a G_b H_c (InputError for factors outside -1..1).
Tensor3 element_triple(const basis::SubdivisionElement& el, Factor f, Factor g, Factor h);

}  // namespace iga::quadrature::exact
