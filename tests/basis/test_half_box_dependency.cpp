// Global linear dependence of half-box splines (basis/half_box/dependency.hpp): on a net of hexagons only
// (the dual of a torus triangulation with all valences 6) the alternating pattern is a null combination of
// the 13 functions of every patch, so the space leaves one function out; the map and the solution space are
// unchanged and the mass matrix becomes positive definite. Nets with odd faces keep all their functions.
#include "support/paths.hpp"
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <Eigen/Sparse>
#include <cmath>
#include <iostream>

#include "basis/half_box/irregular_patch.hpp"
#include "basis/half_box/patch_net.hpp"
#include "basis/half_box/space.hpp"
#include "basis/registry.hpp"
#include "fem/expression.hpp"
#include "fem/poisson.hpp"
#include "mesh/obj_reader.hpp"
#include "mesh/three_valent.hpp"
#include "quadrature/exact/geometry_integrals.hpp"
#include "quadrature/per_tile.hpp"
#include "support/rates.hpp"

using namespace iga;
using basis::half_box::HalfBoxSpace;

namespace {

mesh::PolyMesh dual_of(const std::string& file) {
  return mesh::dual_net(mesh::read_obj(std::string(IGA_SOURCE_DIR) + "/data/meshes/" + file));
}

Eigen::MatrixXd mass_matrix(const basis::Space& s) {
  const quadrature::PerTile rules(5, 12);
  Eigen::MatrixXd m = Eigen::MatrixXd::Zero(s.num_dofs(), s.num_dofs());
  basis::BasisValues bv;
  for (Index e = 0; e < s.num_elements(); ++e) {
    const quadrature::Rule& r = rules.rule(s.kind(e));
    s.evaluate(e, r.points, 0, bv);
    const auto d = s.dofs(e);
    const Eigen::MatrixXd loc = bv.value * r.weights.asDiagonal() * bv.value.transpose();  // parametric
    for (std::size_t i = 0; i < d.size(); ++i)
      for (std::size_t j = 0; j < d.size(); ++j) m(d[i], d[j]) += loc(static_cast<Index>(i), static_cast<Index>(j));
  }
  return m;
}

// ∫_S φ_a φ_b on the surface (sparse: the refined tori have thousands of dofs).
Eigen::SparseMatrix<double> physical_mass_matrix(const basis::Geometry& g) {
  const quadrature::PerTile rules(5, 12);
  std::vector<Eigen::Triplet<double>> entries;
  basis::BasisValues bv;
  basis::GeometryValues gv;
  for (Index e = 0; e < g.space().num_elements(); ++e) {
    const quadrature::Rule& r = rules.rule(g.space().kind(e));
    g.space().evaluate(e, r.points, 1, bv);
    g.evaluate(e, bv, gv);
    const auto d = g.space().dofs(e);
    const Eigen::MatrixXd loc = bv.value * (r.weights.array() * gv.measure.array()).matrix().asDiagonal() * bv.value.transpose();
    for (std::size_t i = 0; i < d.size(); ++i)
      for (std::size_t j = 0; j < d.size(); ++j) entries.emplace_back(d[i], d[j], loc(static_cast<Index>(i), static_cast<Index>(j)));
  }
  Eigen::SparseMatrix<double> m(g.space().num_dofs(), g.space().num_dofs());
  m.setFromTriplets(entries.begin(), entries.end());
  return m;
}

}  // namespace

TEST(HalfBoxDependency, HexagonalTorusLeavesOneFunctionOut) {
  const mesh::PolyMesh net = dual_of("tri_torus.obj");
  const HalfBoxSpace space(net);
  ASSERT_TRUE(space.reduced());
  EXPECT_EQ(space.num_dofs(), net.num_vertices() - 1);
  // The full function set (13 per patch, one per net vertex, gathered and evaluated independently of the
  // space's reduction) has a Gram matrix with exactly one null vector, and it is ±1 up to scale.
  const quadrature::PerTile rules(5, 12);
  const quadrature::Rule& r = rules.rule(basis::ElementKind{basis::Shape::Triangle, basis::Family::Regular, 6});
  basis::BasisValues full;
  basis::half_box::evaluate_patch(6, r.points, 0, full);
  const Eigen::MatrixXd local = full.value * r.weights.asDiagonal() * full.value.transpose();
  Eigen::MatrixXd gram = Eigen::MatrixXd::Zero(net.num_vertices(), net.num_vertices());
  for (Index v = 0; v < net.num_vertices(); ++v) {
    const auto p = basis::half_box::patch_net(net, v);
    for (std::size_t i = 0; i < p.points.size(); ++i)
      for (std::size_t j = 0; j < p.points.size(); ++j)
        gram(p.points[i], p.points[j]) += local(static_cast<Index>(i), static_cast<Index>(j));
  }
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> full_eig(gram);
  EXPECT_LT(full_eig.eigenvalues()(0), 1e-14 * full_eig.eigenvalues().maxCoeff());
  EXPECT_GT(full_eig.eigenvalues()(1), 1e-8 * full_eig.eigenvalues().maxCoeff());
  const Eigen::VectorXd null = full_eig.eigenvectors().col(0);
  EXPECT_LE((null.cwiseAbs().array() - 1.0 / std::sqrt(double(net.num_vertices()))).abs().maxCoeff(), 1e-10);
  // The reduced functions have a positive definite Gram matrix.
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(mass_matrix(space));
  EXPECT_GT(eig.eigenvalues()(0), 1e-8 * eig.eigenvalues().maxCoeff());
}

// The map is unchanged: the reduced geometry (control points from_vertices() · positions) equals Σ_v P_v φ_v
// of the full patches at random points of every element.
TEST(HalfBoxDependency, TheMapIsUnchanged) {
  const mesh::PolyMesh net = dual_of("tri_torus.obj");
  basis::BackendFacts facts;
  const basis::Geometry g = basis::make_geometry(basis::backend("halfbox"), &net, basis::BackendOptions{}, facts);
  const auto& space = dynamic_cast<const HalfBoxSpace&>(g.space());
  Eigen::Matrix2Xd pts(2, 3);
  pts << 0.2, 0.5, 0.1, 0.3, 0.25, 0.7;
  basis::BasisValues full;
  basis::half_box::evaluate_patch(6, pts, 0, full);
  basis::GeometryValues gv;
  double worst = 0;
  for (Index e = 0; e < space.num_elements(); ++e) {
    g.evaluate(e, pts, gv);
    // Full patch points of the element's vertex, in patch order, from the net.
    const auto p = basis::half_box::patch_net(space.control_net(), space.element_vertex(e));
    Eigen::MatrixXd x(static_cast<Index>(p.points.size()), 3);
    for (std::size_t i = 0; i < p.points.size(); ++i) x.row(static_cast<Index>(i)) = net.point(p.points[i]).transpose();
    worst = std::max(worst, (full.value.transpose() * x - gv.x.transpose()).cwiseAbs().maxCoeff());
  }
  EXPECT_LE(worst, 1e-12);
}

TEST(HalfBoxDependency, NetsWithOddFacesOrQuadsKeepEveryFunction) {
  for (const std::string file : {"tri_sphere.obj", "tri_square.obj", "tri_l_shape.obj"}) {
    const HalfBoxSpace space(dual_of(file));
    EXPECT_FALSE(space.reduced()) << file;
  }
}

// Laplace–Beltrami on the limit surface of the hexagonal torus net (every element regular): solvable after
// the reduction (CHOLMOD refused the unreduced system as not positive definite), refinement of the reduced
// spaces is nested (the exact volume ∫ z det J is unchanged, 10.454542619589...), and the solutions
// self-converge: ‖u_{l+1} − u_l‖_L2(S) = 5.9e-3, 6.2e-4, 6.9e-5, fitted rate 3.21.
TEST(HalfBoxDependency, LaplaceBeltramiOnTheTorus) {
  const mesh::PolyMesh net = dual_of("tri_torus.obj");
  fem::PoissonProblem p;
  p.reaction = 1.0;
  p.source = std::make_shared<fem::Expression>("x + y*z", "source");
  const quadrature::PerTile rules(4, 4);
  basis::BackendFacts facts;
  basis::Geometry g = basis::make_geometry(basis::backend("halfbox"), &net, basis::BackendOptions{}, facts);
  Eigen::VectorXd u = fem::solve_poisson(g, rules, p).u;
  std::vector<double> differences;
  for (int level = 1; level <= 3; ++level) {
    const basis::Refinement r = basis::refine_uniform(g, 1, facts);
    ASSERT_TRUE(r.nested);
    EXPECT_NEAR(quadrature::exact::exact_volume(r.geometry), quadrature::exact::exact_volume(g), 1e-12);
    const Eigen::VectorXd coarse_on_fine = r.prolongation * u;
    g = r.geometry;
    u = fem::solve_poisson(g, rules, p).u;
    const Eigen::VectorXd d = u - coarse_on_fine;
    differences.push_back(std::sqrt(d.dot(physical_mass_matrix(g) * d)));
  }
  const double rate = iga::test::fitted_rate(differences);
  std::cout << "torus: differences " << differences[0] << " " << differences[1] << " " << differences[2] << ", rate " << rate << std::endl;
  EXPECT_GE(rate, 2.8);
}
