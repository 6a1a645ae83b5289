// Three-valent nets from triangle meshes (thesis Appendix B.1): the geometric dual and the trisection.
// Counts are checked against closed forms in the input's V, E, F and boundary edges B (mesh/three_valent.hpp);
// positions against exact values (centroids of an equilateral lattice, trisection points of integer
// triangles, midpoints on the square's sides).
#include "support/paths.hpp"
#include <gtest/gtest.h>

#include <cmath>
#include <Eigen/Geometry>
#include <functional>

#include "mesh/obj_reader.hpp"
#include "mesh/three_valent.hpp"

using namespace iga;
using mesh::PolyMesh;

namespace {

PolyMesh load(const std::string& name) { return mesh::read_obj(std::string(IGA_SOURCE_DIR) + "/data/meshes/" + name); }

Index num_boundary_edges(const PolyMesh& m) {
  Index b = 0;
  for (Index h = 0; h < m.num_half_edges(); ++h) b += m.half_edge(h).twin < 0;
  return b;
}
Index num_edges(const PolyMesh& m) { return (m.num_half_edges() + num_boundary_edges(m)) / 2; }
Index euler(const PolyMesh& m) { return m.num_vertices() - num_edges(m) + m.num_faces(); }

Eigen::Vector3d face_centroid(const PolyMesh& m, Index f) {
  Eigen::Vector3d c = Eigen::Vector3d::Zero();
  for (Index v : m.face(f)) c += m.point(v);
  return c / static_cast<double>(m.face_size(f));
}

/// Newell normal (twice the vector area) of face f.
Eigen::Vector3d face_area_vector(const PolyMesh& m, Index f) {
  Eigen::Vector3d n = Eigen::Vector3d::Zero();
  const std::span<const Index> face = m.face(f);
  for (std::size_t i = 0; i < face.size(); ++i) n += m.point(face[i]).cross(m.point(face[(i + 1) % face.size()]));
  return n;
}

/// Every interior vertex on 3 edges, every boundary vertex on 2 or 3.
bool three_valent(const PolyMesh& m) {
  for (Index v = 0; v < m.num_vertices(); ++v) {
    const int k = m.valence(v);
    if (k != 3 && !(k == 2 && m.is_boundary_vertex(v))) return false;
  }
  return true;
}

/// The message of the InputError f throws ("" if none).
std::string error_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

/// Equilateral triangle lattice with unit edges on the n x n parallelogram (i, j) -> i e1 + j e2,
/// e1 = (1, 0), e2 = (1/2, sqrt(3)/2); vertex i + (n + 1) j.
PolyMesh equilateral_lattice(int n) {
  std::vector<Eigen::Vector3d> points;
  for (int j = 0; j <= n; ++j) {
    for (int i = 0; i <= n; ++i) points.emplace_back(i + 0.5 * j, std::sqrt(3.0) / 2.0 * j, 0.0);
  }
  const auto id = [n](int i, int j) { return static_cast<Index>(i + (n + 1) * j); };
  std::vector<std::vector<Index>> faces;
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i < n; ++i) {
      faces.push_back({id(i, j), id(i + 1, j), id(i, j + 1)});
      faces.push_back({id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)});
    }
  }
  return PolyMesh::build(points, faces);
}

PolyMesh octahedron() {
  std::vector<Eigen::Vector3d> p = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  return PolyMesh::build(p, {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4}, {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}});
}

/// Closed-form counts of the dual (mesh/three_valent.hpp), its face sizes and its three-valence.
void expect_dual_counts(const PolyMesh& m, const PolyMesh& d) {
  const Index b = num_boundary_edges(m);
  EXPECT_EQ(d.num_vertices(), m.num_faces() + 2 * b);
  EXPECT_EQ(num_edges(d), num_edges(m) + 2 * b);
  EXPECT_EQ(d.num_faces(), m.num_vertices());
  EXPECT_EQ(euler(d), euler(m));
  EXPECT_EQ(d.boundary_loops().size(), m.boundary_loops().size());
  EXPECT_TRUE(three_valent(d));
  for (Index k = 0; k < m.num_vertices(); ++k) {
    EXPECT_EQ(d.face_size(k), m.valence(k) + (m.is_boundary_vertex(k) ? 2 : 0)) << "face " << k;
  }
}

/// Closed-form counts of the trisection, its face sizes and its three-valence.
void expect_trisection_counts(const PolyMesh& m, const PolyMesh& t) {
  const Index b = num_boundary_edges(m);
  EXPECT_EQ(t.num_vertices(), 2 * num_edges(m) + b);
  EXPECT_EQ(num_edges(t), num_edges(m) + 3 * m.num_faces() + 2 * b);
  EXPECT_EQ(t.num_faces(), m.num_vertices() + m.num_faces());
  EXPECT_EQ(euler(t), euler(m));
  EXPECT_TRUE(three_valent(t));
  for (Index k = 0; k < m.num_vertices(); ++k) {
    EXPECT_EQ(t.face_size(k), m.valence(k) + (m.is_boundary_vertex(k) ? 1 : 0)) << "face " << k;
  }
  for (Index f = m.num_vertices(); f < t.num_faces(); ++f) EXPECT_EQ(t.face_size(f), 6);
}

/// Number of faces of the dual around interior input vertices with `sides` sides.
int interior_faces_with(const PolyMesh& m, const PolyMesh& d, int sides) {
  int count = 0;
  for (Index k = 0; k < m.num_vertices(); ++k) count += !m.is_boundary_vertex(k) && d.face_size(k) == sides;
  return count;
}

/// Edges of the dual shared by two non-hexagonal faces around interior input vertices.
int adjacent_interior_non_hexagons(const PolyMesh& m, const PolyMesh& d) {
  const auto odd = [&](Index f) { return !m.is_boundary_vertex(f) && d.face_size(f) != 6; };
  int count = 0;
  for (Index h = 0; h < d.num_half_edges(); ++h) {
    const Index t = d.half_edge(h).twin;
    count += t > h && odd(d.half_edge(h).face) && odd(d.half_edge(t).face);
  }
  return count;
}

}  // namespace

TEST(DualNet, OctahedronGivesTheCube) {
  const PolyMesh m = octahedron();
  const PolyMesh d = mesh::dual_net(m);
  expect_dual_counts(m, d);  // V' = 8, E' = 12, F' = 6 quadrilaterals
  EXPECT_EQ(d.num_vertices(), 8);
  for (Index v = 0; v < d.num_vertices(); ++v) {
    for (int c = 0; c < 3; ++c) EXPECT_EQ(std::abs(d.point(v)[c]), 1.0 / 3.0);  // (±1 + 0 + 0) / 3, exact
  }
  for (Index k = 0; k < d.num_faces(); ++k) {
    // Face k surrounds vertex k: its centroid is (1/3) e_k exactly up to rounding, its normal points outward.
    EXPECT_NEAR((face_centroid(d, k) - m.point(k) / 3.0).norm(), 0.0, 1e-16);
    EXPECT_GT(face_area_vector(d, k).dot(m.point(k)), 0.0);
  }
}

TEST(DualNet, FaceSurroundsItsVertexInARegularLattice) {
  const PolyMesh m = equilateral_lattice(4);
  const PolyMesh d = mesh::dual_net(m);
  expect_dual_counts(m, d);
  EXPECT_TRUE(d.is_planar());
  int interior = 0;
  for (Index k = 0; k < m.num_vertices(); ++k) {
    EXPECT_GT(face_area_vector(d, k).z(), 0.0) << "face " << k;  // counter-clockwise in the plane
    if (m.is_boundary_vertex(k)) continue;
    ++interior;
    // A regular hexagon centred at vertex k: centroid = vertex, corners at the circumradius 1/sqrt(3) of a
    // unit equilateral triangle; 4e-15 is a few roundings (ulp 8.9e-16) of coordinates <= 6.
    EXPECT_NEAR((face_centroid(d, k) - m.point(k)).norm(), 0.0, 4e-15);
    for (Index v : d.face(k)) EXPECT_NEAR((d.point(v) - m.point(k)).norm(), 1.0 / std::sqrt(3.0), 4e-15);
  }
  EXPECT_EQ(interior, 9);  // (4 - 1)^2
}

TEST(DualNet, SquareBoundaryIsKept) {
  const PolyMesh m = load("tri_square.obj");
  ASSERT_EQ(m.num_vertices(), 81);
  ASSERT_EQ(m.num_faces(), 128);
  ASSERT_EQ(num_boundary_edges(m), 32);
  const PolyMesh d = mesh::dual_net(m);
  expect_dual_counts(m, d);
  EXPECT_EQ(d.num_vertices(), 192);  // 128 + 2 * 32
  EXPECT_EQ(num_edges(d), 272);      // 208 + 2 * 32
  EXPECT_EQ(euler(d), 1);
  EXPECT_TRUE(d.is_planar());
  ASSERT_EQ(d.boundary_loops().size(), 1u);
  const std::vector<Index>& loop = d.boundary_loops()[0];
  EXPECT_EQ(loop.size(), 64u);
  int corners = 0;
  for (Index h : loop) {
    const Eigen::Vector3d& p = d.point(d.half_edge(h).origin);
    EXPECT_TRUE(p.x() == 0.0 || p.x() == 1.0 || p.y() == 0.0 || p.y() == 1.0) << p.transpose();  // exact
    corners += (p.x() == 0.0 || p.x() == 1.0) && (p.y() == 0.0 || p.y() == 1.0);
  }
  EXPECT_EQ(corners, 4);
  for (Index f = 0; f < d.num_faces(); ++f) EXPECT_GT(face_area_vector(d, f).z(), 0.0) << "face " << f;
}

TEST(DualNet, DataMeshesHaveSeparatedPentagonsAndHeptagons) {
  struct Case {
    const char* name;
    Index v, f;
    int pentagons, heptagons;
  };
  // Counts from tools/make_meshes.py's construction (flipped cell rectangles, icosahedron split twice).
  for (const Case& c : {Case{"tri_square.obj", 81, 128, 2, 2}, Case{"tri_l_shape.obj", 65, 96, 4, 4},
                        Case{"tri_sphere.obj", 162, 320, 12, 0}, Case{"tri_torus.obj", 72, 144, 0, 0}}) {
    SCOPED_TRACE(c.name);
    const PolyMesh m = load(c.name);
    ASSERT_EQ(m.num_vertices(), c.v);
    ASSERT_EQ(m.num_faces(), c.f);
    const PolyMesh d = mesh::dual_net(m);
    expect_dual_counts(m, d);
    EXPECT_NO_THROW(mesh::check_three_valent(d, c.name));
    EXPECT_EQ(interior_faces_with(m, d, 5), c.pentagons);
    EXPECT_EQ(interior_faces_with(m, d, 7), c.heptagons);
    Index interior = 0;
    for (Index k = 0; k < m.num_vertices(); ++k) interior += !m.is_boundary_vertex(k);
    EXPECT_EQ(interior_faces_with(m, d, 6), interior - c.pentagons - c.heptagons);
    EXPECT_EQ(adjacent_interior_non_hexagons(m, d), 0);
  }
}

TEST(DualNet, ClosedSurfaces) {
  const PolyMesh sphere = load("tri_sphere.obj");
  const PolyMesh d = mesh::dual_net(sphere);
  EXPECT_TRUE(d.is_closed());
  EXPECT_EQ(d.num_vertices(), 320);  // V' = F
  EXPECT_EQ(num_edges(d), 480);      // E' = E
  EXPECT_EQ(d.num_faces(), 162);     // F' = V
  EXPECT_EQ(euler(d), 2);
  for (Index k = 0; k < d.num_faces(); ++k) EXPECT_GT(face_area_vector(d, k).dot(sphere.point(k)), 0.0);
  const PolyMesh torus = mesh::dual_net(load("tri_torus.obj"));
  EXPECT_EQ(torus.num_vertices(), 144);
  EXPECT_EQ(num_edges(torus), 216);
  EXPECT_EQ(torus.num_faces(), 72);
  EXPECT_EQ(euler(torus), 0);
}

TEST(TrisectNet, SingleTriangleExactPoints) {
  const PolyMesh m = PolyMesh::build({{0, 0, 0}, {3, 0, 0}, {0, 3, 0}}, {{0, 1, 2}});
  const PolyMesh t = mesh::trisect_net(m);
  expect_trisection_counts(m, t);  // V' = 9, E' = 12, F' = 4: three corner triangles and the hexagon
  EXPECT_EQ(t.num_vertices(), 9);
  // Edge 0 is (0,0)-(3,0): its points (2a + b) / 3 = (1,0) and (a + 2b) / 3 = (2,0), exact.
  EXPECT_EQ(t.point(0), Eigen::Vector3d(1, 0, 0));
  EXPECT_EQ(t.point(1), Eigen::Vector3d(2, 0, 0));
  const std::vector<Index> corner = {0, 5, 6};  // face 0: near vertex 0, then vertex 0 itself (net vertex 6)
  EXPECT_EQ(std::vector<Index>(t.face(0).begin(), t.face(0).end()), corner);
  EXPECT_EQ(t.point(6), m.point(0));
  for (Index f = 0; f < t.num_faces(); ++f) EXPECT_GT(face_area_vector(t, f).z(), 0.0);
}

TEST(TrisectNet, CountsAndThreeValence) {
  struct Case {
    const char* name;
    Index v, e, f, boundary;
  };
  for (const Case& c : {Case{"tri_square.obj", 448, 656, 209, 32}, Case{"tri_l_shape.obj", 352, 512, 161, 32},
                        Case{"tri_sphere.obj", 960, 1440, 482, 0}, Case{"tri_torus.obj", 432, 648, 216, 0}}) {
    SCOPED_TRACE(c.name);
    const PolyMesh m = load(c.name);
    const PolyMesh t = mesh::trisect_net(m);
    expect_trisection_counts(m, t);
    // Closed: V' = 2E, E' = 3E, F' = V + F; with boundary: V' = 2E + B, E' = E + 3F + 2B.
    EXPECT_EQ(t.num_vertices(), c.v);
    EXPECT_EQ(num_edges(t), c.e);
    EXPECT_EQ(t.num_faces(), c.f);
    EXPECT_EQ(num_boundary_edges(t), 3 * c.boundary);
    EXPECT_EQ(t.is_planar(), m.is_planar());
    EXPECT_NO_THROW(mesh::check_three_valent(t, c.name));
    for (Index f = 0; f < t.num_faces() && m.is_planar(); ++f) {
      EXPECT_GT(face_area_vector(t, f).z(), 0.0) << "face " << f;  // counter-clockwise, reflex corner too
    }
  }
  const PolyMesh o = octahedron();
  expect_trisection_counts(o, mesh::trisect_net(o));  // the truncated octahedron: 24, 36, 14
}

TEST(CheckThreeValent, NamesTheLowestOffendingVertex) {
  // 2 x 2 quads: the centre (vertex 5 in OBJ numbering) has 4 edges; the boundary has 2 and 3.
  std::vector<Eigen::Vector3d> p;
  for (int j = 0; j < 3; ++j) {
    for (int i = 0; i < 3; ++i) p.emplace_back(i, j, 0);
  }
  const PolyMesh quads = PolyMesh::build(p, {{0, 1, 4, 3}, {1, 2, 5, 4}, {3, 4, 7, 6}, {4, 5, 8, 7}});
  EXPECT_EQ(error_of([&] { mesh::check_three_valent(quads, "net.obj"); }),
            "net.obj:0: vertex 5 has 4 edges; a half-box net must be three-valent");
  try {
    mesh::check_three_valent(quads, "net.obj");
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), "net.obj");
    EXPECT_EQ(e.line(), 0);
  }
  // A boundary vertex with 4 edges (a fan of three triangles) fails too.
  const PolyMesh fan = PolyMesh::build({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {-1, 1, 0}},
                                       {{0, 1, 2}, {0, 2, 3}, {0, 3, 4}});
  EXPECT_EQ(error_of([&] { mesh::check_three_valent(fan, "fan"); }),
            "fan:0: vertex 1 has 4 edges; a half-box net must be three-valent");
  // An isolated vertex (appended as vertex 4) has 0 edges.
  const PolyMesh lonely = PolyMesh::build({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {5, 5, 0}}, {{0, 1, 2}});
  EXPECT_EQ(error_of([&] { mesh::check_three_valent(lonely, "t"); }),
            "t:0: vertex 4 has 0 edges; a half-box net must be three-valent");
  EXPECT_EQ(error_of([&] { mesh::check_three_valent(mesh::dual_net(octahedron()), "cube"); }), "");
}

TEST(ThreeValentInput, NonTrianglesAndUnusedVerticesAreNamed) {
  const PolyMesh mixed = PolyMesh::build({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {2, 0, 0}, {2, 1, 0}},
                                         {{0, 1, 2}, {0, 2, 3}, {1, 4, 5, 2}});
  EXPECT_EQ(error_of([&] { mesh::dual_net(mixed); }), "face 3 has 4 vertices; dual net needs a triangle mesh");
  EXPECT_EQ(error_of([&] { mesh::trisect_net(mixed); }), "face 3 has 4 vertices; trisection needs a triangle mesh");
  const PolyMesh lonely = PolyMesh::build({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {5, 5, 0}}, {{0, 1, 2}});
  EXPECT_EQ(error_of([&] { mesh::dual_net(lonely); }), "vertex 4 is in no triangle; dual net gives every vertex a face");
  EXPECT_EQ(error_of([&] { mesh::dual_net(PolyMesh()); }), "dual net: the triangle mesh has no faces");
}
