// Refinement of half-box spaces through the registry: one subdivision step per level, nested for closed nets
// and for nets with a receding boundary alike. With random control points the refined geometry P·x must be the
// same surface: the polynomial functionals ∫ det J (area) and ∫ z det J of the map are equal before and after
// (both exact: geometric series at the EF elements), which they would not be for a different map.
#include <gtest/gtest.h>

#include <random>

#include "basis/registry.hpp"
#include "mesh/obj_reader.hpp"
#include "mesh/three_valent.hpp"
#include "quadrature/exact/geometry_integrals.hpp"

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
