// Exact integrals of half-box elements through the scheme-neutral subdivision view
// (quadrature/exact/subdivision_integrals.hpp, basis/half_box/exact_view.hpp): element integrals against
// partition of unity and a deep per-tile rule, the exact area of planar nets against Green's theorem on the
// boundary curves, and exact area and volume against the per-tile rule at 16 levels.
#include "support/paths.hpp"
#include <gtest/gtest.h>

#include <cmath>

#include "basis/half_box/exact_view.hpp"
#include "basis/half_box/irregular_patch.hpp"
#include "basis/registry.hpp"
#include "fem/assembler.hpp"
#include "mesh/obj_reader.hpp"
#include "mesh/three_valent.hpp"
#include "quadrature/exact/geometry_integrals.hpp"
#include "quadrature/exact/subdivision_integrals.hpp"
#include "quadrature/gauss_legendre.hpp"
#include "quadrature/per_tile.hpp"

using namespace iga;
using namespace iga::quadrature;

namespace {

basis::Geometry half_box_geometry(const std::string& triangles) {
  const mesh::PolyMesh net = mesh::dual_net(mesh::read_obj(std::string(IGA_SOURCE_DIR) + "/data/meshes/" + triangles));
  basis::BackendFacts facts;
  return basis::make_geometry(basis::backend("halfbox"), &net, basis::BackendOptions{}, facts);
}

// Σ_e ∫ detJ by a rule provider (the per-tile rule at irregular elements).
double area_by(const basis::Geometry& g, const RuleProvider& rules, bool volume) {
  const fem::Assembler assembler(g, rules);
  return assembler.integrate(1, [&](const fem::ElementContext& c, Eigen::Ref<Eigen::VectorXd> out) {
    double s = 0;
    for (Eigen::Index k = 0; k < c.rule->size(); ++k) {
      const double det = c.geo.xu(0, k) * c.geo.xv(1, k) - c.geo.xu(1, k) * c.geo.xv(0, k);
      s += c.rule->weights(k) * det * (volume ? c.geo.x(2, k) : 1.0);
    }
    out(0) = s;
  })(0);
}

// Green's theorem: area = ∮ x dy over the boundary sides (counter-clockwise). Each side is split at the dyadic
// points 2^-k and 1 − 2^-k (k = 1..60), where the tiles of an EF element meet it, and every piece gets 4-point
// Gauss (x dy is a polynomial of degree 5 there).
double green_area(const basis::Geometry& g) {
  const Rule1D line = gauss_legendre(4);
  std::vector<double> breaks{0.0, 1.0};
  for (int k = 1; k <= 60; ++k) {
    breaks.push_back(std::ldexp(1.0, -k));
    breaks.push_back(1.0 - std::ldexp(1.0, -k));
  }
  std::sort(breaks.begin(), breaks.end());
  breaks.erase(std::unique(breaks.begin(), breaks.end()), breaks.end());
  double a = 0.0;
  basis::BasisValues bv;
  basis::GeometryValues gv;
  for (const basis::BoundaryEdge& edge : g.space().boundary_edges()) {
    const basis::Shape shape = g.space().kind(edge.element).shape;
    const Eigen::Vector2d dt = basis::side_tangent(shape, edge.side);
    for (std::size_t p = 0; p + 1 < breaks.size(); ++p) {
      const double t0 = breaks[p], h = breaks[p + 1] - breaks[p];
      Eigen::Matrix2Xd pts(2, line.size());
      for (Eigen::Index i = 0; i < line.size(); ++i) pts.col(i) = basis::side_point(shape, edge.side, t0 + h * line.points(i));
      g.space().evaluate(edge.element, pts, 1, bv);
      g.evaluate(edge.element, bv, gv, false);
      for (Eigen::Index i = 0; i < line.size(); ++i) {
        const double dy = dt(0) * gv.xu(1, i) + dt(1) * gv.xv(1, i);
        a += h * line.weights(i) * gv.x(0, i) * dy;
      }
    }
  }
  return a;
}

}  // namespace

// Every EF valence: the functions sum to one, so Σ_ab ∫ φ_a φ_b = Σ_a ∫ φ_a = 1/2 (the triangle's area) and
// the gradient Gram matrices annihilate the constant; the mass matrix equals the per-tile rule with 20 levels
// (its plain-Gauss corner triangle has area 2^-41) to 1e-12 relative.
TEST(ExactHalfBox, ElementIntegralsOfEveryValence) {
  const Rule deep = tiled_triangle_rule(6, 20);
  for (int n = 3; n <= 12; ++n) {
    if (n == 6) continue;
    SCOPED_TRACE(n);
    const Index m = n + 7;
    const basis::SubdivisionElement el{&basis::half_box::half_box_view(n), Eigen::MatrixXd::Identity(m, m), 0, {}};
    const Eigen::VectorXd phi = exact::element_integral(el);
    const Eigen::MatrixXd mass = exact::element_gram(el, -1, -1);
    EXPECT_NEAR(phi.sum(), 0.5, 1e-14);
    EXPECT_NEAR(mass.sum(), 0.5, 1e-14);
    for (int i = 0; i < 2; ++i) {
      for (int j = 0; j < 2; ++j) EXPECT_LE((exact::element_gram(el, i, j) * Eigen::VectorXd::Ones(m)).norm(), 1e-12);
    }
    basis::BasisValues bv;
    basis::half_box::evaluate_irregular(n, deep.points, 0, bv);
    const Eigen::MatrixXd by_rule = bv.value * deep.weights.asDiagonal() * bv.value.transpose();
    EXPECT_LE((mass - by_rule).norm(), 1e-12 * mass.norm());
    EXPECT_LE((phi - bv.value * deep.weights).norm(), 1e-12 * phi.norm());
  }
}

// Planar duals of the square and L-shape triangulations (pentagons and heptagons inside; a receding boundary
// with EF elements on it): the exact area (geometric series at the EF elements) equals Green's theorem on the
// boundary curves, and the per-tile rule at 16 levels (measured 6.8e-15 and 2.7e-14).
TEST(ExactHalfBox, AreaEqualsTheBoundaryIntegral) {
  for (const std::string file : {"tri_square.obj", "tri_l_shape.obj"}) {
    SCOPED_TRACE(file);
    const basis::Geometry g = half_box_geometry(file);
    const double exact = exact::exact_area(g);
    EXPECT_NEAR(exact, green_area(g), 1e-12);
    EXPECT_NEAR(exact, area_by(g, PerTile(4, 16), false), 1e-12);
    EXPECT_GT(std::abs(exact - area_by(g, Gauss(4), false)), 1e-8);  // plain Gauss is not exact at the EFs
  }
}

// The closed limit surface of the dual of the geodesic sphere (12 pentagons): exact enclosed volume against
// the per-tile rule at 16 levels (measured 4.2e-13), and the surface is a sphere-like body of volume < 4π/3.
TEST(ExactHalfBox, VolumeOfAClosedNet) {
  const basis::Geometry g = half_box_geometry("tri_sphere.obj");
  const double exact = exact::exact_volume(g);
  EXPECT_NEAR(exact, area_by(g, PerTile(5, 16), true), 1e-12 * exact);
  EXPECT_GT(exact, 3.5);
  EXPECT_LT(exact, 4.0 * M_PI / 3.0);
}
