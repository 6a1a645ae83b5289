// The biharmonic equation on the C1 spaces beyond tensor B-splines (issue 31): Catmull–Clark at extraordinary
// vertices (natural and clamped boundary rule), polyhedral splines and half-box splines, u = sin²(πx) sin²(πy)
// clamped, and u = sin(πx) sin(πy) simply supported, on the unit square (nets square_6x6.obj, square_evs.obj,
// tri_square.obj's dual) and clamped on closed fans. Rates fitted over three levels, printed for the README's table.
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <numbers>

#include "basis/registry.hpp"
#include "fem/problem.hpp"
#include "mesh/obj_reader.hpp"
#include "mesh/three_valent.hpp"
#include "pde/biharmonic/biharmonic.hpp"
#include "quadrature/rule_provider.hpp"
#include "support/biharmonic_solutions.hpp"
#include "support/nets.hpp"
#include "support/paths.hpp"
#include "support/rates.hpp"

using namespace iga;
using std::numbers::pi;
using test::bump;
using test::bump_source;

namespace {

// u = sin(πx) sin(πy): u = Δu = 0 on the square's edges (simply supported), Δ²u = 4π⁴ u; its second normal
// derivative vanishes on the boundary, as every function of the natural Catmull–Clark boundary rule's does.
std::shared_ptr<fem::Function> sine() {
  return fem::make_function(
      [](const Eigen::Vector3d& x) { return std::sin(pi * x(0)) * std::sin(pi * x(1)); },
      [](const Eigen::Vector3d& x) {
        return Eigen::Vector3d(pi * std::cos(pi * x(0)) * std::sin(pi * x(1)), pi * std::sin(pi * x(0)) * std::cos(pi * x(1)), 0);
      },
      [](const Eigen::Vector3d& x) {
        Eigen::Matrix3d h = Eigen::Matrix3d::Zero();
        h(0, 0) = h(1, 1) = -pi * pi * std::sin(pi * x(0)) * std::sin(pi * x(1));
        h(0, 1) = h(1, 0) = pi * pi * std::cos(pi * x(0)) * std::cos(pi * x(1));
        return h;
      });
}
std::shared_ptr<fem::Function> sine_source() {
  return fem::make_function([](const Eigen::Vector3d& x) { return 4 * std::pow(pi, 4) * std::sin(pi * x(0)) * std::sin(pi * x(1)); });
}

struct Measured {
  double l2, h1, h2;
};

// Clamped bump (∂²u/∂n² = 2π² sin²(πt) on the edges) or, simply_supported, the sine on every part.
Measured measure(const std::string& name, const std::string& backend, const mesh::PolyMesh& net,
                 basis::BackendOptions options, int first, const std::string& rule, bool simply_supported = false) {
  const basis::Backend& b = basis::backend(backend);
  const auto rules = quadrature::make_rule_provider(rule, basis::degree(b, options) + 1);
  pde::BiharmonicData data = pde::biharmonic_data_from_exact(bump(), bump_source());
  if (simply_supported) {
    basis::BackendFacts facts;
    std::vector<int> all(basis::make_geometry(b, &net, options, facts).space().boundary_part_names().size());
    for (std::size_t i = 0; i < all.size(); ++i) all[i] = static_cast<int>(i);
    data = pde::biharmonic_data_from_exact(sine(), sine_source(), all);
  }
  std::vector<double> l2, h1, h2;
  for (int level = first; level < first + 3; ++level) {
    basis::BackendFacts facts;
    const basis::Geometry g = basis::make_refined_geometry(b, &net, options, level, facts).geometry;
    const fem::ProblemResult r = fem::solve_problem(g, *rules, pde::make_biharmonic(data));
    l2.push_back(r.error("L2").error);
    h1.push_back(r.error("H1").error);
    h2.push_back(r.error("H2").error);
    std::cout << "  " << name << " level " << level << ", dofs " << r.dofs << ": L2 " << l2.back() << ", H1 "
              << h1.back() << ", H2 " << h2.back() << "\n";
  }
  const Measured m{test::fitted_rate(l2), test::fitted_rate(h1), test::fitted_rate(h2)};
  std::cout << name << ": rates L2 " << m.l2 << ", H1 " << m.h1 << ", H2 " << m.h2 << "\n";
  return m;
}

mesh::PolyMesh net(const std::string& file) {
  return mesh::read_obj(std::string(IGA_SOURCE_DIR) + "/data/meshes/" + file);
}

}  // namespace

// Measured (levels 1-3): the regular net square_6x6 is optimal with either boundary rule (natural, sine: 4.02 / 3.01 /
// 2.01; clamped 4.02 / 3.01 / 2.01); interior EVs with the clamped rule (closed fans of valence 3, 5, 6, the clamped
// bump's data from the exact solution) 4.65 / 3.65 / 2.36, 4.58 / 3.56 / 2.29, 4.35 / 3.57 / 2.29 (tiles:4:12 gives
// the same to 4 digits, so the quadrature at the EVs is not what limits). square_evs with the natural rule (interior
// EVs and a boundary EV of three faces) loses order: sine 0.65 / 0.56 / 0.36, clamped bump 1.09 / 1.11 / 0.55 (there
// the natural rule's zero second normal derivative also meets u_nn = 2π² sin²(πt) ≠ 0). The clamped rule is refused
// at that boundary EV (traces nearly dependent; Nitsche for u would need third derivatives). Floors: the 0.9
// where it is met, the measured figures less 0.1 where it is not (README, "iga and the biharmonic equation").
TEST(BiharmonicBackends, CatmullClarkAtExtraordinaryVertices) {
  basis::BackendOptions natural, clamped;
  clamped.cc_boundary = "clamped";
  const Measured regular = measure("cc natural, square_6x6, sine", "cc", net("square_6x6.obj"), natural, 1, "tiles:4:8", true);
  EXPECT_GE(regular.l2, 3.8);
  EXPECT_GE(regular.h2, 1.8);
  for (int n : {3, 5, 6}) {
    const Measured fan = measure("cc clamped, fan of valence " + std::to_string(n) + ", clamped bump", "cc",
                                 test::closed_fan(n, 2), clamped, 1, "tiles:4:8");
    EXPECT_GE(fan.l2, 3.8) << n;
    EXPECT_GE(fan.h2, 1.8) << n;
  }
  const Measured ns = measure("cc natural, square_evs, sine", "cc", net("square_evs.obj"), natural, 1, "tiles:4:8", true);
  const Measured nc = measure("cc natural, square_evs, clamped bump", "cc", net("square_evs.obj"), natural, 1, "tiles:4:8");
  EXPECT_GE(ns.h2, 0.26);
  EXPECT_GE(ns.l2, 0.55);
  EXPECT_GE(nc.h2, 0.45);
  EXPECT_GE(nc.l2, 0.99);
}

// Measured (bi-2 polyhedral splines, nets refined by Catmull-Clark steps 1-3): square_evs sine 1.29 / 1.31 / 0.74,
// clamped bump 1.28 / 1.28 / 0.73 — below the 0.9 in H2, as Poisson's H1 on the same star caps is below 2
// (1.88, tests/fem/test_polyhedral_poisson.cpp): the caps' approximation order, not the solver, limits it. (Before
// issue 32 two interior curves were taken for boundary and clamped to the exact data: 1.15 / 1.35 / 0.78 and
// 1.45 / 1.41 / 0.80.)
TEST(BiharmonicBackends, Polyhedral) {
  const Measured s = measure("polyhedral, square_evs, sine", "polyhedral", net("square_evs.obj"), {}, 1, "gauss:4", true);
  const Measured c = measure("polyhedral, square_evs, clamped bump", "polyhedral", net("square_evs.obj"), {}, 1, "gauss:4");
  EXPECT_GE(s.h2, 0.68);
  EXPECT_GE(s.l2, 1.05);
  EXPECT_GE(c.h2, 0.7);
  EXPECT_GE(c.l2, 1.2);
}

TEST(BiharmonicBackends, HalfBox) {
  const mesh::PolyMesh dual = mesh::dual_net(net("tri_square.obj"));
  const Measured s = measure("half-box, dual of tri_square, sine", "halfbox", dual, {}, 1, "gauss:4", true);
  const Measured c = measure("half-box, dual of tri_square, clamped bump", "halfbox", dual, {}, 1, "gauss:4");
  // Measured 1.94 / 1.95 / 0.96 (sine) and 2.09 / 2.06 / 1.02 (clamped bump).
  EXPECT_GE(s.h2, 0.9);
  EXPECT_GE(c.h2, 0.9);
  EXPECT_GE(s.l2, 1.8);
  EXPECT_GE(c.l2, 1.9);
}
