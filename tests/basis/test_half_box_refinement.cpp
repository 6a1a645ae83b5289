// Refinement of half-box spaces through the registry: one subdivision step per level, nested for closed nets
// and for nets with a receding boundary alike. With random control points the refined geometry P·x must be the
// same surface: the polynomial functionals ∫ det J (area) and ∫ z det J of the map are equal before and after
// (both exact: geometric series at the EF elements), which they would not be for a different map.
#include "support/paths.hpp"
#include <gtest/gtest.h>

#include <random>

#include "basis/registry.hpp"
#include "mesh/obj_reader.hpp"
#include "mesh/three_valent.hpp"
#include "quadrature/exact/geometry_integrals.hpp"
#include "basis/space.hpp"

using namespace iga;

namespace {

basis::Geometry perturbed(const std::string& triangles, bool lift, unsigned seed) {
  const mesh::PolyMesh net = mesh::dual_net(mesh::read_obj(std::string(IGA_SOURCE_DIR) + "/data/meshes/" + triangles));
  basis::BackendFacts facts;
  const basis::Geometry g = basis::make_geometry(basis::backend("halfbox"), &net, basis::BackendOptions{}, facts);
  std::mt19937 rng(seed);
  std::normal_distribution<double> noise(0.0, 0.01);
  Eigen::MatrixXd cp = Eigen::MatrixXd::Zero(g.control_points().rows(), lift ? 3 : 2);
  cp.leftCols(2) = g.control_points();
  for (Index i = 0; i < cp.rows(); ++i) {
    for (Index c = 0; c < cp.cols(); ++c) cp(i, c) += c < 2 ? noise(rng) : 5.0 * noise(rng);
  }
  return basis::Geometry(g.space_ptr(), cp);
}

}  // namespace

TEST(HalfBoxRefinement, NestedWithARecedingBoundary) {
  for (const std::string file : {"tri_square.obj", "tri_l_shape.obj"}) {
    for (const bool lift : {false, true}) {
      SCOPED_TRACE(file + (lift ? " lifted" : " planar"));
      const basis::Geometry g = perturbed(file, lift, 7);
      basis::BackendFacts facts;
      const basis::Refinement r = basis::refine_uniform(g, 2, facts);
      ASSERT_TRUE(r.nested);
      EXPECT_EQ(r.geometry.space().num_elements(), 16 * g.space().num_elements());
      EXPECT_EQ(r.geometry.space().boundary_edges().size(), 4 * g.space().boundary_edges().size());
      // Rows of the prolongation sum to one (it maps constants to constants).
      EXPECT_LE((r.prolongation * Eigen::VectorXd::Ones(g.space().num_dofs()) - Eigen::VectorXd::Ones(r.prolongation.rows()))
                    .cwiseAbs().maxCoeff(), 1e-14);
      if (!lift) {
        const double a = quadrature::exact::exact_area(g), b = quadrature::exact::exact_area(r.geometry);
        EXPECT_NEAR(a, b, 1e-13 * std::abs(a));
      } else {
        const double a = quadrature::exact::exact_volume(g), b = quadrature::exact::exact_volume(r.geometry);
        EXPECT_NEAR(a, b, 1e-13 * std::abs(a)) << a;
      }
    }
  }
}

// The functionals do tell different maps apart: moving one interior control point changes them.
TEST(HalfBoxRefinement, TheCheckSeesAMovedPoint) {
  basis::Geometry g = perturbed("tri_square.obj", false, 7);
  const double a = quadrature::exact::exact_area(g);
  Eigen::MatrixXd cp = g.control_points();
  cp(cp.rows() / 2, 0) += 0.01;
  const basis::Geometry moved(g.space_ptr(), cp);
  EXPECT_GT(std::abs(quadrature::exact::exact_area(moved) - a), 1e-6);
}

// The boundary of a net with a boundary (thesis §3.2.1, "Boundaries and creases": along an ordinary boundary
// the boundary curve is a C1 cubic B-spline with double knots): every boundary side of a regular element is a
// cubic (its fourth differences along t vanish), consecutive sides meet with equal end point and equal
// derivative d/dt, i.e. C1 with uniform double knots. Measured on the dual of tri_square at sides of regular
// elements whose neighbours along the boundary are regular too.
TEST(HalfBoxRefinement, OrdinaryBoundaryIsAC1CubicSpline) {
  const mesh::PolyMesh net = mesh::dual_net(mesh::read_obj(std::string(IGA_SOURCE_DIR) + "/data/meshes/tri_square.obj"));
  basis::BackendFacts facts;
  const basis::Geometry g = basis::make_geometry(basis::backend("halfbox"), &net, basis::BackendOptions{}, facts);
  struct End {
    Eigen::Vector3d start, end, d_start, d_end;
    bool regular;
  };
  std::vector<End> ends;
  double worst_cubic = 0;
  basis::GeometryValues gv;
  for (const basis::BoundaryEdge& b : g.space().boundary_edges()) {
    const basis::Shape shape = g.space().kind(b.element).shape;
    Eigen::Matrix2Xd pts(2, 5);
    for (int k = 0; k < 5; ++k) pts.col(k) = basis::side_point(shape, b.side, k / 4.0);
    g.evaluate(b.element, pts, gv);
    const Eigen::Vector2d dt = basis::side_tangent(shape, b.side);
    const bool regular = g.space().kind(b.element).family == basis::Family::Regular;
    if (regular) {
      const Eigen::Vector3d fourth = gv.x.col(0) - 4 * gv.x.col(1) + 6 * gv.x.col(2) - 4 * gv.x.col(3) + gv.x.col(4);
      worst_cubic = std::max(worst_cubic, fourth.norm());
    }
    ends.push_back({gv.x.col(0), gv.x.col(4), dt(0) * gv.xu.col(0) + dt(1) * gv.xv.col(0),
                    dt(0) * gv.xu.col(4) + dt(1) * gv.xv.col(4), regular});
  }
  EXPECT_LE(worst_cubic, 1e-13);
  int joins = 0;
  double worst_c0 = 0, worst_c1 = 0;
  for (const End& a : ends) {
    for (const End& b : ends) {
      if (!a.regular || !b.regular || (a.end - b.start).norm() > 1e-9) continue;
      ++joins;
      worst_c0 = std::max(worst_c0, (a.end - b.start).norm());
      worst_c1 = std::max(worst_c1, (a.d_end - b.d_start).norm() / a.d_end.norm());
    }
  }
  EXPECT_GE(joins, 16);  // 20 joins of regular boundary sides on this net
  EXPECT_LE(worst_c0, 1e-13);
  EXPECT_LE(worst_c1, 1e-12);
}
