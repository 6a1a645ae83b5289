#pragma once
// The matrices of Stam's evaluation of a Catmull–Clark patch at an extraordinary vertex (thesis §3.2.2,
// (3.46)): the subdivision matrix A, the extended subdivision matrix Ā and the picking matrices X^k.
//
// Local ordering of the 2n+8 control points of a quad whose corner 0 is an interior extraordinary vertex (EV)
// of valence n, named by their "grid coordinates" (i, j) (exact for n = 4; the element is [0,1]^2):
//   0: the EV (0,0);
//   2k+1 (k = 0..n-1): the k-th edge neighbour of the EV, counter-clockwise, 1 = (1,0), 3 = (0,1), 5 = (-1,0),
//                      2n-1 = (0,-1);
//   2k+2 (k = 0..n-1): the vertex opposite the EV in the quad between edges k and k+1, 2 = (1,1),
//                      4 = (-1,1), 2n = (1,-1);
//   2n+1 .. 2n+7: (2,-1), (2,0), (2,1), (2,2), (1,2), (0,2), (-1,2).
// After one subdivision step the new points carry the same names at half the spacing; the extended set adds
//   2n+8 .. 2n+16: (3,-1), (3,0), (3,1), (3,2), (3,3), (2,3), (1,3), (0,3), (-1,3).
// For n = 3, (-1,0) and (0,-1) are the same point (index 5). For n = 4 only, (-1,-1) is index 6.
#include <Eigen/Core>

namespace iga::basis::catmull_clark {

inline constexpr int kMinValence = 3;
inline constexpr int kMaxValence = 16;

/// Throws InputError unless kMinValence <= valence <= kMaxValence.
void check_valence(int valence);

/// 2n + 8.
int num_local_points(int valence);

/// 2n + 17.
int num_extended_points(int valence);

/// Index of the point with grid coordinates (i, j) in the (extended) local ordering above; InputError for a
/// name the ordering does not contain.
int local_index(int valence, int i, int j);

/// (2n+8) × (2n+8): row r holds the weights of the old local points in new local point r after one
/// Catmull–Clark step (face, edge and vertex rules of §3.2.2 / (3.45)). Rows sum to 1.
Eigen::MatrixXd subdivision_matrix(int valence);

/// (2n+17) × (2n+8): the first 2n+8 rows are subdivision_matrix(valence); rows 2n+8 .. 2n+16 give the nine
/// further points (3,-1) .. (-1,3) needed by the three tiles of level 1.
Eigen::MatrixXd extended_subdivision_matrix(int valence);

/// Grid coordinates (at level 1) of the lower-left control point (i0, j0) of tile k's 4×4 B-spline net:
///   k = 1: u in [1/2,1], v in [0,1/2]  -> (0,-1);
///   k = 2: u in [1/2,1], v in [1/2,1]  -> (0, 0);
///   k = 3: u in [0,1/2], v in [1/2,1]  -> (-1,0).
/// InputError unless 1 <= tile <= 3.
Eigen::Vector2i tile_origin(int tile);

/// 16 × (2n+17) picking matrix X^k: row a + 4b selects the extended point (i0 + a, j0 + b), a, b = 0..3
/// (a along u, b along v), so that the tile's patch is sum_{a,b} N_a(s) N_b(t) P_{a+4b}, with N_0..N_3 the
/// uniform cubic B-splines on the segment [0,1] and (s, t) the tile's local coordinates.
Eigen::MatrixXd picking_matrix(int valence, int tile);

}  // namespace iga::basis::catmull_clark
