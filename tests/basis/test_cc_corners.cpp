// Corner vertices of the clamped Catmull–Clark boundary (basis/catmull_clark/corners.hpp): the limit domain passes
// through the vertex and leaves it along its two boundary edges, so its angle there is the net's. Checked by
// evaluating the geometry (Stam's method on the extended net, not the eigenvector stencils corners.cpp solves
// with): the limit point at the element corner, and the chords x(t) − x(0) along the two boundary sides, whose
// directions converge to the edges' as t → 0. Bad input is named.
#include "support/paths.hpp"
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "basis/catmull_clark/corners.hpp"
#include "basis/catmull_clark/space.hpp"
#include "basis/geometry.hpp"
#include "core/error.hpp"
#include "mesh/obj_reader.hpp"
#include "support/nets.hpp"

namespace {

using iga::Index;
using iga::basis::Geometry;
using iga::basis::catmull_clark::BoundaryRule;
using iga::basis::catmull_clark::make_catmull_clark_geometry;
using iga::basis::catmull_clark::with_corners;
using iga::mesh::PolyMesh;

// An open fan of k sectors of 2 × 2 quads around vertex 0 (the origin), its spokes at angles α t / k, t = 0..k: a
// boundary vertex with k faces and interior angle α.
PolyMesh fan(int k, double alpha) { return iga::test::open_fan(k, alpha, 2.0); }

// The two boundary sides that end at `corner`, as (element, side, t at the corner).
struct Side {
  Index element;
  int side;
  double t0;
};
std::vector<Side> sides_at(const Geometry& g, const Eigen::Vector2d& corner) {
  std::vector<Side> out;
  for (const auto& b : g.space().boundary_edges()) {
    for (double t0 : {0.0, 1.0}) {
      Eigen::Matrix2Xd pt(2, 1);
      pt.col(0) = iga::basis::side_point(iga::basis::Shape::Quad, b.side, t0);
      iga::basis::GeometryValues gv;
      g.evaluate(b.element, pt, gv);
      if ((gv.x.col(0).head<2>() - corner).norm() < 1e-12) out.push_back({b.element, b.side, t0});
    }
  }
  return out;
}

// Unit chord from the corner to the boundary point at parameter distance h along a side.
Eigen::Vector2d chord(const Geometry& g, const Side& s, double h, const Eigen::Vector2d& corner) {
  Eigen::Matrix2Xd pt(2, 1);
  pt.col(0) = iga::basis::side_point(iga::basis::Shape::Quad, s.side, s.t0 == 0 ? h : 1 - h);
  iga::basis::GeometryValues gv;
  g.evaluate(s.element, pt, gv);
  return (gv.x.col(0).head<2>() - corner).normalized();
}

// Largest angle (radians) between the chords at distance h and the nearest of the given edge directions.
double tangent_error(const Geometry& g, const Eigen::Vector2d& corner, const std::vector<Eigen::Vector2d>& edges, double h) {
  const std::vector<Side> sides = sides_at(g, corner);
  EXPECT_EQ(sides.size(), 2u);
  double worst = 0;
  for (const Side& s : sides) {
    const Eigen::Vector2d c = chord(g, s, h, corner);
    double best = 10;
    for (const Eigen::Vector2d& e : edges) best = std::min(best, std::acos(std::clamp(c.dot(e.normalized()), -1.0, 1.0)));
    worst = std::max(worst, best);
  }
  return worst;
}

struct FanCase {
  int faces;
  double degrees;
};
class CornerFan : public ::testing::TestWithParam<FanCase> {};

TEST_P(CornerFan, LimitDomainHasTheNetsAngleAtTheVertex) {
  const auto [k, degrees] = GetParam();
  const double alpha = degrees * std::numbers::pi / 180;
  const Geometry plain = make_catmull_clark_geometry(fan(k, alpha), "fan", BoundaryRule::kClamped);
  const Index corner_vertex[] = {0};
  const Geometry g = with_corners(plain, corner_vertex, "fan");
  const Eigen::Vector2d origin = Eigen::Vector2d::Zero();
  // Without the corner the limit point is off the vertex (no boundary side ends at the origin).
  EXPECT_TRUE(sides_at(plain, origin).empty());
  const std::vector<Eigen::Vector2d> edges{{1.0, 0.0}, {std::cos(alpha), std::sin(alpha)}};
  // The chords' directions converge to the edges' geometrically in the parameter distance (like the subdivision
  // level's ratio of eigenvalues): measured 8e-3 .. 9e-2 rad at 2^-4, 8e-7 .. 1.3e-3 at 2^-24 (the slowest with six
  // faces, valence 8).
  const double coarse = tangent_error(g, origin, edges, std::ldexp(1.0, -4));
  const double fine = tangent_error(g, origin, edges, std::ldexp(1.0, -24));
  std::cout << k << " faces, " << degrees << " degrees: tangent error " << coarse << " at 2^-4, " << fine << " at 2^-24\n";
  EXPECT_LT(fine, 2e-3);
  EXPECT_LT(fine, 0.05 * coarse);
  // Only the corner's point and its ghost moved.
  const Eigen::MatrixXd moved = g.control_points() - plain.control_points();
  int rows = 0;
  for (Index i = 0; i < moved.rows(); ++i) rows += moved.row(i).norm() > 0;
  EXPECT_EQ(rows, 2);
}

INSTANTIATE_TEST_SUITE_P(Angles, CornerFan,
                         ::testing::Values(FanCase{3, 270}, FanCase{3, 200}, FanCase{3, 340}, FanCase{4, 300},
                                           FanCase{5, 330}, FanCase{6, 320}),
                         [](const ::testing::TestParamInfo<FanCase>& info) {
                           return std::to_string(info.param.faces) + "faces" + std::to_string(static_cast<int>(info.param.degrees)) + "degrees";
                         });

TEST(CornerLShape, ReflexCornerAtOneOneAlongTheAxes) {
  const PolyMesh net = iga::mesh::read_obj(std::string(IGA_SOURCE_DIR) + "/data/meshes/l_shape.obj");
  const Index corner_vertex[] = {40};  // v 1 1 0, the 41st vertex
  const Geometry g = with_corners(make_catmull_clark_geometry(net, "l_shape.obj", BoundaryRule::kClamped), corner_vertex, "l_shape.obj");
  EXPECT_LT(tangent_error(g, Eigen::Vector2d(1, 1), {{0.0, 1.0}, {1.0, 0.0}}, std::ldexp(1.0, -24)), 1e-3);
  // Named twice, it is one corner (placing it again from its moved control point would move it off).
  const Index twice[] = {40, 40};
  const Geometry g2 = with_corners(make_catmull_clark_geometry(net, "l_shape.obj", BoundaryRule::kClamped), twice, "l_shape.obj");
  EXPECT_EQ((g2.control_points() - g.control_points()).norm(), 0.0);
}

TEST(CornerErrors, BadVerticesAndRulesAreNamed) {
  const PolyMesh net = iga::mesh::read_obj(std::string(IGA_SOURCE_DIR) + "/data/meshes/l_shape.obj");
  const Geometry clamped = make_catmull_clark_geometry(net, "l_shape.obj", BoundaryRule::kClamped);
  const auto message = [&](const Geometry& g, std::vector<Index> corners) -> std::string {
    try {
      with_corners(g, corners, "l_shape.obj");
    } catch (const iga::Error& e) {
      return e.what();
    }
    return "no error";
  };
  // Vertex 3 (0.25, 0.25) is inside; vertex 2 (0.25, 0) has two faces.
  EXPECT_EQ(message(clamped, {2}), "l_shape.obj:5: vertex 3: a corner must be on the boundary");
  EXPECT_EQ(message(clamped, {1}).find("l_shape.obj:4: vertex 2: a boundary vertex with two faces is a regular point"), 0u);
  EXPECT_EQ(message(clamped, {500}), "l_shape.obj: corner vertex 501 is not a vertex of the net (it has 65)");
  const Index origin[] = {0};
  const auto fan_message = [&](int k, double alpha) -> std::string {
    try {
      with_corners(make_catmull_clark_geometry(fan(k, alpha), "fan", BoundaryRule::kClamped), origin, "fan");
    } catch (const iga::Error& e) {
      return e.what();
    }
    return "no error";
  };
  EXPECT_EQ(fan_message(3, std::numbers::pi), "fan:0: vertex 1: its two boundary edges are collinear: there is no corner to keep");
  // A notch one face wide: 3 × 2 unit quads without the top middle one; its reflex corners (1, 1) and (2, 1) are
  // extraordinary vertices of one face, which needs a global step (the numbering would change): refused.
  std::vector<Eigen::Vector3d> grid;
  for (int j = 0; j <= 2; ++j) {
    for (int i = 0; i <= 3; ++i) grid.emplace_back(i, j, 0);
  }
  std::vector<std::vector<Index>> quads;
  for (const auto& [i, j] : std::vector<std::pair<int, int>>{{0, 0}, {1, 0}, {2, 0}, {0, 1}, {2, 1}}) {
    quads.push_back({i + 4 * j, i + 1 + 4 * j, i + 1 + 4 * (j + 1), i + 4 * (j + 1)});
  }
  const Index notch_corner[] = {5};
  EXPECT_THROW(with_corners(make_catmull_clark_geometry(PolyMesh::build(grid, quads), "notch", BoundaryRule::kClamped),
                            notch_corner, "notch"),
               iga::UnsupportedError);
  // A vertex with one face is a corner of the clamped rule already: nothing moves.
  EXPECT_EQ((with_corners(clamped, std::vector<Index>{0}, "l_shape.obj").control_points() - clamped.control_points()).norm(), 0.0);
  // Corners the clamped space cannot have: two faces (a regular point), a convex angle with three faces.
  EXPECT_THROW(with_corners(make_catmull_clark_geometry(fan(2, std::numbers::pi / 2), "fan", BoundaryRule::kClamped), origin, "fan"),
               iga::UnsupportedError);
  try {
    with_corners(make_catmull_clark_geometry(fan(3, 2 * std::numbers::pi / 3), "fan", BoundaryRule::kClamped), origin, "fan");
    ADD_FAILURE() << "a convex corner with three faces was accepted";
  } catch (const iga::InputError& e) {
    EXPECT_EQ(std::string(e.what()).find("fan:0: vertex 1: a convex corner with 3 faces"), 0u) << e.what();
  }
  const Geometry natural = make_catmull_clark_geometry(net, "l_shape.obj", BoundaryRule::kNatural);
  EXPECT_THROW(with_corners(natural, std::vector<Index>{40}, "l_shape.obj"), iga::UnsupportedError);
}

}  // namespace
