#pragma once
#include "quadrature/rule.hpp"

namespace iga::quadrature {

/// Tensor product of two rules on [0,1]: point (u_i, v_j) at index i + nu * j, weight wu_i wv_j.
Rule tensor_rule(const Rule1D& u, const Rule1D& v);

/// A rule on the unit triangle {u, v >= 0, u + v <= 1} by collapsing the square (Duffy):
/// u = s, v = t (1 - s), weight ws wt (1 - s). With n points per direction it is exact for polynomials of
/// total degree 2n - 2.
Rule collapsed_triangle_rule(const Rule1D& s, const Rule1D& t);

}  // namespace iga::quadrature
