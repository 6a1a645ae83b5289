// The project's own control nets under data/meshes/ (made by tools/make_meshes.py) load and have the
// topology they are made for: Euler characteristic, boundary loops, valences of their EVs.
#include "support/paths.hpp"
#include <gtest/gtest.h>

#include <set>

#include "mesh/obj_reader.hpp"

using namespace iga;

namespace {
mesh::PolyMesh load(const std::string& name) { return mesh::read_obj(std::string(IGA_SOURCE_DIR) + "/data/meshes/" + name); }

Index num_edges(const mesh::PolyMesh& m) {
  Index boundary = 0;
  for (Index h = 0; h < m.num_half_edges(); ++h) boundary += m.half_edge(h).twin < 0;
  return (m.num_half_edges() + boundary) / 2;
}

std::set<int> interior_valences(const mesh::PolyMesh& m) {
  std::set<int> s;
  for (Index v = 0; v < m.num_vertices(); ++v) {
    if (!m.is_boundary_vertex(v)) s.insert(m.valence(v));
  }
  return s;
}

std::set<int> boundary_face_counts(const mesh::PolyMesh& m) {
  std::set<int> s;
  for (Index v = 0; v < m.num_vertices(); ++v) {
    if (m.is_boundary_vertex(v)) s.insert(m.num_vertex_faces(v));
  }
  return s;
}

int euler(const mesh::PolyMesh& m) { return static_cast<int>(m.num_vertices() - num_edges(m) + m.num_faces()); }
}  // namespace

TEST(DataMeshes, SquareWithExtraordinaryVertices) {
  const mesh::PolyMesh m = load("square_evs.obj");
  EXPECT_TRUE(m.is_planar());
  EXPECT_EQ(m.boundary_loops().size(), 1u);
  EXPECT_EQ(euler(m), 1);  // a disc
  EXPECT_EQ(interior_valences(m), (std::set<int>{3, 4, 5, 6}));
  EXPECT_TRUE(boundary_face_counts(m).count(3));  // a boundary EV
  EXPECT_TRUE(boundary_face_counts(m).count(1));  // corners
}

TEST(DataMeshes, SquareWithThreeHoles) {
  const mesh::PolyMesh m = load("square_three_holes.obj");
  EXPECT_EQ(m.boundary_loops().size(), 4u);
  EXPECT_EQ(euler(m), 1 - 3);
  EXPECT_TRUE(boundary_face_counts(m).count(3));  // reflex hole corners
}

TEST(DataMeshes, LShape) {
  const mesh::PolyMesh m = load("l_shape.obj");
  EXPECT_EQ(m.boundary_loops().size(), 1u);
  EXPECT_EQ(euler(m), 1);
  EXPECT_EQ(boundary_face_counts(m), (std::set<int>{1, 2, 3}));
}

TEST(DataMeshes, ClosedSurfaces) {
  const mesh::PolyMesh cube = load("cube.obj");
  EXPECT_TRUE(cube.is_closed());
  EXPECT_EQ(euler(cube), 2);
  EXPECT_EQ(interior_valences(cube), (std::set<int>{3, 4}));
  const mesh::PolyMesh torus = load("torus_evs.obj");
  EXPECT_TRUE(torus.is_closed());
  EXPECT_EQ(euler(torus), 0);
  EXPECT_EQ(interior_valences(torus), (std::set<int>{3, 4, 5}));
}
