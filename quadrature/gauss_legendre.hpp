#pragma once
#include "quadrature/rule.hpp"

namespace iga::quadrature {

/// The n-point Gauss–Legendre rule on [0, 1] (exact for polynomials of degree 2n - 1), n >= 1.
/// Nodes by Newton's method on the three-term recurrence of the Legendre polynomials, in long double,
/// from the asymptotic guesses cos(pi (k - 1/4) / (n + 1/2)); weights 2 / ((1 - x^2) P_n'(x)^2) on [-1, 1].
/// Points ascending.
Rule1D gauss_legendre(int n);

}  // namespace iga::quadrature
