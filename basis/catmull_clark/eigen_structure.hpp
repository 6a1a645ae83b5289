#pragma once
// Real eigen-decomposition of the Catmull–Clark subdivision matrix A = V diag(lambda) V^{-1} (Stam 1998),
// built from the block structure of A rather than by a general eigensolver.
#include <Eigen/Core>

namespace iga::basis::catmull_clark {

struct EigenStructure {
  Eigen::VectorXd values;   ///< lambda, sorted descending (ties keep the construction order below)
  Eigen::MatrixXd vectors;  ///< V, eigenvectors as columns
  Eigen::MatrixXd inverse;  ///< V^{-1}; its rows are the dual (left) eigenvectors
};

/// Eigen-decomposition of a = subdivision_matrix(valence) (local ordering of subdivision_matrix.hpp).
///
/// A = [[S, 0], [S11, S12]] with S the (2n+1)×(2n+1) one-ring block and S12 the 7×7 block of the remaining
/// points. S is diagonalised by a discrete Fourier transform around the EV: frequency 0 gives a 3×3 block
/// with eigenvalues 1 and (3n − 7 ± sqrt(5n² − 30n + 49)) / (8n); each frequency 0 < ω < n/2 a 2×2 block with
/// eigenvalues (5 + c ± sqrt((1 + c)(9 + c))) / 16, c = cos(2πω/n), each twice (a cosine and a sine mode);
/// ω = n/2 (n even) the eigenvalue 1/4 twice. S12 has eigenvalues 1/8, 1/16, 1/32 (twice each) and 1/64.
/// The eigenvector of A for an eigenpair (λ, u) of S is [u; w] with (λ I − S12) w = S11 u, solved in S12's
/// eigenbasis; where λ equals an eigenvalue of S12 (n = 4: 1/8, 1/16; n = 8, 12, 16: 1/8) the right-hand side
/// has no component along it (checked; A is not defective) and that component of w is set to zero.
/// V^{-1} is formed blockwise, so the dual vectors of the one-ring modes are exactly zero beyond the one-ring.
///
/// Conventions of the columns (StamEvaluator relies on them):
///   column 0: lambda = 1, V(:,0) = (1, ..., 1), so row 0 of V^{-1} is the limit-point stencil;
///   columns 1, 2: the subdominant pair lambda = subdominant_eigenvalue(n), with one-ring parts
///     EV 0, e_k = cos(2πk/n) resp. sin(2πk/n), f_k = (g_k + g_{k+1}) / (4 lambda − 1), g = cos resp. sin.
///     For n = 4 they are the grid coordinates i and j of every point, so rows 1, 2 of V^{-1} are then the
///     stencils of d/du and d/dv at the EV.
/// Throws NumericalError when the reconstruction error ||V diag(lambda) V^{-1} − A||_F / ||A||_F exceeds 1e-12.
EigenStructure eigen_structure(int valence, const Eigen::MatrixXd& a);

/// The subdominant eigenvalue (5 + cos(2π/n) + cos(π/n) sqrt(2 (9 + cos(2π/n)))) / 16.
double subdominant_eigenvalue(int valence);

}  // namespace iga::basis::catmull_clark
