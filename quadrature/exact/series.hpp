#pragma once
// Geometric matrix series of subdivision integrals (thesis §4.2.1, (4.28)–(4.34); Appendix C): the sums over
// the infinitely many tile levels of an element at an extraordinary vertex, computed by doubling, without
// the eigen-decomposition (valid for defective matrices and repeated eigenvalues).
#include <Eigen/Core>
#include <vector>

namespace iga::quadrature::exact {

/// A third-order tensor T(a, b, c) stored as T[a](b, c).
using Tensor3 = std::vector<Eigen::MatrixXd>;

/// y = sum_{j >= 0} s^j (A^T)^j c, the solution of y = c + s A^T y. Doubling: after k steps the first 2^k
/// terms are summed, y <- y + s^(2^k) (A^(2^k))^T y. NumericalError if the terms do not decay within 64
/// doublings (s |lambda| >= 1 for an eigenvalue lambda of A that c does not annihilate).
Eigen::VectorXd linear_series(const Eigen::MatrixXd& a, const Eigen::VectorXd& c, double s);

/// X = sum_{j >= 0} s^j (A^T)^j C A^j (discrete Stein equation X = C + s A^T X A), by doubling
/// X <- X + s^(2^k) (A^(2^k))^T X A^(2^k). Converges when s |lambda_i lambda_j| < 1 on every pair of
/// eigenvalues (with their Jordan chains) that C does not annihilate; since the test is on the decay of the
/// doubled power, eigenvalues that C annihilates but for which s |lambda|^2 >= 1 must be deflated first
/// (deflate_constant, deflate_modes). NumericalError when the series does not converge in 64 doublings.
/// `b` (optional, same size as a) is used on the right: X = sum s^j (A^T)^j C B^j.
Eigen::MatrixXd stein(const Eigen::MatrixXd& a, const Eigen::MatrixXd& c, double s);
Eigen::MatrixXd stein(const Eigen::MatrixXd& a, const Eigen::MatrixXd& c, const Eigen::MatrixXd& b, double s);

/// A - 1 w^T with w^T A = w^T, w^T 1 = 1 (w: the limit stencil): its powers are A^j - 1 w^T, so
/// (B^j)^T C B^j = (A^j)^T C A^j exactly whenever C 1 = 0 and 1^T C = 0 (derivative integrals); the
/// eigenvalue 1 becomes 0 and the series with s = 1 converges.
Eigen::MatrixXd deflate_constant(const Eigen::MatrixXd& a, const Eigen::VectorXd& w);

/// A - R diag(lambda) L for right eigenvectors R (columns), left eigenvectors L (rows, L R = I) and their
/// eigenvalues: removes those modes exactly (B^j = A^j - R diag(lambda)^j L).
Eigen::MatrixXd deflate_modes(const Eigen::MatrixXd& a, const Eigen::MatrixXd& right, const Eigen::MatrixXd& left,
                              const Eigen::VectorXd& lambda);

/// T'(a, b, c) = sum_{p,q,r} T(p, q, r) P(p, a) Q(q, b) R(r, c) (P: p × a', ...).
Tensor3 contract(const Tensor3& t, const Eigen::MatrixXd& p, const Eigen::MatrixXd& q, const Eigen::MatrixXd& r);

/// T = sum_{j >= 0} s^j (P^j, Q^j, R^j) · C (contract above), by doubling. Converges when
/// s |lambda_i mu_j nu_k| < 1 on the non-annihilated triples of eigenvalues of P, Q, R.
/// NumericalError when not converged in 64 doublings.
Tensor3 triple_series(const Tensor3& c, const Eigen::MatrixXd& p, const Eigen::MatrixXd& q, const Eigen::MatrixXd& r,
                      double s);

}  // namespace iga::quadrature::exact
