#pragma once
// The uniform bicubic B-spline patch of a regular Catmull–Clark face: its 16 basis functions on the unit
// square, and the 4×4 grid of control points gathered around a face of a quad mesh, with phantom points
// where the grid leaves the mesh.
#include <Eigen/Core>
#include <array>

#include "basis/basis_values.hpp"
#include "basis/catmull_clark/quad_mesh.hpp"

namespace iga::basis::catmull_clark {

/// Grid position (i, j), i, j in {-1, 0, 1, 2}, of the 4×4 neighbourhood of the face [0,1]^2 → row index.
constexpr int grid_index(int i, int j) { return (i + 1) + 4 * (j + 1); }

/// Values (and first/second derivatives for derivatives >= 1, 2) of the 16 tensor-product uniform cubic
/// B-splines N_{i+1}(u) N_{j+1}(v) at pts (2 × q), rows in grid_index order, scaled: derivative blocks are
/// multiplied by scale (first) and scale² (second), for tiles of size 1/scale. Resizes the blocks of `out`.
void bicubic_values(const Eigen::Matrix2Xd& pts, int derivatives, double scale, BasisValues& out);

/// The 4×4 control points of face `face` of m (corner c_i = quads[face][(i + rotation) % 4] at grid
/// (0,0), (1,0), (1,1), (0,1)) as a 16 × m.num_vertices weight matrix. The corners must be regular (interior
/// with 4 faces, boundary with 2 faces, or a corner with 1 face) and their faces present in m. Points outside
/// the mesh are phantoms that make the bicubic patch reproduce the boundary rule: across a boundary edge the
/// reflection P(-1, j) = 2 P(0, j) - P(1, j) (rows first), then the same in the other direction (columns),
/// which at a corner gives the tensor extrapolation 4 P00 - 2 P10 - 2 P01 + P11.
Eigen::MatrixXd grid_operator(const QuadMesh& m, int face, int rotation);

/// Whether the corner of `face` at half-edge h (its origin) is a regular vertex in the sense above.
bool is_regular_corner(const QuadMesh& m, int h);

/// The three grid points a regular corner (origin of half-edge h, its face at grid [0,1]^2 with the corner at
/// (0,0)) contributes: (-1,0), (-1,-1), (0,-1) in that corner's frame; -1 where outside the mesh.
std::array<int, 3> corner_outer_points(const QuadMesh& m, int h);

}  // namespace iga::basis::catmull_clark
