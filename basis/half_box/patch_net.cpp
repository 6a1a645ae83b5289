#include "basis/half_box/patch_net.hpp"

#include <algorithm>
#include <string>

#include "core/error.hpp"

namespace iga::basis::half_box {

namespace {

std::string vname(Index v) { return "vertex " + std::to_string(v + 1); }

// Targets of h, next(h), next(next(h)), ...: the vertices of face(h) counter-clockwise after origin(h).
std::vector<Index> face_walk(const mesh::PolyMesh& net, Index h) {
  std::vector<Index> r;
  const Index n = net.face_size(net.half_edge(h).face);
  for (Index i = 0; i + 1 < n; ++i, h = net.half_edge(h).next) r.push_back(net.half_edge_target(h));
  return r;
}

}  // namespace

PatchNet gather_patch(const mesh::PolyMesh& net, Index half_edge) {
  PatchNet p;
  const Index v = net.half_edge(half_edge).origin;
  p.vertex = v;
  if (net.valence(v) != 3 || net.is_boundary_vertex(v))
    throw InputError("half-box patch: " + vname(v) + " has " + std::to_string(net.valence(v)) + " edges" +
                     (net.is_boundary_vertex(v) ? " and lies on the boundary" : "") +
                     "; a patch needs an interior three-valent vertex");
  // F1 lies across the edge (v, origin(prev(h0))), F2 across (v, origin(prev(h1))) (counter-clockwise).
  const Index h0 = half_edge;
  const Index h1 = net.half_edge(net.half_edge(h0).prev).twin;
  const Index h2 = net.half_edge(net.half_edge(h1).prev).twin;
  p.faces = {net.half_edge(h0).face, net.half_edge(h1).face, net.half_edge(h2).face};
  p.valence = static_cast<int>(net.face_size(p.faces[0]));
  for (int i = 1; i < 3; ++i)
    if (net.face_size(p.faces[static_cast<std::size_t>(i)]) != 6)
      throw UnsupportedError("half-box patch: " + vname(v) + " touches more than one non-hexagonal face (faces " +
                             std::to_string(p.faces[0] + 1) + " and " +
                             std::to_string(p.faces[static_cast<std::size_t>(i)] + 1) +
                             "); subdivide the net once to separate the extraordinary faces");
  const std::vector<Index> f0 = face_walk(net, h0), f1 = face_walk(net, h1), f2 = face_walk(net, h2);
  if (p.valence == 6) {
    // f0 = u2, 4, 5, 6, u0;  f1 = u0, 7, 8, 9, u1;  f2 = u1, 10, 11, 12, u2.
    p.points = {v, f1[0], f2[0], f0[0], f0[1], f0[2], f0[3], f1[1], f1[2], f1[3], f2[1], f2[2], f2[3]};
  } else {
    p.points.push_back(v);
    p.points.insert(p.points.end(), f0.begin(), f0.end());          // 1..n−1
    p.points.insert(p.points.end(), f1.begin() + 1, f1.end());      // n..n+3
    p.points.insert(p.points.end(), f2.begin() + 1, f2.end() - 1);  // n+4..n+6
  }
  std::vector<Index> sorted = p.points;
  std::sort(sorted.begin(), sorted.end());
  const auto dup = std::adjacent_find(sorted.begin(), sorted.end());
  if (dup != sorted.end())
    throw InputError("half-box patch: the patch of " + vname(v) + " repeats " + vname(*dup) +
                     " (the net is too coarse around it)");
  return p;
}

PatchNet patch_net(const mesh::PolyMesh& net, Index vertex) {
  const Index start = net.vertex_half_edge(vertex);
  if (start < 0) throw InputError("half-box patch: " + vname(vertex) + " is not used by any face");
  if (net.valence(vertex) != 3 || net.is_boundary_vertex(vertex)) return gather_patch(net, start);
  Index h = start;
  for (int i = 0; i < 3; ++i) {
    if (net.face_size(net.half_edge(h).face) != 6) return gather_patch(net, h);
    h = net.half_edge(net.half_edge(h).prev).twin;
  }
  return gather_patch(net, start);
}

bool efs_separated(const mesh::PolyMesh& net) {
  for (Index v = 0; v < net.num_vertices(); ++v) {
    const Index start = net.vertex_half_edge(v);
    if (start < 0) continue;
    int irregular = 0;
    Index h = start;
    do {
      if (net.face_size(net.half_edge(h).face) != 6) ++irregular;
      const Index t = net.half_edge(net.half_edge(h).prev).twin;
      if (t < 0) break;
      h = t;
    } while (h != start);
    if (irregular > 1) return false;
  }
  return true;
}

}  // namespace iga::basis::half_box
