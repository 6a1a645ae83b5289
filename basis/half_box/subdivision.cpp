#include "basis/half_box/subdivision.hpp"

#include <cmath>
#include <numbers>
#include <string>

#include "core/error.hpp"

namespace iga::basis::half_box {

std::vector<double> s1_weights(int n) {
  if (n < 3) throw InputError("half-box S1: a face needs at least 3 vertices, got " + std::to_string(n));
  if (n == 6) return {0.5, 0.125, 0.125, 0.0, 0.125, 0.125};  // mask of H111 (Figure 3.8)
  std::vector<double> w(static_cast<std::size_t>(n));
  w[0] = 0.25 + 1.25 / n;  // (3.37), k = 0
  for (int j = 1; j < n; ++j) w[static_cast<std::size_t>(j)] = (3.0 + 2.0 * std::cos(2.0 * std::numbers::pi * j / n)) / (4.0 * n);
  return w;
}

namespace {

void check_valence(const mesh::PolyMesh& net, bool allow_fewer) {
  for (Index v = 0; v < net.num_vertices(); ++v) {
    const int k = net.valence(v);
    if (k == 0) continue;  // isolated vertex: no stencil involves it
    if (k > 3 || (!allow_fewer && k != 3))
      throw InputError("vertex " + std::to_string(v + 1) + " has " + std::to_string(k) +
                       " edges; half-box nets are three-valent");
  }
}

// The three neighbours of a vertex with three edges (rotating through twins; works at a boundary vertex
// whose three edges are all present, i.e. valence 3 with two faces).
std::vector<Index> neighbours(const mesh::PolyMesh& net, Index v) {
  std::vector<Index> r;
  const Index start = net.vertex_half_edge(v);
  // Walk clockwise (twin then next) from the outgoing half-edge; at a boundary the start is the boundary edge.
  Index h = start;
  while (true) {
    r.push_back(net.half_edge_target(h));
    const Index in = net.half_edge(h).prev;  // incoming to v in face(h)
    const Index t = net.half_edge(in).twin;
    if (t < 0) {
      r.push_back(net.half_edge(in).origin);  // the last edge of a boundary fan
      break;
    }
    h = t;
    if (h == start) break;
  }
  return r;
}

NetSubdivision subdivide_checked(const mesh::PolyMesh& net) {
  const Index nh = net.num_half_edges();
  NetSubdivision out;
  out.vertex_point.assign(static_cast<std::size_t>(net.num_vertices()), -1);
  out.edge_face.assign(static_cast<std::size_t>(nh), -1);
  std::vector<Eigen::Triplet<double>> triplets;
  // S1 corner points, one per half-edge (Figure 3.9 left/right).
  for (Index f = 0; f < net.num_faces(); ++f) {
    const int n = static_cast<int>(net.face_size(f));
    const std::vector<double> w = s1_weights(n);
    const auto verts = net.face(f);
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j)
        if (w[static_cast<std::size_t>(j)] != 0.0)
          triplets.emplace_back(net.face_half_edge(f) + i, verts[static_cast<std::size_t>((i + j) % n)],
                                w[static_cast<std::size_t>(j)]);
  }
  // S2 points of vertices with three edges (b = c = d = 1/4).
  Index next = nh;
  for (Index v = 0; v < net.num_vertices(); ++v) {
    if (net.valence(v) != 3) continue;
    const std::vector<Index> nb = neighbours(net, v);
    if (nb.size() != 3) continue;
    out.vertex_point[static_cast<std::size_t>(v)] = next;
    triplets.emplace_back(next, v, kS2Weight);
    for (Index w : nb) triplets.emplace_back(next, w, kS2Weight);
    ++next;
  }
  out.prolongation.resize(next, net.num_vertices());
  out.prolongation.setFromTriplets(triplets.begin(), triplets.end());

  std::vector<Eigen::Vector3d> points(static_cast<std::size_t>(next), Eigen::Vector3d::Zero());
  for (int k = 0; k < out.prolongation.outerSize(); ++k)
    for (Eigen::SparseMatrix<double>::InnerIterator it(out.prolongation, k); it; ++it)
      points[static_cast<std::size_t>(it.row())] += it.value() * net.point(it.col());
  std::vector<std::vector<Index>> faces;
  for (Index f = 0; f < net.num_faces(); ++f) {
    std::vector<Index> face;
    for (Index i = 0; i < net.face_size(f); ++i) face.push_back(net.face_half_edge(f) + i);
    faces.push_back(std::move(face));
  }
  // Edge hexagons [next(h), h, S2(v), next(t), t, S2(w)] for h: v → w, t = twin(h) (orientation of the
  // shrunk faces, which traverse h → next(h) and t → next(t)).
  for (Index h = 0; h < nh; ++h) {
    const mesh::HalfEdge& e = net.half_edge(h);
    if (e.twin < h) continue;  // boundary (−1) or already done
    const Index sv = out.vertex_point[static_cast<std::size_t>(e.origin)];
    const Index sw = out.vertex_point[static_cast<std::size_t>(net.half_edge_target(h))];
    if (sv < 0 || sw < 0) continue;
    const Index t = e.twin;
    out.edge_face[static_cast<std::size_t>(h)] = out.edge_face[static_cast<std::size_t>(t)] =
        static_cast<Index>(faces.size());
    faces.push_back({e.next, h, sv, net.half_edge(t).next, t, sw});
  }
  out.net = mesh::PolyMesh::build(std::move(points), std::move(faces));
  return out;
}

}  // namespace

NetSubdivision subdivide(const mesh::PolyMesh& net) {
  if (!net.is_closed()) {
    const Index h = net.boundary_loops().front().front();
    throw UnsupportedError("half-box subdivision: the net has a boundary (" +
                           std::to_string(net.boundary_loops().size()) + " loop(s), one through vertex " +
                           std::to_string(net.half_edge(h).origin + 1) +
                           "); boundary rules are not implemented");
  }
  check_valence(net, false);
  return subdivide_checked(net);
}

NetSubdivision subdivide_local(const mesh::PolyMesh& net) {
  check_valence(net, true);
  return subdivide_checked(net);
}

}  // namespace iga::basis::half_box
