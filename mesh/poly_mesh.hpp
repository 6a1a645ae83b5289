#pragma once
// Polygonal surface mesh with half-edge adjacency: the control mesh that subdivision-style and
// unstructured-spline constructions start from.
#include <Eigen/Core>
#include <span>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "core/types.hpp"

namespace iga::mesh {

/// One directed edge of one face. Half-edge indices are laid out face by face: the half-edges of face f
/// are face_half_edge(f) + i for i in [0, face_size(f)), the i-th one leaving vertex face(f)[i].
struct HalfEdge {
  Index origin = -1;  ///< vertex it starts at
  Index face = -1;    ///< face on its left (every half-edge belongs to a face; boundary = twin == -1)
  Index next = -1;    ///< next half-edge around the same face
  Index prev = -1;    ///< previous half-edge around the same face
  Index twin = -1;    ///< opposite half-edge in the neighbouring face, -1 on the boundary
};

/// What kind of topology problem a TopologyError describes (kOther: only the free-text reason is known).
enum class TopologyProblem {
  kOther,
  kNoFaces,
  kTooFewVertices,           ///< vertices() = the face's vertices
  kIndexOutOfRange,          ///< vertices() = {offending index}, count() = number of vertices
  kRepeatedVertex,           ///< vertices() = {repeated vertex}
  kNonManifoldEdge,          ///< vertices() = {a, b}, the edge as the face traverses it
  kInconsistentOrientation,  ///< vertices() = {a, b}, the edge as the face traverses it
  kNonManifoldVertex,        ///< vertices() = {vertex}, count() = number of fans
};

/// Topology problem found while building a PolyMesh. face() is the index of the offending face (-1 if none),
/// so a file reader can report the line where that face was read.
class TopologyError : public InputError {
 public:
  TopologyError(Index face, const std::string& reason);
  /// Structured form; the message is "face F: " + describe(0).
  TopologyError(Index face, TopologyProblem problem, std::vector<Index> vertices, Index count = 0);

  Index face() const { return face_; }
  TopologyProblem problem() const { return problem_; }
  const std::vector<Index>& vertices() const { return vertices_; }
  Index count() const { return count_; }
  /// The reason without the face, vertex indices shifted by index_base (1 for OBJ numbering).
  std::string describe(Index index_base) const;

 private:
  Index face_ = -1;
  TopologyProblem problem_ = TopologyProblem::kOther;
  std::vector<Index> vertices_;
  Index count_ = 0;
  std::string text_;  // the free-text reason (kOther)
};

/// A manifold polygonal surface (possibly with boundary) stored as flat face lists plus half-edges.
class PolyMesh {
 public:
  PolyMesh() = default;

  /// Builds half-edge adjacency for faces (any n-gons, vertex indices 0-based, listed counter-clockwise).
  /// Throws TopologyError for: a face with < 3 vertices; an index out of range; a vertex repeated in a face;
  /// a non-manifold edge (shared by > 2 faces: reports the third face); inconsistent orientation (two faces
  /// traverse a shared edge in the same direction: reports the second); a non-manifold vertex (its faces
  /// form more than one fan: reports the lowest face outside the fan of the vertex's lowest face); no faces.
  /// When several problems exist, per-face problems come first (lowest face), then edge problems (lowest
  /// reported face), then vertex problems (lowest reported face). Throws InputError for non-finite
  /// coordinates. Isolated vertices are allowed. O(total face size) plus small per-vertex sorts.
  static PolyMesh build(std::vector<Eigen::Vector3d> points, std::vector<std::vector<Index>> faces);

  Index num_vertices() const { return static_cast<Index>(points_.size()); }
  Index num_faces() const { return static_cast<Index>(face_offsets_.size()) - (face_offsets_.empty() ? 0 : 1); }
  Index num_half_edges() const { return static_cast<Index>(half_edges_.size()); }

  const Eigen::Vector3d& point(Index v) const { return points_[static_cast<std::size_t>(v)]; }
  const std::vector<Eigen::Vector3d>& points() const { return points_; }

  /// Vertex indices of face f in order.
  std::span<const Index> face(Index f) const;
  Index face_size(Index f) const;
  /// Half-edge of f whose origin is face(f)[0].
  Index face_half_edge(Index f) const { return face_offsets_[static_cast<std::size_t>(f)]; }
  /// An outgoing half-edge; for a boundary vertex the outgoing boundary half-edge (twin == -1); -1 if unused.
  Index vertex_half_edge(Index v) const { return vertex_half_edge_[static_cast<std::size_t>(v)]; }
  const HalfEdge& half_edge(Index h) const { return half_edges_[static_cast<std::size_t>(h)]; }
  /// Vertex the half-edge points to (= origin of next).
  Index half_edge_target(Index h) const { return half_edge(half_edge(h).next).origin; }

  /// Number of edges incident to v (0 if unused).
  int valence(Index v) const { return valence_[static_cast<std::size_t>(v)]; }
  /// Number of faces incident to v.
  int num_vertex_faces(Index v) const { return num_vertex_faces_[static_cast<std::size_t>(v)]; }
  bool is_boundary_vertex(Index v) const;
  /// No boundary half-edges.
  bool is_closed() const { return boundary_loops_.empty(); }

  /// Boundary loops: each a list of boundary half-edge indices (twin == -1) in order, following the boundary
  /// so that the mesh lies to the left; target(loop[k]) == origin(loop[k+1]). Loops are sorted by their
  /// smallest half-edge index, each starting at its smallest half-edge index.
  const std::vector<std::vector<Index>>& boundary_loops() const { return boundary_loops_; }

  /// All z coordinates are exactly 0.
  bool is_planar() const { return planar_; }

  /// Where the mesh came from, for messages in the user's words: the line of a file on which vertex v (face
  /// f) was read, 0 when unknown (a mesh made in memory, or refined from one). Set by the OBJ reader.
  void set_source_lines(std::vector<long> vertex_lines, std::vector<long> face_lines);
  long vertex_line(Index v) const;
  long face_line(Index f) const;

 private:
  std::vector<Eigen::Vector3d> points_;
  std::vector<Index> face_offsets_;  // size num_faces + 1
  std::vector<Index> face_indices_;  // concatenated face vertex lists
  std::vector<HalfEdge> half_edges_;
  std::vector<Index> vertex_half_edge_;
  std::vector<int> valence_;
  std::vector<int> num_vertex_faces_;
  std::vector<std::vector<Index>> boundary_loops_;
  bool planar_ = true;
  std::vector<long> vertex_lines_, face_lines_;
};

}  // namespace iga::mesh
