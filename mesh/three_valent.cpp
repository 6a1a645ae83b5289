#include "mesh/three_valent.hpp"

#include <vector>

namespace iga::mesh {

namespace {

using Points = std::vector<Eigen::Vector3d>;
using Faces = std::vector<std::vector<Index>>;

std::size_t at(Index i) { return static_cast<std::size_t>(i); }

/// The input must be a triangle mesh in which every vertex gets a face of >= 3 sides in the net.
void require_triangles(const PolyMesh& m, const char* what) {
  if (m.num_faces() == 0) throw InputError(std::string(what) + ": the triangle mesh has no faces");
  for (Index f = 0; f < m.num_faces(); ++f) {
    if (m.face_size(f) != 3) {
      throw InputError("face " + std::to_string(f + 1) + " has " + std::to_string(m.face_size(f)) + " vertices; " +
                       what + " needs a triangle mesh");
    }
  }
  for (Index v = 0; v < m.num_vertices(); ++v) {
    const std::string name = "vertex " + std::to_string(v + 1);
    if (m.valence(v) == 0) throw InputError(name + " is in no triangle; " + what + " gives every vertex a face");
    if (!m.is_boundary_vertex(v) && m.valence(v) < 3) {
      throw InputError(name + " is interior with " + std::to_string(m.valence(v)) + " edges; its face in the " +
                       what + " would have fewer than 3 sides");
    }
  }
}

/// Outgoing half-edges of v in counter-clockwise order (h -> twin(prev(h))). For a boundary vertex the fan
/// starts at the outgoing boundary half-edge and ends at the half-edge whose prev is the incoming one.
std::vector<Index> outgoing_fan(const PolyMesh& m, Index v) {
  std::vector<Index> fan;
  const Index first = m.vertex_half_edge(v);
  Index h = first;
  do {
    fan.push_back(h);
    h = m.half_edge(m.half_edge(h).prev).twin;
  } while (h >= 0 && h != first);
  return fan;
}

/// Appends, loop by loop, every boundary half-edge's origin and then (with_midpoints) its midpoint; fills the
/// net index of each boundary vertex (by input vertex) and of each boundary half-edge's midpoint.
void append_boundary(const PolyMesh& m, bool with_midpoints, Points& points, std::vector<Index>& vertex_index,
                     std::vector<Index>& midpoint_index) {
  vertex_index.assign(at(m.num_vertices()), -1);
  midpoint_index.assign(at(m.num_half_edges()), -1);
  for (const std::vector<Index>& loop : m.boundary_loops()) {
    for (Index h : loop) {
      const Eigen::Vector3d& a = m.point(m.half_edge(h).origin);
      vertex_index[at(m.half_edge(h).origin)] = static_cast<Index>(points.size());
      points.push_back(a);
      if (with_midpoints) {
        midpoint_index[at(h)] = static_cast<Index>(points.size());
        points.push_back((a + m.point(m.half_edge_target(h))) / 2.0);
      }
    }
  }
}

}  // namespace

PolyMesh dual_net(const PolyMesh& triangles) {
  const PolyMesh& m = triangles;
  require_triangles(m, "dual net");
  Points points;
  points.reserve(at(m.num_faces()));
  for (Index t = 0; t < m.num_faces(); ++t) {
    const std::span<const Index> f = m.face(t);
    points.push_back((m.point(f[0]) + m.point(f[1]) + m.point(f[2])) / 3.0);  // vertex centroid
  }
  std::vector<Index> vertex_index, midpoint_index;
  append_boundary(m, true, points, vertex_index, midpoint_index);

  Faces faces(at(m.num_vertices()));
  for (Index v = 0; v < m.num_vertices(); ++v) {
    const std::vector<Index> fan = outgoing_fan(m, v);
    std::vector<Index>& face = faces[at(v)];
    const bool boundary = m.is_boundary_vertex(v);
    if (boundary) face.push_back(midpoint_index[at(fan.front())]);
    for (Index h : fan) face.push_back(m.half_edge(h).face);
    if (boundary) {
      face.push_back(midpoint_index[at(m.half_edge(fan.back()).prev)]);
      face.push_back(vertex_index[at(v)]);
    }
  }
  return PolyMesh::build(std::move(points), std::move(faces));
}

PolyMesh trisect_net(const PolyMesh& triangles) {
  const PolyMesh& m = triangles;
  require_triangles(m, "trisection");
  // Edge of each half-edge, numbered by first half-edge; `along` = the half-edge runs along its edge.
  std::vector<Index> edge(at(m.num_half_edges()));
  std::vector<bool> along(at(m.num_half_edges()));
  Points points;
  for (Index h = 0; h < m.num_half_edges(); ++h) {
    const Index twin = m.half_edge(h).twin;
    along[at(h)] = twin < 0 || twin > h;
    if (!along[at(h)]) {
      edge[at(h)] = edge[at(twin)];
      continue;
    }
    edge[at(h)] = static_cast<Index>(points.size()) / 2;
    const Eigen::Vector3d& a = m.point(m.half_edge(h).origin);
    const Eigen::Vector3d& b = m.point(m.half_edge_target(h));
    points.push_back((2.0 * a + b) / 3.0);
    points.push_back((a + 2.0 * b) / 3.0);
  }
  const auto near_origin = [&](Index h) { return 2 * edge[at(h)] + (along[at(h)] ? 0 : 1); };
  const auto near_target = [&](Index h) { return 2 * edge[at(h)] + (along[at(h)] ? 1 : 0); };
  std::vector<Index> vertex_index, unused;
  append_boundary(m, false, points, vertex_index, unused);

  Faces faces(at(m.num_vertices() + m.num_faces()));
  for (Index v = 0; v < m.num_vertices(); ++v) {
    const std::vector<Index> fan = outgoing_fan(m, v);
    std::vector<Index>& face = faces[at(v)];
    for (Index h : fan) face.push_back(near_origin(h));
    if (m.is_boundary_vertex(v)) {
      face.push_back(near_target(m.half_edge(fan.back()).prev));
      face.push_back(vertex_index[at(v)]);
    }
  }
  for (Index t = 0; t < m.num_faces(); ++t) {
    std::vector<Index>& face = faces[at(m.num_vertices() + t)];
    for (Index i = 0; i < 3; ++i) {
      const Index h = m.face_half_edge(t) + i;
      face.push_back(near_origin(h));
      face.push_back(near_target(h));
    }
  }
  return PolyMesh::build(std::move(points), std::move(faces));
}

void check_three_valent(const PolyMesh& net, const std::string& file) {
  for (Index v = 0; v < net.num_vertices(); ++v) {
    const int k = net.valence(v);
    if (k == 3 || (k == 2 && net.is_boundary_vertex(v))) continue;
    throw InputError(file, 0,
                     "vertex " + std::to_string(v + 1) + " has " + std::to_string(k) +
                         " edges; a half-box net must be three-valent");
  }
}

}  // namespace iga::mesh
