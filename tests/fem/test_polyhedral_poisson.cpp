// Polyhedral splines through the whole pipeline (basis/polyhedral/space.hpp + fem::solve_poisson): the
// patch test (an affine solution is reproduced, also through the coupled Dirichlet constraints of the
// receding boundary) and convergence under Catmull–Clark refinement of the net (the spaces are not nested).
#include "support/paths.hpp"
#include <gtest/gtest.h>

#include "basis/polyhedral/configuration.hpp"
#include "basis/polyhedral/space.hpp"
#include "basis/polyhedral_nets.hpp"
#include "fem/function.hpp"
#include "fem/poisson.hpp"
#include "fem/problems.hpp"
#include "mesh/obj_reader.hpp"
#include "quadrature/rule_provider.hpp"
#include "support/rates.hpp"

using namespace iga;
using iga::test::fitted_rate;

namespace {

mesh::PolyMesh grid(int n) {
  std::vector<Eigen::Vector3d> p;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) p.emplace_back(double(i) / (n - 1), double(j) / (n - 1), 0.0);
  std::vector<std::vector<Index>> f;
  for (int j = 0; j + 1 < n; ++j)
    for (int i = 0; i + 1 < n; ++i) f.push_back({j * n + i, j * n + i + 1, (j + 1) * n + i + 1, (j + 1) * n + i});
  return mesh::PolyMesh::build(p, f);
}

// The unit square with a T0 configuration: rows 0..2 of 6 vertices (5 quads per row), rows 3..5 of 5
// vertices (4 quads), and between rows 2 and 3 four quads and one triangle (b2, b3, t2), whose corner t2
// has valence 5 (the T0 triangle (5, 4, 4) of the paper, a change in the number of columns).
mesh::PolyMesh square_with_t0() {
  std::vector<Eigen::Vector3d> p;
  std::vector<std::vector<Index>> rows;
  for (int r = 0; r < 6; ++r) {
    const int m = r < 3 ? 6 : 5;
    rows.emplace_back();
    for (int k = 0; k < m; ++k) {
      rows.back().push_back(static_cast<Index>(p.size()));
      p.emplace_back(double(k) / (m - 1), r / 5.0, 0.0);
    }
  }
  std::vector<std::vector<Index>> f;
  for (int r = 0; r < 5; ++r) {
    const auto& lo = rows[static_cast<std::size_t>(r)];
    const auto& hi = rows[static_cast<std::size_t>(r + 1)];
    if (lo.size() == hi.size()) {
      for (std::size_t k = 0; k + 1 < lo.size(); ++k) f.push_back({lo[k], lo[k + 1], hi[k + 1], hi[k]});
    } else {
      f.push_back({lo[0], lo[1], hi[1], hi[0]});
      f.push_back({lo[1], lo[2], hi[2], hi[1]});
      f.push_back({lo[2], lo[3], hi[2]});
      f.push_back({lo[3], lo[4], hi[3], hi[2]});
      f.push_back({lo[4], lo[5], hi[4], hi[3]});
    }
  }
  return mesh::PolyMesh::build(p, f);
}

fem::PoissonResult solve(const mesh::PolyMesh& net, const std::string& problem) {
  const basis::Geometry g = basis::polyhedral::make_polyhedral_geometry(net);
  const fem::ManufacturedProblem m = fem::manufactured_problem(problem);
  fem::PoissonProblem p;
  p.source = m.source;
  p.dirichlet = m.exact;
  p.exact = m.exact;
  return fem::solve_poisson(g, quadrature::Gauss(4), p);
}

}  // namespace

TEST(PolyhedralPoisson, UnitSquareNetWithATJunction) {
  int t0 = 0;
  for (const auto& site : basis::polyhedral::classify(square_with_t0())) t0 += site.type == basis::polyhedral::Configuration::T0;
  EXPECT_EQ(t0, 1);
}

TEST(PolyhedralPoisson, PatchTest) {
  std::vector<std::pair<std::string, mesh::PolyMesh>> nets{
      {"square_evs", mesh::read_obj(std::string(IGA_SOURCE_DIR) + "/data/meshes/square_evs.obj")}, {"grid", grid(6)}};
  for (int n : {3, 5, 6, 7, 8}) {
    nets.emplace_back("star " + std::to_string(n), polyhedral_nets::star_net(n, 50 + n, true));
    nets.emplace_back("ngon " + std::to_string(n), polyhedral_nets::flattened(polyhedral_nets::ngon_net(n, 60 + n)));
  }
  for (int n = 3; n <= 8; ++n) nets.emplace_back("polar " + std::to_string(n), polyhedral_nets::flattened(polyhedral_nets::polar_net(n, 70 + n)));
  nets.emplace_back("T0", polyhedral_nets::flattened(polyhedral_nets::t0_net(false, 81)));
  nets.emplace_back("unit square with T0", square_with_t0());
  nets.emplace_back("T1", polyhedral_nets::flattened(polyhedral_nets::t1_net(false, 82)));
  nets.emplace_back("T2", polyhedral_nets::flattened(polyhedral_nets::t2_net(false, 83)));
  for (const auto& [name, net] : nets) {
    const fem::PoissonResult r = solve(net, "linear");
    ASSERT_TRUE(r.errors);
    EXPECT_LE(r.errors->l2 / r.errors->l2_exact, 1e-10) << name;
    EXPECT_LE(r.errors->h1 / r.errors->h1_exact, 1e-10) << name;
    EXPECT_GT(r.dirichlet_dofs, 0) << name;
  }
}

TEST(PolyhedralPoisson, ConvergenceUnderNetRefinement) {
  // u = sin πx sin πy, nets refined by 0..3 Catmull–Clark steps (h halves; the receding boundary moves
  // toward the square, the exact solution is defined everywhere). Regular bi-2 patches only: L2 rate 3,
  // H1 rate 2 (measured 2.97 / 1.96 on the last pair). With star caps (square_evs.obj: valences 3, 5, 6,
  // whose caps keep their patch count while the regular part grows) the fitted rates are 2.78 and 1.88 (before
  // issue 32 two interior curves were taken for boundary and held to the data: L2 2.49, 2.30, 2.14 and H1 2.17,
  // 1.75, 1.66 per level) — asserted as floors below.
  struct Case {
    std::string name;
    mesh::PolyMesh net;
    double l2_floor, h1_floor;
  };
  std::vector<Case> cases{{"grid", grid(6), 2.9, 1.85},
                          {"square_evs", mesh::read_obj(std::string(IGA_SOURCE_DIR) + "/data/meshes/square_evs.obj"), 2.65, 1.8},
                          {"unit square with T0", square_with_t0(), 2.4, 1.5}};  // measured 2.55 / 1.63
  for (const Case& c : cases) {
    std::vector<double> l2, h1;
    for (int level = 0; level <= 3; ++level) {
      const mesh::PolyMesh net = level ? basis::polyhedral::presubdivide(c.net, level) : c.net;
      const fem::PoissonResult r = solve(net, "sine");
      l2.push_back(r.errors->l2);
      h1.push_back(r.errors->h1);
    }
    const double rl2 = fitted_rate(l2), rh1 = fitted_rate(h1);
    std::cout << c.name << ": fitted L2 rate " << rl2 << ", H1 rate " << rh1 << std::endl;
    EXPECT_GE(rl2, c.l2_floor) << c.name;
    EXPECT_GE(rh1, c.h1_floor) << c.name;
  }
}

// Issue 32: in square_evs.obj a coarse patch's side meets four patches of a star cap, each along a quarter of it.
// Sides were matched only as wholes or halves, so both sides of that curve (two of them in this net) were
// reported as boundary: zero-area slits inside the domain on which the FEM imposed the Dirichlet data (right only
// when the data are the exact solution). The torsion problem −Δu = 1, u = 0 on the boundary, shows it: by the
// maximum principle u > 0 inside, but on a slit u_h was 0. Each slit runs through the point where the coarse
// side's midpoint lies, (0.5104, 0.2396) and (0.5150, 0.4225) (from the net: sides of faces of square_evs.obj).
TEST(PolyhedralPoisson, InteriorSidesMetInQuartersAreNotBoundary) {
  const basis::Geometry g = basis::polyhedral::make_polyhedral_geometry(
      mesh::read_obj(std::string(IGA_SOURCE_DIR) + "/data/meshes/square_evs.obj"));
  fem::PoissonProblem p;
  p.source = fem::constant_function(1.0);
  const fem::PoissonResult r = fem::solve_poisson(g, quadrature::Gauss(4), p);
  // u_h at every element's side midpoints near the two points, and its largest value.
  const basis::Space& space = g.space();
  const Eigen::Vector2d targets[2] = {{0.5104, 0.2396}, {0.5150, 0.4225}};
  double near[2] = {-1.0, -1.0}, largest = 0.0;
  for (Index e = 0; e < space.num_elements(); ++e) {
    Eigen::Matrix2Xd pts(2, 5);
    for (int s = 0; s < 4; ++s) pts.col(s) = basis::side_point(space.kind(e).shape, s, 0.5);
    pts.col(4) << 0.5, 0.5;
    basis::BasisValues b;
    space.evaluate(e, pts, 1, b);
    basis::GeometryValues x;
    g.evaluate(e, b, x, false);
    const auto dofs = space.dofs(e);
    for (int k = 0; k < 5; ++k) {
      double u = 0.0;
      for (std::size_t a = 0; a < dofs.size(); ++a) u += r.u(dofs[a]) * b.value(static_cast<Index>(a), k);
      largest = std::max(largest, u);
      for (int t = 0; t < 2; ++t) {
        if ((x.x.col(k).head<2>() - targets[t]).norm() < 1e-3) near[t] = u;
      }
    }
  }
  for (int t = 0; t < 2; ++t) {
    ASSERT_GE(near[t], 0.0) << "no side midpoint at target " << t;
    EXPECT_GT(near[t], 0.3 * largest) << "u_h on the curve through target " << t << " (largest " << largest << ")";
  }
  // And that curve is now an interior edge: no boundary edge passes through either point.
  for (const basis::BoundaryEdge& e : space.boundary_edges()) {
    Eigen::Matrix2Xd pts(2, 1);
    pts.col(0) = basis::side_point(space.kind(e.element).shape, e.side, 0.5);
    basis::BasisValues b;
    space.evaluate(e.element, pts, 1, b);
    basis::GeometryValues x;
    g.evaluate(e.element, b, x, false);
    for (int t = 0; t < 2; ++t) EXPECT_GT((x.x.col(0).head<2>() - targets[t]).norm(), 1e-3) << "element " << e.element;
  }
}
