// B-spline geometries: exact areas, the structured-grid reader, refinement keeps the map.
#include <gtest/gtest.h>

#include <numbers>
#include <random>

#include "basis/bspline/patches.hpp"
#include "basis/bspline/rational_space.hpp"
#include "basis/registry.hpp"
#include "core/error.hpp"
#include "fem/assembler.hpp"
#include "quadrature/rule_provider.hpp"
#include "refine/uniform.hpp"

using namespace iga;
using namespace iga::basis::bspline;

namespace {
double area(const basis::Geometry& g, int points) {
  const quadrature::Gauss rules(points);
  const fem::Assembler a(g, rules);
  return a.integrate(1, [](const fem::ElementContext& ctx, Eigen::Ref<Eigen::VectorXd> out) { out(0) = ctx.weight.sum(); })(0);
}

mesh::PolyMesh grid_mesh(int nx, int ny, bool bumpy) {
  std::vector<Eigen::Vector3d> pts;
  for (int j = 0; j <= ny; ++j) {
    for (int i = 0; i <= nx; ++i) pts.emplace_back(i, 0.5 * j, bumpy ? 0.1 * i * j : 0.0);
  }
  std::vector<std::vector<Index>> faces;
  for (int j = 0; j < ny; ++j) {
    for (int i = 0; i < nx; ++i) {
      const Index a = i + (nx + 1) * j;
      faces.push_back({a, a + 1, a + 1 + (nx + 1), a + (nx + 1)});
    }
  }
  return mesh::PolyMesh::build(pts, faces);
}

// Physical point of knot-parameter (x, y) on a tensor geometry.
Eigen::Vector3d map_point(const basis::Geometry& g, double x, double y) {
  const RationalSpace* rational = rational_space(g.space());
  const auto& s = rational ? rational->base() : dynamic_cast<const TensorSpace&>(g.space());
  for (Index e = 0; e < s.num_elements(); ++e) {
    const Eigen::Vector4d b = s.element_box(e);
    if (x >= b(0) && x <= b(1) && y >= b(2) && y <= b(3)) {
      Eigen::Matrix2Xd p(2, 1);
      p << (x - b(0)) / (b(1) - b(0)), (y - b(2)) / (b(3) - b(2));
      basis::GeometryValues gv;
      g.evaluate(e, p, gv);
      return gv.x.col(0);
    }
  }
  return Eigen::Vector3d::Constant(NAN);
}
}  // namespace

// The exact quarter annulus 1 <= r <= 2 (NURBS): area (π/4)(2² − 1²) = 3π/4. The integrand |det J| is rational, so
// Gauss is not exact: 16 points per direction on one element, or 8 on 16 elements, leave less than 1e-14.
TEST(Patches, QuarterAnnulusAreaIsExact) {
  const double exact = 0.75 * std::numbers::pi;
  for (int p = 2; p <= 5; ++p) {
    const basis::Geometry g = make_quarter_annulus(p);
    EXPECT_NEAR(area(g, 16), exact, 1e-14) << p;
    EXPECT_NEAR(area(refine::refine_uniform(g, 2).geometry, 8), exact, 1e-14) << p;
  }
  EXPECT_THROW(make_quarter_annulus(1), InputError);
}

// The quarter plate [0, 4]² with the hole r <= 1: area 16 − π/4; the hole (u = 0) on the circle, the outer sides
// (u = 1) on x = 4 and y = 4, and the symmetry segments on the axes, at every degree.
TEST(Patches, PlateWithAHoleIsExact) {
  const double exact = 16.0 - 0.25 * std::numbers::pi;
  for (int p = 2; p <= 4; ++p) {
    const basis::Geometry g = make_plate_with_hole(p);
    EXPECT_NEAR(area(refine::refine_uniform(g, 2).geometry, 12), exact, 1e-12) << p;
    for (double t = 0.0; t <= 1.0; t += 1.0 / 16) {
      EXPECT_NEAR(map_point(g, 0.0, t).head<2>().norm(), 1.0, 1e-14) << p << " " << t;
      const Eigen::Vector3d outer = map_point(g, 1.0, t);
      EXPECT_NEAR(t <= 0.5 ? outer(0) : outer(1), 4.0, 1e-14) << p << " " << t;
      EXPECT_NEAR(map_point(g, t, 0.0)(1), 0.0, 1e-14);
      EXPECT_NEAR(map_point(g, t, 1.0)(0), 0.0, 1e-14);
    }
    EXPECT_NEAR((map_point(g, 1.0, 0.5) - Eigen::Vector3d(4, 4, 0)).norm(), 0.0, 1e-14);
  }
  EXPECT_THROW(make_plate_with_hole(1), InputError);
  EXPECT_THROW(make_plate_with_hole(2, 2.0, 1.0), InputError);
}

TEST(Patches, RectangleAreaAndAffineMap) {
  const basis::Geometry g = make_rectangle(3, 1.0, 4.0, -1.0, 1.0);
  EXPECT_NEAR(area(g, 2), 6.0, 1e-14);
  const Eigen::Vector3d x = map_point(g, 0.25, 0.5);
  EXPECT_NEAR(x(0), 1.75, 1e-14);
  EXPECT_NEAR(x(1), 0.0, 1e-14);
}

TEST(Patches, RefinementKeepsTheMap) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u01(0.0, 1.0);
  const basis::Geometry coarse = make_quarter_annulus(3);
  const refine::Refinement r = refine::refine_uniform(coarse, 3);
  EXPECT_EQ(r.geometry.space().num_elements(), 64);
  EXPECT_EQ(r.prolongation.rows(), r.geometry.space().num_dofs());
  EXPECT_EQ(r.prolongation.cols(), coarse.space().num_dofs());
  for (int k = 0; k < 100; ++k) {
    const double x = u01(rng), y = u01(rng);
    EXPECT_LE((map_point(coarse, x, y) - map_point(r.geometry, x, y)).norm(), 1e-13);
  }
}

// --coarse-split (BackendOptions::split_u/v) inserts knots only: the quarter annulus keeps its map, whose closed form
// is |x(u, v)| = 1 + u (the radial factor is linear, the arc has unit radius); 1 × 3 elements. Split 2,2 is one
// midpoint step: the same knots and control points as refine_uniform's.
TEST(Patches, CoarseSplitKeepsTheMap) {
  const basis::Backend& b = basis::backend("bspline");
  basis::BackendOptions o;
  o.split_v = 3;
  const basis::Geometry coarse = make_quarter_annulus(3), split = b.default_geometry(o);
  EXPECT_EQ(split.space().num_elements(), 3);
  EXPECT_EQ(split.space().num_dofs(), 4 * 6);
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u01(0.0, 1.0);
  for (int k = 0; k < 100; ++k) {
    const double x = u01(rng), y = u01(rng);
    const Eigen::Vector3d p = map_point(split, x, y);
    EXPECT_NEAR(p.head<2>().norm(), 1.0 + x, 1e-14);
    EXPECT_LE((p - map_point(coarse, x, y)).norm(), 1e-14);
  }
  o.split_u = o.split_v = 2;
  const basis::Geometry twice = b.default_geometry(o);
  const basis::Geometry once = refine::refine_uniform(coarse, 1).geometry;
  ASSERT_EQ(twice.space().num_dofs(), once.space().num_dofs());
  EXPECT_LE((twice.control_points() - once.control_points()).cwiseAbs().maxCoeff(), 1e-15);
  o.split_u = 0;
  EXPECT_THROW(b.default_geometry(o), InputError);
}

TEST(QuadGrid, ControlNetFromMesh) {
  const basis::Geometry g = geometry_from_quad_grid(grid_mesh(5, 4, false), 2);
  EXPECT_EQ(g.dim(), 2);
  const auto& s = dynamic_cast<const TensorSpace&>(g.space());
  EXPECT_EQ(s.num_basis_u() * s.num_basis_v(), 30);
  EXPECT_EQ(s.num_elements(), (6 - 2) * (5 - 2));
  // x depends on u only and y on v only, each monotone from the first to the last vertex: the image is
  // [0,5]×[0,2] exactly, and det J is a polynomial that 3-point Gauss integrates exactly.
  EXPECT_NEAR(area(g, 3), 10.0, 1e-12);
  // The boundary vertices are interpolated at the corners.
  EXPECT_LE((map_point(g, 0.0, 0.0) - Eigen::Vector3d(0, 0, 0)).norm(), 1e-14);
  EXPECT_LE((map_point(g, 1.0, 1.0) - Eigen::Vector3d(5, 2, 0)).norm(), 1e-14);
  const basis::Geometry surface = geometry_from_quad_grid(grid_mesh(4, 4, true), 3);
  EXPECT_EQ(surface.dim(), 3);
}

TEST(QuadGrid, RejectsWhatIsNotAGrid) {
  // A triangle.
  const mesh::PolyMesh tri = mesh::PolyMesh::build({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {{0, 1, 2}});
  EXPECT_THROW(geometry_from_quad_grid(tri, 1, "tri.obj"), InputError);
  // Too few vertices for the degree.
  try {
    geometry_from_quad_grid(grid_mesh(2, 4, false), 3, "small.obj");
    FAIL() << "no exception";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("small.obj:0:"), std::string::npos);
    EXPECT_NE(std::string(e.what()).find("degree 3"), std::string::npos);
  }
  // An L-shaped set of quads is not a rectangle.
  std::vector<Eigen::Vector3d> pts;
  for (int j = 0; j <= 2; ++j) for (int i = 0; i <= 2; ++i) pts.emplace_back(i, j, 0);
  const mesh::PolyMesh l = mesh::PolyMesh::build(pts, {{0, 1, 4, 3}, {1, 2, 5, 4}, {3, 4, 7, 6}});
  EXPECT_THROW(geometry_from_quad_grid(l, 1, "l.obj"), InputError);
}
