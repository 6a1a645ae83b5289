#pragma once
// Singular data inside the domain (issue 38, class 5): a source 1/x on a domain that contains x = 0 is finite at
// every quadrature point that misses x = 0, and would be integrated to a finite, meaningless load. The check here
// samples the data where the rules do not look, and reads their singular set from the symbolic form.
#include "basis/geometry.hpp"
#include "fem/function.hpp"

namespace iga::fem {

/// Checks data that are integrated over the domain (a source, a body force, a coefficient) before they are used:
/// for a user's expression (fem::Expression; other functions are not checked) on every element, at the corners, the
/// side midpoints and the centre (physical points by the geometry):
///  - a value that is not finite at such a point inside the domain is refused:
///    "--source '1/x' is not finite at (0, 0.5) (element 3, a corner): singular data inside the domain have no
///    finite load";
///  - with the expression read symbolically, each singular factor (Expression::singular_factor_names(): the
///    denominators, the arguments of log) that vanishes at such a point inside the domain (|value| at most 1e-12 of
///    its largest on the element), or changes sign between two neighbouring points of an element (its zero set
///    crosses the element), is refused naming the factor, the element and the zero interpolated between the two
///    points.
/// Points on the domain's boundary (the corners and midpoints of boundary sides) are not judged: a singularity
/// there can be integrable against the test functions (x^(-1.5) on x = 0 with u = 0 there, r^(-1/3) at a corner).
/// Not found: a zero of a factor that never changes sign and misses every point (1/(x^2+y^2) about an interior point
/// that is no corner, midpoint or centre; 1/(x-0.3)^2 with x = 0.3 between the points) and singular sets of texts
/// that were not read symbolically. InputError as above.
void check_domain_data(const basis::Geometry& geometry, const Function& f);

}  // namespace iga::fem
