// BezierView .bv writer and reader (io/bv.hpp): the file layout of the format description (u-major control
// points, kind 5 with "deg_u deg_v", kind 4 with one degree, kind 3 triangles in row-ascending order, group
// lines), exact round trips, and one
// InputError with file and line for each kind of malformed input.
#include <gtest/gtest.h>

#include <Eigen/Core>
#include <filesystem>
#include <random>
#include <sstream>
#include <string>
#include <unistd.h>

#include "core/error.hpp"
#include "io/bv.hpp"

namespace {

using iga::io::BvPatch;

BvPatch random_patch(int du, int dv, const std::string& group, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> d(-10.0, 10.0);
  BvPatch p;
  p.group = group;
  p.degree_u = du;
  p.degree_v = dv;
  p.points.resize((du + 1) * (dv + 1), 3);
  for (Eigen::Index i = 0; i < p.points.rows(); ++i) p.points.row(i) << d(rng), d(rng) * 1e-7, d(rng) * 1e5;
  return p;
}

TEST(Bv, WritesTheFormatsLayout) {
  // Degree (1, 2): b_ij = (i, j, 10 i + j). The file lists rows of constant u index: p(0,0) p(0,1) p(0,2) p(1,0)…
  BvPatch p;
  p.group = "Group 0 Regular";
  p.degree_u = 1;
  p.degree_v = 2;
  p.points.resize(6, 3);
  for (int j = 0; j <= 2; ++j) {
    for (int i = 0; i <= 1; ++i) p.points.row(j * 2 + i) << i, j, 10 * i + j;
  }
  std::ostringstream out;
  iga::io::write_bv(out, {p});
  EXPECT_EQ(out.str(), "Group 0 Regular\n5\n1 2\n0 0 0\n0 1 1\n0 2 2\n1 0 10\n1 1 11\n1 2 12\n");
}

TEST(Bv, ReadsTheFormatDescriptionsExample) {
  // The degree 1 by 2 example of the BezierView format description, then a kind-4 patch of degree 1.
  std::istringstream in("5\n1 2\n-1 -1 0\n 0 -1 0\n 1 -1 0\n-1  1 0\n 0  1 0\n 1  1 0\n\nGroup 3 T1\n4\n1\n0 0 0\n0 1 0\n1 0 0\n1 1 1\n");
  const auto patches = iga::io::parse_bv(in, "example.bv");
  ASSERT_EQ(patches.size(), 2u);
  EXPECT_EQ(patches[0].group, "");
  EXPECT_EQ(patches[0].degree_u, 1);
  EXPECT_EQ(patches[0].degree_v, 2);
  // Row j·2 + i holds p(i, j): u index i = 0 is the first three points of the file.
  EXPECT_EQ(patches[0].points.row(0), Eigen::RowVector3d(-1, -1, 0));  // (0,0)
  EXPECT_EQ(patches[0].points.row(2), Eigen::RowVector3d(0, -1, 0));   // (0,1)
  EXPECT_EQ(patches[0].points.row(1), Eigen::RowVector3d(-1, 1, 0));   // (1,0)
  EXPECT_EQ(patches[0].points.row(5), Eigen::RowVector3d(1, 1, 0));    // (1,2)
  EXPECT_EQ(patches[1].group, "Group 3 T1");
  EXPECT_EQ(patches[1].degree_u, 1);
  EXPECT_EQ(patches[1].degree_v, 1);
  EXPECT_EQ(patches[1].points.row(3), Eigen::RowVector3d(1, 1, 1));
}

TEST(Bv, RoundTripIsExact) {
  std::vector<BvPatch> patches{random_patch(3, 3, "Group 1 ExtraordinaryPoint", 1), random_patch(3, 2, "Group 5 Polar", 2),
                               random_patch(2, 2, "", 3), random_patch(1, 4, "Group 8 nGon", 4)};
  const auto path = std::filesystem::temp_directory_path() / ("iga_test_bv_" + std::to_string(::getpid()) + ".bv");
  iga::io::write_bv(path.string(), patches);
  const auto back = iga::io::read_bv(path.string());
  std::filesystem::remove(path);
  ASSERT_EQ(back.size(), patches.size());
  for (std::size_t k = 0; k < patches.size(); ++k) {
    EXPECT_EQ(back[k].degree_u, patches[k].degree_u);
    EXPECT_EQ(back[k].degree_v, patches[k].degree_v);
    EXPECT_EQ(back[k].points, patches[k].points) << k;  // 17 significant digits: bit-exact
  }
  EXPECT_EQ(back[0].group, "Group 1 ExtraordinaryPoint");
  EXPECT_EQ(back[2].group, "Group 5 Polar");  // no group line of its own: the previous one still applies
  EXPECT_EQ(back[3].group, "Group 8 nGon");
}

BvPatch random_triangle(int d, const std::string& group, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-10.0, 10.0);
  BvPatch p;
  p.group = group;
  p.triangle = true;
  p.degree_u = p.degree_v = d;
  p.points.resize(iga::io::triangle_size(d), 3);
  for (Eigen::Index i = 0; i < p.points.rows(); ++i) p.points.row(i) << u(rng) * 1e-3, u(rng), u(rng) * 1e9;
  return p;
}

// The cubic triangle of the format page: points numbered 0..3 (bottom row), 4..6, 7..8, 9 (apex). With
// b_ijk = (j, k, i) the file lists rows of constant k, j ascending.
TEST(Bv, WritesTheTriangleLayout) {
  BvPatch p;
  p.triangle = true;
  p.degree_u = 3;
  p.points.resize(10, 3);
  for (int k = 0; k <= 3; ++k) {
    for (int j = 0; j + k <= 3; ++j) p.points.row(iga::io::triangle_index(3, j, k)) << j, k, 3 - j - k;
  }
  std::ostringstream out;
  iga::io::write_bv(out, {p});
  EXPECT_EQ(out.str(), "3\n3\n0 0 3\n1 0 2\n2 0 1\n3 0 0\n0 1 2\n1 1 1\n2 1 0\n0 2 1\n1 2 0\n0 3 0\n");
  EXPECT_EQ(iga::io::triangle_index(3, 0, 1), 4);  // the page's numbering
  EXPECT_EQ(iga::io::triangle_index(3, 0, 2), 7);
  EXPECT_EQ(iga::io::triangle_index(3, 0, 3), 9);
  EXPECT_EQ(iga::io::triangle_size(3), 10);
}

TEST(Bv, TrianglesAndTensorsRoundTripExactly) {
  std::vector<BvPatch> patches{random_triangle(3, "Group 0 HalfBox", 11), random_patch(3, 3, "Group 1 Regular", 12),
                               random_triangle(1, "", 13), random_triangle(5, "Group 2 Quintic", 14)};
  std::ostringstream out;
  iga::io::write_bv(out, patches);
  std::istringstream in(out.str());
  const auto back = iga::io::parse_bv(in, "mixed.bv");
  ASSERT_EQ(back.size(), patches.size());
  for (std::size_t k = 0; k < patches.size(); ++k) {
    EXPECT_EQ(back[k].triangle, patches[k].triangle) << k;
    EXPECT_EQ(back[k].degree_u, patches[k].degree_u) << k;
    EXPECT_EQ(back[k].points, patches[k].points) << k;  // 17 significant digits: bit-exact
  }
  EXPECT_EQ(back[0].degree_v, 3);  // set to the degree on reading
  EXPECT_EQ(back[2].group, "Group 1 Regular");
  EXPECT_EQ(back[3].group, "Group 2 Quintic");
}

void expect_error(const std::string& text, long line, const std::string& part) {
  std::istringstream in(text);
  try {
    iga::io::parse_bv(in, "bad.bv");
    FAIL() << "parsed: " << text;
  } catch (const iga::InputError& e) {
    EXPECT_EQ(e.file(), "bad.bv");
    EXPECT_EQ(e.line(), line) << e.what();
    EXPECT_NE(std::string(e.what()).find(part), std::string::npos) << e.what();
  }
}

TEST(Bv, MalformedInputNamesFileAndLine) {
  expect_error("Group 0 Regular\nfive\n", 2, "patch kind");
  expect_error("1\n3 1\n", 1, "kind 1 (polyhedron) is not supported");
  expect_error("8\n1 1\n", 1, "kind 8 (rational patch)");
  expect_error("5\n3\n", 2, "two degrees");
  expect_error("5\n0 2\n", 2, "degrees must be in 1..30");
  expect_error("4\n2 2\n", 2, "one degree");
  expect_error("5\n1 1\n0 0 0\n1 0 0\n0 1\n1 1 1\n", 5, "control point 'x y z'");
  expect_error("5\n1 1\n0 0 0\n1 0 0 7\n", 4, "control point 'x y z'");
  expect_error("5\n1 1\n0 0 0\n1 0 nan\n", 4, "not finite");
  expect_error("5\n1 1\n0 0 0\n1 0x 0\n", 4, "control point");
  expect_error("5\n1 1\n0 0 0\n\n1 0 0\n", 5, "2 of 4 control points read");
  expect_error("5\n", 1, "end of file after patch kind");
  expect_error("9\n3 3\n", 1, "kind 9 (PN triangle) is not supported");
  expect_error("3\n3 3\n", 2, "one degree for a kind-3 patch");
  expect_error("3\n31\n", 2, "degrees must be in 1..30");
  expect_error("3\n1\n0 0 0\n1 0 0\n", 4, "2 of 3 control points read");
  EXPECT_THROW(iga::io::read_bv("/nonexistent-dir/x.bv"), iga::InputError);
  // The writer refuses a patch whose points do not fit its degrees.
  BvPatch p = random_patch(2, 2, "", 5);
  p.degree_v = 3;
  std::ostringstream out;
  EXPECT_THROW(iga::io::write_bv(out, {p}), iga::InputError);
  BvPatch t = random_triangle(3, "", 6);
  t.points.conservativeResize(9, 3);  // a cubic triangle needs 10
  EXPECT_THROW(iga::io::write_bv(out, {t}), iga::InputError);
}

}  // namespace
