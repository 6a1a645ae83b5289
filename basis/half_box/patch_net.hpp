#pragma once
// The control points of the patch of one net vertex, gathered from a PolyMesh in the order the evaluators
// expect (regular_patch.hpp for 13 points, irregular_patch.hpp for n + 7).
#include <array>
#include <vector>

#include "mesh/poly_mesh.hpp"

namespace iga::basis::half_box {

/// Number of control points of a patch whose face at corner (0,0) is an n-gon: 13 for n = 6, else n + 7.
constexpr int patch_size(int valence) { return valence == 6 ? 13 : valence + 7; }

/// The patch of an interior three-valent vertex v. Its reference triangle {u, v >= 0, u + v <= 1} has corner
/// (0,0) in faces[0] = F0, (1,0) in F1, (0,1) in F2 (counter-clockwise around v). Side 0 ((0,0)-(1,0)) lies
/// between F0 and F1, side 1 ((1,0)-(0,1)) between F1 and F2, side 2 ((0,1)-(0,0)) between F2 and F0.
///
/// valence = size of F0 (6: regular patch, F1 and F2 must be hexagons in every case). Order of `points`:
///  - valence 6: the 13-point order of regular_patch.hpp;
///  - valence n != 6 (the EF at corner (0,0)): 0..n−1 the EF counter-clockwise from v (point 0 = v);
///    F1 counter-clockwise from v reads v, n−1, n, n+1, n+2, n+3; F2 counter-clockwise from v reads
///    v, n+3, n+4, n+5, n+6, 1 (n+3 is the neighbour of v off the EF, the "spoke").
struct PatchNet {
  Index vertex = -1;
  int valence = 6;
  std::array<Index, 3> faces{-1, -1, -1};
  std::vector<Index> points;
};

/// The patch of origin(half_edge) with F0 = face(half_edge). Throws InputError when the vertex is not an
/// interior vertex with three edges, or the patch would repeat a net vertex (a net too coarse around it);
/// UnsupportedError when F1 or F2 is not a hexagon (two EFs touch the vertex: subdivide the net once first).
/// Vertices in messages are 1-based.
PatchNet gather_patch(const mesh::PolyMesh& net, Index half_edge);

/// The patch of vertex v with F0 its non-hexagonal face if it has one, else the face of
/// net.vertex_half_edge(v). Errors as gather_patch.
PatchNet patch_net(const mesh::PolyMesh& net, Index vertex);

/// Whether no vertex touches two or more non-hexagonal faces (then every interior vertex has a patch).
bool efs_separated(const mesh::PolyMesh& net);

}  // namespace iga::basis::half_box
