#pragma once
// A proof that a planar geometry map does not fold (issue 38, class 1): the sign of det J on the whole of every
// element, not only at the points a rule samples.
//
// On an element where the map is a polynomial of degree d in each of u and v (Space::polynomial_degree), det J =
// x_u y_v − x_v y_u is one of degree 2d − 1; where it is rational, x = (X, Y)/W with W > 0, det J · W³ is one of
// degree 3d − 1 (it is the determinant of the rows (X, X_u, X_v), (Y, Y_u, Y_v), (W, W_u, W_v)). A polynomial on a
// box lies between the least and largest of its Bernstein coefficients, and the coefficients converge to the values
// under subdivision (Farin, "Curves and surfaces for CAGD", §§ 5.3, 16.3). So: the coefficients on the element
// (interpolated at Chebyshev–Lobatto nodes, exact for a polynomial of the degree) all of the geometry's orientation
// prove it; a value of the other sign at a node is a fold; otherwise the box is split in four, down to 1/256 of the
// element, and a box that still cannot be decided is reported as a fold at its least coefficient.
// Infinitely piecewise elements (Catmull–Clark at extraordinary vertices, Space::subdivision_element) are checked on
// their polynomial tiles, layer by layer towards the vertex, until the layers' shape has converged (the
// sub-dominant eigenvectors of the subdivision matrix: every further layer is that shape scaled). Triangle elements
// and tiles (half-box splines) and backends without either form keep the rule's sampling (Geometry::evaluate).
#include <string>

#include "basis/geometry.hpp"

namespace iga::basis {

/// For a planar geometry (dim 2), the message naming the first element, and the point on it, where det J does not
/// have the sign of orientation() ("element 3: det J = -0.0082 < 0 at (0.001, 0.002) where most of the domain has
/// det J > 0: the geometry map folds over (proved from det J's Bernstein coefficients)"), or "" when every element
/// is proved or has no polynomial form to prove it with. Surfaces: "".
std::string fold_certificate(const Geometry& geometry);

}  // namespace iga::basis
