#include "basis/catmull_clark/ghost_net.hpp"

#include <vector>

#include "basis/catmull_clark/topology.hpp"
#include "core/error.hpp"

namespace iga::basis::catmull_clark {

namespace {

// Per boundary vertex: its boundary half-edges in and out (domain on the left).
struct BoundaryVertex {
  Index in = -1, out = -1;
};

// The ghost vertices of a boundary vertex: across its incoming edge, on the diagonal (corners only), across
// its outgoing edge; a smooth (or extraordinary) boundary vertex has one ghost for both edges.
struct Ghosts {
  Index in = -1, diagonal = -1, out = -1;
};

}  // namespace

ExtendedNet extend_net(const mesh::PolyMesh& net, const std::string& name) {
  check_no_isolated_vertices(net, name);
  const Index nv = net.num_vertices(), nf = net.num_faces();
  std::vector<BoundaryVertex> bv(static_cast<std::size_t>(nv));
  for (const auto& loop : net.boundary_loops()) {
    for (Index h : loop) {
      bv[static_cast<std::size_t>(net.half_edge(h).origin)].out = h;
      bv[static_cast<std::size_t>(net.half_edge_target(h))].in = h;
    }
  }
  // Interior neighbours (ends of edges with two faces) of every vertex.
  std::vector<Eigen::Vector3d> inner_sum(static_cast<std::size_t>(nv), Eigen::Vector3d::Zero());
  std::vector<int> inner_count(static_cast<std::size_t>(nv), 0);
  for (Index h = 0; h < net.num_half_edges(); ++h) {
    if (net.half_edge(h).twin < 0) continue;
    const Index v = net.half_edge(h).origin;
    inner_sum[static_cast<std::size_t>(v)] += net.point(net.half_edge_target(h));
    ++inner_count[static_cast<std::size_t>(v)];
  }
  std::vector<Eigen::Vector3d> points = net.points();
  std::vector<Ghosts> ghosts(static_cast<std::size_t>(nv));
  auto add = [&](const Eigen::Vector3d& p) {
    points.push_back(p);
    return static_cast<Index>(points.size()) - 1;
  };
  for (Index v = 0; v < nv; ++v) {
    const BoundaryVertex& b = bv[static_cast<std::size_t>(v)];
    if (b.out < 0) continue;
    const Eigen::Vector3d& c = net.point(v);
    Ghosts& g = ghosts[static_cast<std::size_t>(v)];
    if (net.num_vertex_faces(v) == 1) {
      // The corner's face runs c -> after -> opposite -> before (domain on the left).
      const Index after = net.half_edge_target(b.out), before = net.half_edge(b.in).origin;
      const Index opposite = net.half_edge(net.half_edge(b.out).next).next;
      const Eigen::Vector3d& d = net.point(net.half_edge(opposite).origin);
      g.in = add(2.0 * c - net.point(after));
      g.diagonal = add(4.0 * c - 2.0 * net.point(before) - 2.0 * net.point(after) + d);
      g.out = add(2.0 * c - net.point(before));
    } else {
      const int r = inner_count[static_cast<std::size_t>(v)];
      if (r == 0) throw std::logic_error("extend_net: a boundary vertex with several faces has no interior edge");
      g.in = g.out = add(2.0 * c - inner_sum[static_cast<std::size_t>(v)] / r);
    }
  }
  std::vector<std::vector<Index>> faces;
  faces.reserve(static_cast<std::size_t>(nf) + bv.size());
  for (Index f = 0; f < nf; ++f) {
    const auto fv = net.face(f);
    faces.emplace_back(fv.begin(), fv.end());
  }
  for (const auto& loop : net.boundary_loops()) {
    for (Index h : loop) {
      const Index a = net.half_edge(h).origin, b = net.half_edge_target(h);
      faces.push_back({b, a, ghosts[static_cast<std::size_t>(a)].out, ghosts[static_cast<std::size_t>(b)].in});
    }
  }
  for (Index v = 0; v < nv; ++v) {
    const Ghosts& g = ghosts[static_cast<std::size_t>(v)];
    if (g.diagonal >= 0) faces.push_back({v, g.in, g.diagonal, g.out});
  }
  const std::size_t total_faces = faces.size(), total_vertices = points.size();
  ExtendedNet out{mesh::PolyMesh::build(std::move(points), std::move(faces)), nf};
  std::vector<long> vertex_lines(total_vertices, 0), face_lines(total_faces, 0);
  for (Index v = 0; v < nv; ++v) vertex_lines[static_cast<std::size_t>(v)] = net.vertex_line(v);
  for (Index f = 0; f < nf; ++f) face_lines[static_cast<std::size_t>(f)] = net.face_line(f);
  out.mesh.set_source_lines(std::move(vertex_lines), std::move(face_lines));
  return out;
}

ExtendedRefinement refine_extended(const ExtendedNet& net, int steps) {
  ExtendedRefinement r{net, Eigen::SparseMatrix<double>(net.mesh.num_vertices(), net.mesh.num_vertices())};
  r.prolongation.setIdentity();
  for (int s = 0; s < steps; ++s) {
    const mesh::PolyMesh& coarse = r.net.mesh;
    Index domain_children = 0;
    for (Index f = 0; f < r.net.domain_faces; ++f) domain_children += coarse.face_size(f);
    NetRefinement fine = refine_net(coarse, 1);
    const mesh::PolyMesh& m = fine.mesh;
    std::vector<char> in_domain(static_cast<std::size_t>(m.num_vertices()), 0);
    for (Index f = 0; f < domain_children; ++f) {
      for (Index v : m.face(f)) in_domain[static_cast<std::size_t>(v)] = 1;
    }
    std::vector<Index> index(static_cast<std::size_t>(m.num_vertices()), -1);
    std::vector<std::vector<Index>> faces;
    for (Index f = 0; f < m.num_faces(); ++f) {
      const auto fv = m.face(f);
      bool keep = f < domain_children;
      for (Index v : fv) keep = keep || in_domain[static_cast<std::size_t>(v)] != 0;
      if (!keep) continue;
      faces.emplace_back(fv.begin(), fv.end());
      for (Index v : fv) index[static_cast<std::size_t>(v)] = 0;
    }
    std::vector<Eigen::Vector3d> points;
    for (Index v = 0; v < m.num_vertices(); ++v) {
      if (index[static_cast<std::size_t>(v)] < 0) continue;
      index[static_cast<std::size_t>(v)] = static_cast<Index>(points.size());
      points.push_back(m.point(v));
    }
    for (auto& f : faces) {
      for (Index& v : f) v = index[static_cast<std::size_t>(v)];
    }
    // The kept rows of this step's prolongation, then composed with the steps before (one sparse product).
    const Eigen::SparseMatrix<double, Eigen::RowMajor> rows = fine.prolongation;
    std::vector<Eigen::Triplet<double>> kept;
    kept.reserve(static_cast<std::size_t>(rows.nonZeros()));
    for (Index v = 0; v < m.num_vertices(); ++v) {
      const Index row = index[static_cast<std::size_t>(v)];
      if (row < 0) continue;
      for (Eigen::SparseMatrix<double, Eigen::RowMajor>::InnerIterator it(rows, v); it; ++it) kept.emplace_back(row, it.col(), it.value());
    }
    Eigen::SparseMatrix<double> step(static_cast<Index>(points.size()), coarse.num_vertices());
    step.setFromTriplets(kept.begin(), kept.end());
    r.prolongation = s == 0 ? step : Eigen::SparseMatrix<double>(step * r.prolongation);
    r.net = ExtendedNet{mesh::PolyMesh::build(std::move(points), std::move(faces)), domain_children};
  }
  return r;
}

}  // namespace iga::basis::catmull_clark
