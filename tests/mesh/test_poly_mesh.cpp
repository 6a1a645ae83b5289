#include "mesh/poly_mesh.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <iostream>
#include <cmath>
#include <limits>
#include <numbers>
#include <set>
#include <vector>

namespace iga::mesh {
namespace {

using Faces = std::vector<std::vector<Index>>;
using Points = std::vector<Eigen::Vector3d>;

// n x m grid of unit quads in the plane z = 0, vertex (i, j) = j * (n + 1) + i; cells listed in `skip` omitted.
PolyMesh make_grid(Index n, Index m, const std::set<std::pair<Index, Index>>& skip = {}) {
  Points points;
  for (Index j = 0; j <= m; ++j) {
    for (Index i = 0; i <= n; ++i) {
      points.emplace_back(static_cast<double>(i), static_cast<double>(j), 0.0);
    }
  }
  Faces faces;
  const auto id = [n](Index i, Index j) { return j * (n + 1) + i; };
  for (Index j = 0; j < m; ++j) {
    for (Index i = 0; i < n; ++i) {
      if (skip.count({i, j}) == 0) {
        faces.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)});
      }
    }
  }
  return PolyMesh::build(std::move(points), std::move(faces));
}

PolyMesh make_cube() {
  Points points;
  for (int k = 0; k < 8; ++k) {
    points.emplace_back(k & 1, (k >> 1) & 1, (k >> 2) & 1);
  }
  Faces faces = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  return PolyMesh::build(std::move(points), std::move(faces));
}

// Structural invariants every valid mesh satisfies.
void check_invariants(const PolyMesh& mesh) {
  for (Index f = 0; f < mesh.num_faces(); ++f) {
    const Index first = mesh.face_half_edge(f);
    EXPECT_EQ(mesh.half_edge(first).origin, mesh.face(f)[0]);
    Index h = first;
    Index steps = 0;
    do {
      EXPECT_EQ(mesh.half_edge(h).face, f);
      EXPECT_EQ(mesh.half_edge(mesh.half_edge(h).next).prev, h);
      EXPECT_EQ(mesh.half_edge(h).origin, mesh.face(f)[static_cast<std::size_t>(steps)]);
      h = mesh.half_edge(h).next;
      ++steps;
    } while (h != first && steps <= mesh.face_size(f));
    EXPECT_EQ(steps, mesh.face_size(f));
    h = first;
    steps = 0;
    do {
      h = mesh.half_edge(h).prev;
      ++steps;
    } while (h != first && steps <= mesh.face_size(f));
    EXPECT_EQ(steps, mesh.face_size(f));
  }
  for (Index h = 0; h < mesh.num_half_edges(); ++h) {
    const HalfEdge& e = mesh.half_edge(h);
    EXPECT_EQ(mesh.half_edge_target(h), mesh.half_edge(e.next).origin);
    if (e.twin >= 0) {
      EXPECT_NE(e.twin, h);
      EXPECT_EQ(mesh.half_edge(e.twin).twin, h);
      EXPECT_EQ(mesh.half_edge(e.twin).origin, mesh.half_edge_target(h));
      EXPECT_EQ(mesh.half_edge_target(e.twin), e.origin);
    }
  }
  for (Index v = 0; v < mesh.num_vertices(); ++v) {
    const Index h = mesh.vertex_half_edge(v);
    if (h < 0) {
      EXPECT_EQ(mesh.valence(v), 0);
      EXPECT_EQ(mesh.num_vertex_faces(v), 0);
      EXPECT_FALSE(mesh.is_boundary_vertex(v));
      continue;
    }
    EXPECT_EQ(mesh.half_edge(h).origin, v);
    EXPECT_EQ(mesh.is_boundary_vertex(v), mesh.half_edge(h).twin < 0);
    EXPECT_EQ(mesh.valence(v), mesh.num_vertex_faces(v) + (mesh.is_boundary_vertex(v) ? 1 : 0));
  }
  Index boundary = 0;
  for (Index h = 0; h < mesh.num_half_edges(); ++h) {
    boundary += mesh.half_edge(h).twin < 0 ? 1 : 0;
  }
  Index in_loops = 0;
  Index previous_first = -1;
  for (const std::vector<Index>& loop : mesh.boundary_loops()) {
    ASSERT_FALSE(loop.empty());
    EXPECT_EQ(loop.front(), *std::min_element(loop.begin(), loop.end()));
    EXPECT_GT(loop.front(), previous_first);
    previous_first = loop.front();
    for (std::size_t k = 0; k < loop.size(); ++k) {
      EXPECT_EQ(mesh.half_edge(loop[k]).twin, -1);
      EXPECT_EQ(mesh.half_edge_target(loop[k]), mesh.half_edge(loop[(k + 1) % loop.size()]).origin);
    }
    in_loops += static_cast<Index>(loop.size());
  }
  EXPECT_EQ(in_loops, boundary);
  EXPECT_EQ(mesh.is_closed(), boundary == 0);
}

// Twice the signed area of a boundary loop projected on z = 0.
double loop_area2(const PolyMesh& mesh, const std::vector<Index>& loop) {
  double a = 0.0;
  for (const Index h : loop) {
    const Eigen::Vector3d& p = mesh.point(mesh.half_edge(h).origin);
    const Eigen::Vector3d& q = mesh.point(mesh.half_edge_target(h));
    a += p.x() * q.y() - q.x() * p.y();
  }
  return a;
}

TEST(PolyMesh, QuadGrid2x2) {
  const PolyMesh mesh = make_grid(2, 2);
  EXPECT_EQ(mesh.num_vertices(), 9);
  EXPECT_EQ(mesh.num_faces(), 4);
  EXPECT_EQ(mesh.num_half_edges(), 16);
  check_invariants(mesh);
  for (const Index corner : {0, 2, 6, 8}) {
    EXPECT_EQ(mesh.valence(corner), 2);
    EXPECT_EQ(mesh.num_vertex_faces(corner), 1);
    EXPECT_TRUE(mesh.is_boundary_vertex(corner));
  }
  for (const Index side : {1, 3, 5, 7}) {
    EXPECT_EQ(mesh.valence(side), 3);
    EXPECT_EQ(mesh.num_vertex_faces(side), 2);
    EXPECT_TRUE(mesh.is_boundary_vertex(side));
  }
  EXPECT_EQ(mesh.valence(4), 4);
  EXPECT_EQ(mesh.num_vertex_faces(4), 4);
  EXPECT_FALSE(mesh.is_boundary_vertex(4));
  EXPECT_FALSE(mesh.is_closed());
  EXPECT_TRUE(mesh.is_planar());
  ASSERT_EQ(mesh.boundary_loops().size(), 1U);
  const std::vector<Index>& loop = mesh.boundary_loops()[0];
  EXPECT_EQ(loop.size(), 8U);
  EXPECT_EQ(loop.front(), 0);  // half-edge 0 (0 -> 1) is a boundary half-edge
  EXPECT_DOUBLE_EQ(loop_area2(mesh, loop), 8.0);  // counter-clockwise: the mesh is on the left
  for (Index f = 0; f < mesh.num_faces(); ++f) {
    EXPECT_EQ(mesh.face_size(f), 4);
    EXPECT_EQ(mesh.face_half_edge(f), 4 * f);
  }
  EXPECT_EQ(mesh.face(3)[0], 4);
  EXPECT_EQ(mesh.face(3)[2], 8);
  EXPECT_EQ(mesh.half_edge_target(0), 1);
  EXPECT_EQ(mesh.point(8), Eigen::Vector3d(2.0, 2.0, 0.0));
}

TEST(PolyMesh, ClosedCube) {
  const PolyMesh mesh = make_cube();
  check_invariants(mesh);
  EXPECT_TRUE(mesh.is_closed());
  EXPECT_TRUE(mesh.boundary_loops().empty());
  EXPECT_FALSE(mesh.is_planar());
  for (Index v = 0; v < 8; ++v) {
    EXPECT_EQ(mesh.valence(v), 3);
    EXPECT_EQ(mesh.num_vertex_faces(v), 3);
    EXPECT_FALSE(mesh.is_boundary_vertex(v));
  }
  for (Index h = 0; h < mesh.num_half_edges(); ++h) {
    EXPECT_GE(mesh.half_edge(h).twin, 0);
  }
  const Index edges = mesh.num_half_edges() / 2;
  EXPECT_EQ(edges, 12);
  EXPECT_EQ(mesh.num_vertices() - edges + mesh.num_faces(), 2);
}

TEST(PolyMesh, MeshWithHoleHasTwoLoops) {
  const PolyMesh mesh = make_grid(3, 3, {{1, 1}});
  check_invariants(mesh);
  EXPECT_EQ(mesh.num_faces(), 8);
  ASSERT_EQ(mesh.boundary_loops().size(), 2U);
  std::vector<std::size_t> sizes;
  double area_sum = 0.0;
  for (const auto& loop : mesh.boundary_loops()) {
    sizes.push_back(loop.size());
    const double a = loop_area2(mesh, loop);
    EXPECT_DOUBLE_EQ(std::abs(a), loop.size() == 12 ? 18.0 : 2.0);
    EXPECT_EQ(a > 0, loop.size() == 12);  // outer counter-clockwise, hole clockwise
    area_sum += a;
  }
  std::sort(sizes.begin(), sizes.end());
  EXPECT_EQ(sizes, (std::vector<std::size_t>{4, 12}));
  EXPECT_DOUBLE_EQ(area_sum, 16.0);
  // Vertex (1, 1) = 5: corner of the hole, 3 faces, 4 edges, on the boundary.
  EXPECT_EQ(mesh.num_vertex_faces(5), 3);
  EXPECT_EQ(mesh.valence(5), 4);
  EXPECT_TRUE(mesh.is_boundary_vertex(5));
  const Index edges = (mesh.num_half_edges() + 16) / 2;
  EXPECT_EQ(mesh.num_vertices() - edges + mesh.num_faces(), 0);  // annulus
}

TEST(PolyMesh, MixedTrianglesAndPentagonsWithIsolatedVertex) {
  // A pentagon with a triangle on each side, plus an unused vertex 10.
  Points points;
  for (int i = 0; i < 5; ++i) {
    const double t = 2.0 * std::numbers::pi * i / 5.0;
    points.emplace_back(std::cos(t), std::sin(t), 0.0);
  }
  for (int i = 0; i < 5; ++i) {
    const double t = 2.0 * std::numbers::pi * (i + 0.5) / 5.0;
    points.emplace_back(2.0 * std::cos(t), 2.0 * std::sin(t), 0.5);
  }
  points.emplace_back(9.0, 9.0, 9.0);
  Faces faces = {{0, 1, 2, 3, 4}};
  for (Index i = 0; i < 5; ++i) {
    faces.push_back({(i + 1) % 5, i, 5 + i});
  }
  const PolyMesh mesh = PolyMesh::build(points, faces);
  check_invariants(mesh);
  EXPECT_EQ(mesh.num_faces(), 6);
  EXPECT_EQ(mesh.num_half_edges(), 20);
  EXPECT_EQ(mesh.face_size(0), 5);
  EXPECT_EQ(mesh.face_size(3), 3);
  EXPECT_EQ(mesh.face_half_edge(1), 5);
  for (Index i = 0; i < 5; ++i) {
    EXPECT_EQ(mesh.valence(i), 4);
    EXPECT_EQ(mesh.num_vertex_faces(i), 3);
    EXPECT_TRUE(mesh.is_boundary_vertex(i));
    EXPECT_EQ(mesh.valence(5 + i), 2);
    EXPECT_EQ(mesh.num_vertex_faces(5 + i), 1);
  }
  EXPECT_EQ(mesh.valence(10), 0);
  EXPECT_EQ(mesh.num_vertex_faces(10), 0);
  EXPECT_EQ(mesh.vertex_half_edge(10), -1);
  EXPECT_FALSE(mesh.is_boundary_vertex(10));
  EXPECT_FALSE(mesh.is_planar());
  ASSERT_EQ(mesh.boundary_loops().size(), 1U);
  EXPECT_EQ(mesh.boundary_loops()[0].size(), 10U);
  EXPECT_GT(loop_area2(mesh, mesh.boundary_loops()[0]), 0.0);
  // Pentagon interior edges all have twins.
  for (Index h = 0; h < 5; ++h) {
    EXPECT_GE(mesh.half_edge(h).twin, 5);
  }
}

TEST(PolyMesh, TriangleFanAroundInteriorVertex) {
  // Hexagon fan: interior vertex 0 of valence 6.
  Points points = {Eigen::Vector3d::Zero()};
  for (int i = 0; i < 6; ++i) {
    const double t = std::numbers::pi * i / 3.0;
    points.emplace_back(std::cos(t), std::sin(t), 0.0);
  }
  Faces faces;
  for (Index i = 0; i < 6; ++i) {
    faces.push_back({0, 1 + i, 1 + (i + 1) % 6});
  }
  const PolyMesh mesh = PolyMesh::build(points, faces);
  check_invariants(mesh);
  EXPECT_EQ(mesh.valence(0), 6);
  EXPECT_FALSE(mesh.is_boundary_vertex(0));
  EXPECT_EQ(mesh.valence(1), 3);
  EXPECT_TRUE(mesh.is_planar());
}

Points some_points(int n) {
  Points p;
  for (int i = 0; i < n; ++i) {
    p.emplace_back(i, i * i, 0.0);
  }
  return p;
}

// Builds and returns the TopologyError thrown (fails the test if none).
TopologyError topology_error(const Points& points, const Faces& faces) {
  try {
    (void)PolyMesh::build(points, faces);
  } catch (const TopologyError& e) {
    return e;
  }
  ADD_FAILURE() << "no TopologyError thrown";
  return TopologyError(-2, "none");
}

TEST(PolyMeshErrors, NoFaces) {
  const TopologyError e = topology_error(some_points(3), {});
  EXPECT_EQ(e.face(), -1);
  EXPECT_EQ(e.problem(), TopologyProblem::kNoFaces);
  EXPECT_NE(std::string(e.what()).find("no faces"), std::string::npos);
}

TEST(PolyMeshErrors, TooFewVertices) {
  const TopologyError e = topology_error(some_points(4), {{0, 1, 2}, {2, 3}});
  EXPECT_EQ(e.face(), 1);
  EXPECT_EQ(e.problem(), TopologyProblem::kTooFewVertices);
  EXPECT_NE(std::string(e.what()).find("face 1: face has 2 vertices"), std::string::npos) << e.what();
}

TEST(PolyMeshErrors, IndexOutOfRange) {
  TopologyError e = topology_error(some_points(4), {{0, 1, 2}, {2, 1, 9}});
  EXPECT_EQ(e.face(), 1);
  EXPECT_EQ(e.problem(), TopologyProblem::kIndexOutOfRange);
  EXPECT_NE(std::string(e.what()).find("vertex index 9 out of range (4 vertices"), std::string::npos) << e.what();
  e = topology_error(some_points(4), {{0, 1, 2}, {1, 0, 3}, {0, -1, 3}});
  EXPECT_EQ(e.face(), 2);
}

TEST(PolyMeshErrors, RepeatedVertex) {
  const TopologyError e = topology_error(some_points(4), {{0, 1, 2}, {2, 1, 3, 1}});
  EXPECT_EQ(e.face(), 1);
  EXPECT_EQ(e.problem(), TopologyProblem::kRepeatedVertex);
  EXPECT_NE(std::string(e.what()).find("vertex 1 appears more than once"), std::string::npos) << e.what();
  EXPECT_NE(e.describe(1).find("vertex 2 appears"), std::string::npos) << e.describe(1);
}

TEST(PolyMeshErrors, NonManifoldEdgeReportsThirdFace) {
  TopologyError e = topology_error(some_points(5), {{0, 1, 2}, {1, 0, 3}, {0, 1, 4}});
  EXPECT_EQ(e.face(), 2);
  EXPECT_EQ(e.problem(), TopologyProblem::kNonManifoldEdge);
  EXPECT_EQ(e.vertices(), (std::vector<Index>{0, 1}));
  EXPECT_NE(std::string(e.what()).find("edge (0,1) is shared by more than two faces"), std::string::npos);
  EXPECT_EQ(e.describe(1), "edge (1,2) is shared by more than two faces");
  e = topology_error(some_points(6), {{0, 1, 2}, {1, 0, 3}, {3, 0, 5}, {4, 1, 0}});
  EXPECT_EQ(e.face(), 3);
}

TEST(PolyMeshErrors, InconsistentOrientationReportsSecondFace) {
  TopologyError e = topology_error(some_points(4), {{0, 1, 2}, {0, 1, 3}});
  EXPECT_EQ(e.face(), 1);
  EXPECT_EQ(e.problem(), TopologyProblem::kInconsistentOrientation);
  EXPECT_EQ(e.describe(1), "face orientation inconsistent with a neighbouring face across edge (1,2)");
  e = topology_error(some_points(5), {{0, 1, 2}, {2, 1, 4}, {3, 2, 0}, {1, 0, 4}, {3, 1, 2}});
  // Face 2 traverses 2 -> 0 like face 0 (second on that edge); face 4 is also a third face on edge (1,2).
  EXPECT_EQ(e.face(), 2);
}

TEST(PolyMeshErrors, LowestOffendingFaceWinsAcrossEdges) {
  // Face 3 conflicts on edge (2,3) with face 2; face 4 is a third face on edge (0,1). Lowest: face 3.
  const TopologyError e =
      topology_error(some_points(7), {{0, 1, 2}, {1, 0, 3}, {2, 3, 4}, {2, 3, 5}, {0, 1, 6}});
  EXPECT_EQ(e.face(), 3);
  EXPECT_EQ(e.problem(), TopologyProblem::kInconsistentOrientation);
}

TEST(PolyMeshErrors, NonManifoldVertexTwoTriangles) {
  const TopologyError e = topology_error(some_points(5), {{0, 1, 2}, {0, 3, 4}});
  EXPECT_EQ(e.face(), 1);
  EXPECT_EQ(e.problem(), TopologyProblem::kNonManifoldVertex);
  EXPECT_EQ(e.vertices(), (std::vector<Index>{0}));
  EXPECT_EQ(e.count(), 2);
  EXPECT_EQ(e.describe(1), "vertex 1 is non-manifold: its faces form 2 separate fans");
}

TEST(PolyMeshErrors, NonManifoldVertexTwoClosedTetrahedra) {
  const auto tet = [](Index a, Index b, Index c, Index d) {
    return Faces{{a, c, b}, {a, b, d}, {b, c, d}, {a, d, c}};
  };
  Faces faces = tet(0, 1, 2, 3);
  for (auto& f : tet(0, 4, 5, 6)) {
    faces.push_back(f);
  }
  Points points = some_points(7);
  for (auto& p : points) {
    p.z() = p.x() * 0.5;
  }
  // Each tetrahedron alone is a valid closed mesh.
  EXPECT_TRUE(PolyMesh::build(points, tet(0, 1, 2, 3)).is_closed());
  const TopologyError e = topology_error(points, faces);
  EXPECT_EQ(e.problem(), TopologyProblem::kNonManifoldVertex);
  EXPECT_EQ(e.face(), 4);
  EXPECT_EQ(e.vertices(), (std::vector<Index>{0}));
}

TEST(PolyMeshErrors, NonManifoldVertexFanFilledLaterIsFine) {
  // Faces 0 and 1 touch only at vertex 0 until face 2 fills the gap: manifold in the end.
  Points points = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {-1, 1, 0}};
  const PolyMesh mesh = PolyMesh::build(points, {{0, 1, 2}, {0, 3, 4}, {0, 2, 3}});
  check_invariants(mesh);
  EXPECT_EQ(mesh.valence(0), 4);
}

TEST(PolyMeshErrors, NonFiniteCoordinateIsInputError) {
  Points points = some_points(3);
  points[2].y() = std::numeric_limits<double>::quiet_NaN();
  try {
    (void)PolyMesh::build(points, {{0, 1, 2}});
    FAIL() << "no exception";
  } catch (const TopologyError&) {
    FAIL() << "wrong exception type";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("vertex 3 has a non-finite"), std::string::npos) << e.what();  // 1-based
  }
  points[2].y() = std::numeric_limits<double>::infinity();
  EXPECT_THROW((void)PolyMesh::build(points, {{0, 1, 2}}), InputError);
}

TEST(PolyMeshErrors, FreeTextTopologyError) {
  const TopologyError e(7, "something odd");
  EXPECT_EQ(e.face(), 7);
  EXPECT_EQ(e.problem(), TopologyProblem::kOther);
  EXPECT_EQ(e.describe(1), "something odd");
  EXPECT_STREQ(e.what(), "something odd");
  const InputError& base = e;
  EXPECT_EQ(base.reason(), "something odd");
}

TEST(PolyMesh, DefaultConstructedIsEmpty) {
  const PolyMesh mesh;
  EXPECT_EQ(mesh.num_vertices(), 0);
  EXPECT_EQ(mesh.num_faces(), 0);
  EXPECT_EQ(mesh.num_half_edges(), 0);
  EXPECT_TRUE(mesh.boundary_loops().empty());
}

TEST(PolyMesh, MillionQuadsBuildQuickly) {
  const auto start = std::chrono::steady_clock::now();
  const PolyMesh mesh = make_grid(1000, 1000);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  EXPECT_EQ(mesh.num_faces(), 1000000);
  ASSERT_EQ(mesh.boundary_loops().size(), 1U);
  EXPECT_EQ(mesh.boundary_loops()[0].size(), 4000U);
  EXPECT_EQ(mesh.valence(1001 * 500 + 500), 4);
#ifdef NDEBUG
  EXPECT_LT(seconds, 20.0);  // ~1 s (grid generation included) in a release build; generous bound
#endif
  std::cout << "1e6-quad grid built in " << seconds << " s\n";
}

}  // namespace
}  // namespace iga::mesh
