#pragma once
// A small all-quad mesh with half-edge twins, the combinatorial workspace of the Catmull–Clark backend:
// the control net, the unfolded one-ring of a face (its "local neighbourhood"), and one symbolic
// Catmull–Clark step of such a neighbourhood as a linear map of its points.
#include <Eigen/Core>
#include <array>
#include <vector>

#include "mesh/poly_mesh.hpp"

namespace iga::basis::catmull_clark {

/// Quads with counter-clockwise corners. Half-edge 4f + i goes from quads[f][i] to quads[f][(i+1)%4];
/// twin[h] is the opposite half-edge (-1 where the mesh ends: a true boundary, or the rim of a local
/// neighbourhood).
struct QuadMesh {
  int num_vertices = 0;
  std::vector<std::array<int, 4>> quads;
  std::vector<int> twin;

  int num_faces() const { return static_cast<int>(quads.size()); }
  int origin(int h) const { return quads[static_cast<std::size_t>(h / 4)][static_cast<std::size_t>(h % 4)]; }
  int target(int h) const { return origin(next(h)); }
  static int next(int h) { return (h / 4) * 4 + (h % 4 + 1) % 4; }
  static int prev(int h) { return (h / 4) * 4 + (h % 4 + 3) % 4; }
  /// Half-edge leaving the same origin in the face counter-clockwise of h's face (-1 at a boundary).
  int ccw(int h) const {
    const int t = twin[static_cast<std::size_t>(prev(h))];
    return t < 0 ? -1 : t;
  }
  /// Half-edge leaving the same origin in the face clockwise of h's face (-1 at a boundary).
  int cw(int h) const {
    const int t = twin[static_cast<std::size_t>(h)];
    return t < 0 ? -1 : next(t);
  }
};

/// Fills twin from the quads. Throws std::logic_error if a directed edge occurs twice.
void build_twins(QuadMesh& m);

/// The quad control net of a PolyMesh whose faces are all quads (same vertex and face indices).
QuadMesh quad_mesh_from(const mesh::PolyMesh& mesh);

/// The one-ring of a face, unfolded into a disc: local face 0 is the face with local corners 0..3 =
/// its corners (rotation r: local corner i = quads[face][(i + r) % 4]); every face sharing a vertex with it
/// follows, one copy per position (a face met twice in a small closed net becomes two local faces).
/// `parent[v]` is the vertex of `m` that local vertex v copies. Numbering depends only on the combinatorics.
struct OneRing {
  QuadMesh mesh;
  std::vector<int> parent;
};
OneRing unfold_one_ring(const QuadMesh& m, int face, int rotation);

/// One Catmull–Clark step of a (local) quad mesh, vertices: vertex points (same indices), then edge points,
/// then face points; child 4f + k of face f is the quad at its corner k (vertex point of corner k, edge
/// point of edge k, face point, edge point of edge k-1), so child 4f + 0 keeps the parameter directions.
/// `weights` (fine × coarse) maps coarse to fine points. Vertices of the mesh's rim get garbage rows;
/// rows of vertices whose faces are all present are exact (boundary rule: VTX_BOUNDARY_EDGE_AND_CORNER).
struct Subdivided {
  QuadMesh mesh;
  Eigen::MatrixXd weights;
};
Subdivided subdivide(const QuadMesh& m);

}  // namespace iga::basis::catmull_clark
