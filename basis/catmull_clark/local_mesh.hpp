#pragma once
// The neighbourhood of one cell of a Catmull–Clark level, and its Catmull–Clark refinement, with every vertex and
// face named by a key that does not depend on which cells were refined (sparse_levels.hpp builds the levels of
// hierarchical Catmull–Clark from these, one cell at a time, instead of refining whole nets).
//
// Keys of level m (the extended net of the clamped rule has F faces and V vertices at level 0):
//   faces: level 0 its faces 0..F-1; the child in slot k of face f is 4 f + k (refine_net's numbering), so level m
//     has keys below F 4^m;
//   vertices: level 0 its vertices 0..V-1; a vertex of level m + 1 is the vertex point of a vertex of level m (the
//     same key), the edge point of an edge (vb_m + the smaller of 4 f + s over the edge's two faces f, side s) or
//     the face point of a face f (vb_m + 4 F_m + f), with vb_0 = V and vb_{m+1} = vb_m + 5 F_m.
// Child k of a face has native corner j at (c_k + c_j) / 2 of the face's native square (corners c_0..c_3 at
// (0,0), (1,0), (1,1), (0,1)): corner k is the vertex point of the face's corner k, corners k + 1 and k + 3 the
// edge points of its sides k and k + 3, corner k + 2 its face point (the frame of refine_net, levels.hpp).
#include <Eigen/Core>
#include <array>
#include <span>
#include <utility>
#include <vector>

#include "basis/hierarchical/level_hierarchy.hpp"

namespace iga::basis::catmull_clark {

using hierarchical::Key;

/// The bounds of the keys of each level: faces(m) = F 4^m, vertex_bound(m) = vb_m.
struct KeyBounds {
  std::vector<Key> faces, vertex_bound;
};
/// Bounds up to level `levels` (inclusive).
KeyBounds key_bounds(Index level0_faces, Index level0_vertices, int levels);

/// A vertex of level m + 1 by its origin in level m.
struct VertexOrigin {
  enum Kind { kVertex, kEdge, kFace } kind = kVertex;
  Key key = 0;   // the coarse vertex (kVertex) or face (kEdge, kFace)
  int side = 0;  // kEdge: the side of that face
};
VertexOrigin vertex_origin(const KeyBounds& b, int fine_level, Key vertex);

/// Faces of one level around a cell: the cell is face 0, and the others are those of the level sharing a vertex
/// with it that exist (all of them for a cell of the domain: the extended net's ghost ring covers its ring).
/// Corners in native order; orientation as in the net.
struct LocalMesh {
  std::vector<Key> vertex;                 // local vertex -> key
  std::vector<Key> face;                   // local face -> key
  std::vector<std::array<int, 4>> corner;  // local face -> local vertices
};

/// The Catmull–Clark refinement of a local mesh of level m: all four children of every face (child k of local
/// face f is local face 4 f + k), and per fine vertex its stencil on the coarse local vertices, empty where the
/// local mesh lacks faces the rule reads (a vertex point whose fan is open, an edge point of an edge with one face).
/// Fine vertices: the vertex points (fine v = coarse v), then the face points (fine nv + f), then the edge points.
struct RefinedMesh {
  LocalMesh mesh;
  std::vector<int> offsets;                      // fine vertex v: entries[offsets[v], offsets[v + 1])
  std::vector<std::pair<int, double>> entries;   // (coarse local vertex, weight)
  std::span<const std::pair<int, double>> stencil(int v) const {
    return {entries.data() + offsets[static_cast<std::size_t>(v)],
            static_cast<std::size_t>(offsets[static_cast<std::size_t>(v) + 1] - offsets[static_cast<std::size_t>(v)])};
  }
};
/// With `stencils` false only the topology and keys (offsets and entries stay empty).
RefinedMesh refine_local(const LocalMesh& coarse, const KeyBounds& b, int coarse_level, bool stencils = true);

/// The local mesh of fine face `face` of a refined mesh: it and the fine faces sharing a vertex with it.
LocalMesh extract_ring(const LocalMesh& fine, int face);

/// Faces around the vertices of face 0's corners, as numbers of faces at each corner (the valence there; a corner
/// whose fan is open in the local mesh counts the faces present).
std::array<int, 4> corner_valences(const LocalMesh& m);

/// The local mesh renumbered by a walk that sees only its topology: face 0 from corner `start`, then faces across
/// sides in order of discovery, each from the corner where it was entered. Two cells whose neighbourhoods have the
/// same topology get the same result. canonical[i] is the local vertex of canonical vertex i.
struct CanonicalMesh {
  std::vector<std::vector<Index>> faces;  // canonical vertices per face, face 0 first
  std::vector<int> canonical;             // canonical vertex -> local vertex
};
CanonicalMesh canonical_mesh(const LocalMesh& m, int start);

}  // namespace iga::basis::catmull_clark
