#pragma once
// One step of half-box spline subdivision of a three-valent control net (thesis §3.2.1, Figures 3.7–3.9):
// every (face, vertex) corner gets a new point from stencil S1 applied within that face, every vertex a new
// point from stencil S2; each face shrinks to the n-gon of its corner points and each edge becomes a hexagon.
#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <vector>

#include "mesh/poly_mesh.hpp"

namespace iga::basis::half_box {

/// Weights of S1 for the corner point at vertex i of an n-gon: weight[j] multiplies the vertex j steps after
/// i around the face (either direction: the weights are symmetric, weight[j] == weight[n − j]).
/// Hexagon (n = 6, mask of H111): 1/2, 1/8, 1/8, 0, 1/8, 1/8. Other n: a_n^j of (3.37),
/// a_n^0 = 1/4 + 5/(4n), a_n^j = (3 + 2 cos(2πj/n)) / (4n), which gives the face block the spectrum
/// 1, 1/2, 1/4, ..., 1/4, 1/2 (3.36). Throws InputError for n < 3.
std::vector<double> s1_weights(int n);

/// Weights of S2 at a vertex: (b, c, c, d) on the vertex itself, its two neighbours on an n-gon and its
/// neighbour off it (Figure 3.9). This backend uses b = c = d = 1/4 for every n: S2 is then the regular
/// stencil (1/4 on the vertex and each of its three neighbours), so b + 2c = 3/4 and d = 1/4 (the thesis's
/// bounded-curvature condition) hold and every non-EF tile of an EF patch is an ordinary half-box patch.
constexpr double kS2Weight = 0.25;

/// Result of one subdivision step. New vertices: first the corner points, one per half-edge h of the old
/// net (new vertex h is the S1 point of corner (face(h), origin(h))), then the S2 points of the old vertices
/// (vertex_point[v], −1 where S2 is undefined). New faces: first old face f shrunk (new face f, its corners in
/// the old order), then one hexagon per edge with an S2 point at both ends and a face on both sides
/// (edge_face[h] for both half-edges of the edge, −1 otherwise), in order of the smaller half-edge index.
/// new points = prolongation · old points (rows sum to 1).
struct NetSubdivision {
  mesh::PolyMesh net;
  Eigen::SparseMatrix<double> prolongation;  ///< (new vertices) × (old vertices)
  std::vector<Index> vertex_point;           ///< old vertex → its S2 point in net, or −1
  std::vector<Index> edge_face;              ///< old half-edge → the hexagon of its edge in net, or −1
};

/// One half-box subdivision step of a closed three-valent net. Throws InputError naming the first vertex
/// (1-based) whose valence is not 3, UnsupportedError when the net has a boundary (boundary rules are not
/// implemented), naming a boundary vertex (1-based).
NetSubdivision subdivide(const mesh::PolyMesh& net);

/// The same step on a local (open) net: every face shrinks, vertices with exactly three edges get their S2
/// point (it needs only the three neighbours, so a boundary vertex with three edges has one), and an edge
/// becomes a hexagon when it has faces on both sides and S2 points at both ends. Vertices of valence > 3
/// throw InputError (1-based). Used to generate the local subdivision matrices from synthetic nets.
NetSubdivision subdivide_local(const mesh::PolyMesh& net);

}  // namespace iga::basis::half_box
