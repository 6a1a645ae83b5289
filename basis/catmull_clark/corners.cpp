// Corner vertices of the clamped Catmull–Clark boundary (corners.hpp).
#include "basis/catmull_clark/corners.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <vector>

#include "basis/catmull_clark/eigen_structure.hpp"
#include "basis/catmull_clark/space.hpp"
#include "basis/catmull_clark/subdivision_matrix.hpp"
#include "basis/geometry.hpp"
#include "core/error.hpp"

namespace iga::basis::catmull_clark {
namespace {

// The one ring of an interior vertex of the extended net in Stam's local order (subdivision_matrix.hpp): the
// vertex, then per edge k its edge neighbour (2k+1) and the vertex opposite in the quad between edges k and k+1
// (2k+2), counter-clockwise; ghost[k]: that quad is a ghost face.
struct Ring {
  std::vector<Index> points;
  std::vector<bool> ghost;
  int valence() const { return static_cast<int>(ghost.size()); }
};

Ring one_ring(const mesh::PolyMesh& net, Index v, Index domain_faces) {
  Ring r;
  r.points.push_back(v);
  const Index h0 = net.vertex_half_edge(v);
  Index h = h0;
  do {
    const mesh::HalfEdge& he = net.half_edge(h);
    if (net.face_size(he.face) != 4) throw std::logic_error("catmull_clark: a corner's face is not a quad");
    r.points.push_back(net.half_edge_target(h));
    r.points.push_back(net.half_edge_target(he.next));
    r.ghost.push_back(he.face >= domain_faces);
    h = net.half_edge(he.prev).twin;
    if (h < 0) throw std::logic_error("catmull_clark: a boundary vertex of the net is on the extended net's boundary");
  } while (h != h0);
  return r;
}

double cross(const Eigen::Vector2d& a, const Eigen::Vector2d& b) { return a.x() * b.y() - a.y() * b.x(); }

// The local indices of the two boundary edges' neighbours (a, b) and of the ghost edge's (g) in a corner's ring:
// edge k lies between the quads k - 1 and k.
struct CornerEdges {
  int a = -1, b = -1, g = -1;
};
CornerEdges corner_edges(const Ring& r) {
  const int n = r.valence();
  CornerEdges c;
  for (int k = 0; k < n; ++k) {
    const bool before = r.ghost[static_cast<std::size_t>((k + n - 1) % n)], after = r.ghost[static_cast<std::size_t>(k)];
    if (before && after) c.g = 2 * k + 1;
    if (before != after) (c.a < 0 ? c.a : c.b) = 2 * k + 1;
  }
  if (c.a < 0 || c.b < 0 || c.g < 0) throw std::logic_error("catmull_clark: a corner's ring has no ghost edge");
  return c;
}

// Moves the control points of the ring's vertex and ghost neighbour (rows of cp) so that the limit point is the
// vertex's position and the limit tangents along the two boundary edges point along them (corners.hpp).
void place_corner(const Ring& r, bool reflex, Eigen::MatrixXd& cp, const std::string& where) {
  const int n = r.valence();
  const CornerEdges c = corner_edges(r);
  const EigenStructure es = eigen_structure(n, subdivision_matrix(n));
  const auto at = [&](int local) -> Eigen::Vector2d { return cp.row(r.points[static_cast<std::size_t>(local)]).transpose(); };
  const Eigen::Vector2d v = at(0);
  // Stencil of the limit point (row 0) or of the limit tangent along the edge of neighbour `local` (rows 1, 2).
  const auto stencil = [&](int row_or_edge, int i) {
    if (row_or_edge < 0) return es.inverse(0, i);
    const double theta = 2.0 * std::numbers::pi * ((row_or_edge - 1) / 2) / n;
    return std::cos(theta) * es.inverse(1, i) + std::sin(theta) * es.inverse(2, i);
  };
  const auto known = [&](int row_or_edge) {  // the stencil applied to every point but the two unknowns
    Eigen::Vector2d s = Eigen::Vector2d::Zero();
    for (int i = 1; i <= 2 * n; ++i) {
      if (i != c.g) s += stencil(row_or_edge, i) * at(i);
    }
    return s;
  };
  Eigen::Matrix4d m = Eigen::Matrix4d::Zero();
  Eigen::Vector4d rhs;
  // Limit point = v: rows 0, 1 (x and y).
  for (int d = 0; d < 2; ++d) {
    m(d, d) = stencil(-1, 0);
    m(d, 2 + d) = stencil(-1, c.g);
  }
  rhs.head<2>() = v - known(-1);
  // Tangent along edge e parallel to its direction: cross(t_e, dir) = 0, rows 2, 3.
  const int edges[2] = {c.a, c.b};
  for (int row = 0; row < 2; ++row) {
    const Eigen::Vector2d dir = at(edges[row]) - v;
    const auto coefficients = [&](double w, int col) {
      m(2 + row, col) = w * dir.y();
      m(2 + row, col + 1) = -w * dir.x();
    };
    coefficients(stencil(edges[row], 0), 0);
    coefficients(stencil(edges[row], c.g), 2);
    rhs(2 + row) = -cross(known(edges[row]), dir);
  }
  const Eigen::Vector2d da = at(c.a) - v, db = at(c.b) - v;
  if (std::abs(cross(da, db)) <= 1e-9 * da.norm() * db.norm()) {
    throw InputError(where + "its two boundary edges are collinear: there is no corner to keep");
  }
  // With k >= 3 faces the domain is k of the k + 2 sectors of the characteristic map, a reflex angle, which the
  // linear part of the map keeps reflex (it maps the convex complement onto a convex one): the corner must be.
  if (!reflex) {
    throw InputError(where + "a convex corner with " + std::to_string(n - 2) + " faces: the clamped space's limit domain "
                     "is reflex at a boundary vertex with three or more faces (a convex corner needs one face)");
  }
  const Eigen::FullPivLU<Eigen::Matrix4d> lu(m);
  if (!lu.isInvertible()) throw InputError(where + "no ghost position makes the limit boundary pass through it with the edges' directions");
  const Eigen::Vector4d z = lu.solve(rhs);
  cp.row(r.points[0]) = z.head<2>().transpose();
  cp.row(r.points[static_cast<std::size_t>(c.g)]) = z.tail<2>().transpose();
  for (int e : edges) {
    Eigen::Vector2d t = Eigen::Vector2d::Zero();
    for (int i = 0; i <= 2 * n; ++i) t += stencil(e, i) * at(i);
    if (t.dot(at(e) - v) <= 0) {
      throw InputError(where + "the limit boundary can meet it along its edges' directions only with a fold (the corner's "
                       "angle against its " + std::to_string(n - 2) + " faces)");
    }
  }
}

}  // namespace

Geometry with_corners(const Geometry& geometry, std::span<const Index> corners, const std::string& name) {
  const auto* cc = dynamic_cast<const CatmullClarkSpace*>(&geometry.space());
  if (!cc) throw std::logic_error("catmull_clark: with_corners needs a Catmull–Clark geometry");
  if (corners.empty()) return geometry;
  if (cc->boundary_rule() != BoundaryRule::kClamped) {
    throw UnsupportedError("corner vertices need the clamped boundary rule (--cc-boundary clamped): the natural rule has "
                           "no corner rule for a boundary vertex with several faces");
  }
  if (cc->refinement_steps() > 0) {
    throw UnsupportedError("corner vertices on a net that needs a global Catmull–Clark step (faces that are not quads, or "
                           "faces touching several extraordinary vertices): refine the net first");
  }
  if (geometry.dim() != 2) throw UnsupportedError("corner vertices on a surface net (3D): planar nets only");
  const mesh::PolyMesh& net = cc->control_mesh();
  const mesh::PolyMesh& domain = cc->domain_mesh();
  Eigen::MatrixXd cp = geometry.control_points();
  Index net_vertices = 0;  // the net's own vertices come first in the extended net (the ghosts have no domain face)
  while (net_vertices < domain.num_vertices() && domain.num_vertex_faces(net_vertices) > 0) ++net_vertices;
  // The corners are placed one after the other: each moves its vertex and its ghost, which lie in no other corner's
  // one ring (they would share a face of the extended net, so the two extraordinary vertices a domain face or a
  // boundary edge, and the net would have needed the global step refused above).
  std::vector<Index> unique(corners.begin(), corners.end());  // a vertex named twice is one corner
  std::sort(unique.begin(), unique.end());
  unique.erase(std::unique(unique.begin(), unique.end()), unique.end());
  for (const Index v : unique) {
    const std::string where = "vertex " + std::to_string(v + 1) + ": ";
    if (v < 0 || v >= net_vertices) {
      throw InputError(name + ": corner vertex " + std::to_string(v + 1) + " is not a vertex of the net (it has " +
                       std::to_string(net_vertices) + ")");
    }
    if (!domain.is_boundary_vertex(v)) throw InputError(name, net.vertex_line(v), where + "a corner must be on the boundary");
    const int faces = domain.num_vertex_faces(v);
    if (faces == 1) continue;  // a corner of the clamped rule already
    if (faces == 2) {
      throw UnsupportedError(name + ":" + std::to_string(net.vertex_line(v)) + ": " + where +
                             "a boundary vertex with two faces is a regular point of the clamped space (valence 4 in the "
                             "extended net), where the limit boundary is smooth: a corner needs one face, or three or more");
    }
    Ring r = one_ring(net, v, cc->num_elements());
    // The domain lies left of its boundary: the angle from the outgoing boundary edge (to w) round to the incoming
    // one (from u) is reflex when u lies to the right of v -> w.
    const Index w = domain.half_edge_target(domain.vertex_half_edge(v));
    const CornerEdges ce = corner_edges(r);
    const Index u = r.points[static_cast<std::size_t>(ce.a)] == w ? r.points[static_cast<std::size_t>(ce.b)]
                                                                   : r.points[static_cast<std::size_t>(ce.a)];
    const Eigen::Vector2d pv = cp.row(v).transpose();
    const bool reflex = cross(Eigen::Vector2d(cp.row(w).transpose()) - pv, Eigen::Vector2d(cp.row(u).transpose()) - pv) < 0;
    place_corner(r, reflex, cp, name + ":" + std::to_string(net.vertex_line(v)) + ": " + where);
  }
  return Geometry(geometry.space_ptr(), std::move(cp));
}

}  // namespace iga::basis::catmull_clark
