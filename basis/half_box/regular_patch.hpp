#pragma once
// The regular half-box spline patch (thesis §2.2.5): one triangle of the three-directional grid, dual to one
// three-valent vertex v of a hexagonal control net, is a cubic Bézier triangle controlled by the 13 vertices
// of the three hexagons around v; its 13 blending functions are the 13 polynomial pieces of H111, (2.23).
#include <Eigen/Core>

#include "basis/basis_values.hpp"

namespace iga::basis::half_box {

/// Number of control points of a regular patch (18 − 6 + 1).
constexpr int kRegularPatchSize = 13;
/// Number of cubic Bernstein–Bézier coefficients on a triangle.
constexpr int kBezierSize = 10;

/// Ordering of the 13 control points (used everywhere in basis/half_box/). The patch is the reference triangle
/// {u, v >= 0, u + v <= 1}; its corner (0,0) lies in face F0, (1,0) in F1, (0,1) in F2, where F0, F1, F2 are the
/// three faces around v in counter-clockwise order. Side 0 ((0,0)-(1,0)) lies between F0 and F1, side 1
/// ((1,0)-(0,1)) between F1 and F2, side 2 ((0,1)-(0,0)) between F2 and F0; the patch across side i is that of
/// the neighbour of v shared by F_i and F_{i+1}.
///   0: v;  1: u0 = neighbour of v shared by F0 and F1;  2: u1 (F1 and F2);  3: u2 (F2 and F0);
///   F0 counter-clockwise from v reads v, u2, 4, 5, 6, u0;
///   F1 counter-clockwise from v reads v, u0, 7, 8, 9, u1;
///   F2 counter-clockwise from v reads v, u1, 10, 11, 12, u2.
/// (In the three-directional grid with lines x, y, x + y ∈ Z and the patch U(0,0) = {(0,0),(1,0),(0,1)}, the
/// points are the triangles U(0,0), D(0,-1), D(0,0), D(-1,0), U(-1,0), D(-1,-1), U(0,-1), U(1,-1), D(1,-1),
/// U(1,0), U(0,1), D(-1,1), U(-1,1), with U(i,j) = (i,j) + U(0,0) and D(i,j) = (i+1,j+1) − U(0,0).)
///
/// Ordering of the 10 BB coefficients c_{ijk} (barycentric λ0 = 1 − u − v, λ1 = u, λ2 = v, i + j + k = 3):
///   (300), (210), (201), (120), (111), (102), (030), (021), (012), (003).
///
/// The 10 × 13 matrix with c = bezier_matrix() · P (P the 13 control points, one per row). Entries are the
/// BB coefficients of the pieces of H111 in sixths (thesis Figure 2.24): e.g. the corner c_300 is the mean of
/// the six vertices of F0, c_210 = (2 v + 2 u0 + u2 + P6) / 6, the centre c_111 = (3 v + u0 + u1 + u2) / 6.
/// Rank 10: the 13 blending functions span the cubics with a 3-dimensional kernel.
const Eigen::Matrix<double, kBezierSize, kRegularPatchSize>& bezier_matrix();

/// Values of the 10 cubic Bernstein polynomials (order above) and, for derivatives >= 1, 2, their first and
/// second derivatives with respect to (u, v) at one point (u, v) of the reference triangle (any (u, v) is
/// accepted: the polynomials are evaluated as polynomials). Blocks: 10 × 1 each, no allocation.
struct BernsteinValues {
  Eigen::Matrix<double, kBezierSize, 1> value, du, dv, duu, duv, dvv;
};
void bernstein_cubic(double u, double v, int derivatives, BernsteinValues& out);

/// The 13 blending functions at uv (2 × q reference points), rows in the order above, derivatives with
/// respect to (u, v) up to `derivatives` (0, 1 or 2). Resizes `out` to 13 × q (no allocation when `out`
/// already has that size). Throws InputError for derivatives outside 0..2.
void evaluate_regular(const Eigen::Matrix2Xd& uv, int derivatives, BasisValues& out);

}  // namespace iga::basis::half_box
