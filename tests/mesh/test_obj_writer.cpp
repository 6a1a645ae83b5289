#include "mesh/obj_writer.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

#include "mesh/obj_reader.hpp"

namespace iga::mesh {
namespace {

// Mixed quads/triangles with awkward coordinates and one isolated vertex.
PolyMesh awkward_mesh() {
  std::vector<Eigen::Vector3d> points = {
      {0.1, 1.0 / 3.0, -0.0},
      {std::numbers::pi, 2.0 / 3.0, 1e-300},
      {1e300, -std::numbers::e, 5e-324},
      {-1.0 / 7.0, 0.30000000000000004, std::numeric_limits<double>::max()},
      {std::numeric_limits<double>::min(), 123456789.123456789, -2.5},
      {std::nextafter(1.0, 2.0), std::nextafter(0.0, -1.0), 7.0},
  };
  std::vector<std::vector<Index>> faces = {{0, 1, 2, 3}, {1, 4, 2}};
  return PolyMesh::build(std::move(points), std::move(faces));
}

void expect_same(const PolyMesh& a, const PolyMesh& b) {
  ASSERT_EQ(a.num_vertices(), b.num_vertices());
  ASSERT_EQ(a.num_faces(), b.num_faces());
  for (Index v = 0; v < a.num_vertices(); ++v) {
    for (int k = 0; k < 3; ++k) {
      EXPECT_EQ(a.point(v)[k], b.point(v)[k]) << "vertex " << v << " coordinate " << k;  // exact
      EXPECT_EQ(std::signbit(a.point(v)[k]), std::signbit(b.point(v)[k]));
    }
  }
  for (Index f = 0; f < a.num_faces(); ++f) {
    const auto fa = a.face(f);
    const auto fb = b.face(f);
    EXPECT_EQ(std::vector<Index>(fa.begin(), fa.end()), std::vector<Index>(fb.begin(), fb.end()));
  }
}

TEST(ObjWriter, StreamRoundTripIsExact) {
  const PolyMesh mesh = awkward_mesh();
  std::stringstream text;
  write_obj(mesh, text);
  const PolyMesh back = parse_obj(text, "round_trip.obj");
  expect_same(mesh, back);
  EXPECT_EQ(back.valence(5), 0);
}

TEST(ObjWriter, OutputFormat) {
  const PolyMesh mesh = PolyMesh::build({{0, 0, 0}, {1, 0, 0}, {0, 0.5, 0}}, {{0, 1, 2}});
  std::ostringstream text;
  write_obj(mesh, text);
  EXPECT_EQ(text.str(),
            "# iga PolyMesh: 3 vertices, 1 faces\n"
            "v 0 0 0\n"
            "v 1 0 0\n"
            "v 0 0.5 0\n"
            "f 1 2 3\n");
}

TEST(ObjWriter, FileRoundTripOfLargerMesh) {
  // 30 x 20 quad grid with perturbed, non-representable coordinates.
  std::vector<Eigen::Vector3d> points;
  const Index n = 30;
  const Index m = 20;
  for (Index j = 0; j <= m; ++j) {
    for (Index i = 0; i <= n; ++i) {
      points.emplace_back(i / 3.0 + std::sin(static_cast<double>(j)) * 1e-9, j * 0.1, std::cos(i * 0.7 + j));
    }
  }
  std::vector<std::vector<Index>> faces;
  for (Index j = 0; j < m; ++j) {
    for (Index i = 0; i < n; ++i) {
      const Index a = j * (n + 1) + i;
      faces.push_back({a, a + 1, a + n + 2, a + n + 1});
    }
  }
  const PolyMesh mesh = PolyMesh::build(std::move(points), std::move(faces));
  const std::string path = testing::TempDir() + "iga_mesh_writer_grid.obj";
  write_obj(mesh, path);
  const PolyMesh back = read_obj(path);
  expect_same(mesh, back);
  EXPECT_EQ(back.boundary_loops().size(), 1U);
  std::remove(path.c_str());
}

TEST(ObjWriter, UnwritablePath) {
  const std::string path = testing::TempDir() + "iga_no_such_directory/sub/out.obj";
  try {
    write_obj(awkward_mesh(), path);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), path + ":0: cannot write file");
  }
}

TEST(ObjWriter, FailedStreamThrows) {
  std::ostringstream out;
  out.setstate(std::ios::badbit);
  EXPECT_THROW(write_obj(awkward_mesh(), out), InputError);
}

}  // namespace
}  // namespace iga::mesh
