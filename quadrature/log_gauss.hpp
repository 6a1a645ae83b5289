#pragma once
// Gauss rules for the logarithmic weight on [0, 1] (thesis §4.3, (4.51): the weakly singular integrals of
// collocation BEM): ∫_0^1 f(x) (−ln x) dx ≈ Σ w_i f(x_i), exact for polynomials of degree <= 2n − 1.
#include "quadrature/rule.hpp"

namespace iga::quadrature {

/// The n-point rule (1 <= n <= 40; InputError otherwise). The recurrence of the weight's orthogonal polynomials
/// comes from its modified moments against the monic shifted Legendre polynomials, ∫_0^1 P*_k(x) (−ln x) dx =
/// (−1)^k / (k (k+1)) for k >= 1 (1 for k = 0), by Gautschi's modified Chebyshev algorithm (stable, unlike
/// the moment equations in the monomials); nodes and weights are the Golub–Welsch eigen-decomposition of the
/// Jacobi matrix. Points ascending in (0, 1), weights positive and summing to ∫_0^1 −ln x dx = 1.
Rule1D log_gauss_rule(int n);

}  // namespace iga::quadrature
