// Scordelis and Lo's roof on a Catmull–Clark net with extraordinary vertices of valence 3 and 5 (the shell issue's
// item 3): a quad net of the roof with one edge rotated (two vertices of valence 3, two of valence 5), one
// Catmull–Clark step so that no face touches two of them, its control points fitted so that the limit surface lies on
// the cylinder (natural boundary rule, the roof's corners its corners), then the shell as on the NURBS patch.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <Eigen/SparseCholesky>
#include <algorithm>
#include <cmath>
#include <iostream>
#include <numbers>
#include <set>

#include "basis/catmull_clark/quad_mesh.hpp"
#include "basis/locate.hpp"
#include "basis/registry.hpp"
#include "fem/problem.hpp"
#include "mesh/poly_mesh.hpp"
#include "pde/shell/shell.hpp"
#include "quadrature/rule_provider.hpp"
#include "refine/uniform.hpp"

using namespace iga;

namespace {

constexpr double kDeg = std::numbers::pi / 180;

// A cylindrical shell x = (R sin θ, y, R cos θ), θ0 <= θ <= θ1, 0 <= y <= L (as basis::bspline::make_cylinder_patch).
struct Cylinder {
  double r, length, t0, t1;
  Eigen::Vector3d at(double t, double y) const { return {r * std::sin(t), y, r * std::cos(t)}; }
};

// m × m quads over the cylinder with one edge rotated in the middle (the hexagon of two quads split by its other
// diagonal: two vertices of valence 3, two of valence 5; the two moved a quarter cell so that both quads are convex).
mesh::PolyMesh cylinder_net(const Cylinder& c, int m) {
  std::vector<Eigen::Vector3d> p;
  for (int j = 0; j <= m; ++j)
    for (int i = 0; i <= m; ++i) p.push_back(c.at(c.t0 + (c.t1 - c.t0) * i / m, c.length * j / m));
  auto v = [&](int i, int j) { return Index(j * (m + 1) + i); };
  const int ri = m / 2 - 1, rj = m / 2;  // quads (ri, rj) and (ri + 1, rj) share the edge a = (ri + 1, rj), d = (ri + 1, rj + 1)
  p[static_cast<std::size_t>(v(ri + 1, rj))].y() -= 0.25 * c.length / m;
  p[static_cast<std::size_t>(v(ri + 1, rj + 1))].y() += 0.25 * c.length / m;
  std::vector<std::vector<Index>> f;
  for (int j = 0; j < m; ++j)
    for (int i = 0; i < m; ++i) {
      if (j == rj && i == ri) {  // the hexagon f a b c d e, f = (ri, rj), b = (ri + 2, rj), c = (ri + 2, rj + 1), e = (ri, rj + 1)
        f.push_back({v(ri, rj), v(ri + 1, rj), v(ri + 2, rj), v(ri + 2, rj + 1)});      // f a b c
        f.push_back({v(ri + 2, rj + 1), v(ri + 1, rj + 1), v(ri, rj + 1), v(ri, rj)});  // c d e f
      } else if (!(j == rj && i == ri + 1)) {
        f.push_back({v(i, j), v(i + 1, j), v(i + 1, j + 1), v(i, j + 1)});
      }
    }
  return mesh::PolyMesh::build(p, f);
}

// Each boundary part's side of the cylinder, from the mean of its sides' midpoints: 0 the end y = 0, 1 the end y = L,
// 2 the edge θ0, 3 the edge θ1.
std::vector<int> part_roles(const basis::Geometry& g, const Cylinder& c) {
  const basis::Space& space = g.space();
  const std::size_t parts = space.boundary_part_names().size();
  std::vector<Eigen::Vector3d> centre(parts, Eigen::Vector3d::Zero());
  std::vector<int> count(parts, 0), role(parts, -1);
  for (const auto& e : space.boundary_edges()) {
    Eigen::Matrix2Xd mid(2, 1);
    mid.col(0) = basis::side_point(space.kind(e.element).shape, e.side, 0.5);
    basis::GeometryValues gv;
    g.evaluate(e.element, mid, gv);
    centre[static_cast<std::size_t>(e.part)] += gv.x.col(0);
    ++count[static_cast<std::size_t>(e.part)];
  }
  for (std::size_t i = 0; i < parts; ++i) {
    const Eigen::Vector3d x = centre[i] / count[i];
    const double t = std::atan2(x.x(), x.z());
    role[i] = x.y() < 0.2 * c.length ? 0 : x.y() > 0.8 * c.length ? 1 : std::abs(t - c.t0) < std::abs(t - c.t1) ? 2 : 3;
  }
  return role;
}

// The control points of g fitted so that its surface lies on the cylinder: least squares over samples of every element
// towards the samples' radial projections (θ kept in [θ0, θ1], y in [0, L]; boundary samples exactly onto their side's
// plane or line), repeated.
basis::Geometry fit_to_cylinder(const basis::Geometry& g, const Cylinder& c, const std::vector<int>& role) {
  const basis::Space& space = g.space();
  struct Sample {
    Index element;
    Eigen::Vector2d uv;
    int role;
  };
  std::vector<Sample> samples;
  const int k = 5;
  for (Index e = 0; e < space.num_elements(); ++e)
    for (int j = 0; j < k; ++j)
      for (int i = 0; i < k; ++i) samples.push_back({e, Eigen::Vector2d((i + 0.5) / k, (j + 0.5) / k), -1});
  for (const auto& e : space.boundary_edges())
    for (int i = 0; i <= 2 * k; ++i)
      samples.push_back({e.element, basis::side_point(space.kind(e.element).shape, e.side, double(i) / (2 * k)),
                         role[static_cast<std::size_t>(e.part)]});
  std::vector<Eigen::Triplet<double>> entries;
  basis::BasisValues bv;
  Eigen::Matrix2Xd at(2, 1);
  for (std::size_t s = 0; s < samples.size(); ++s) {
    at.col(0) = samples[s].uv;
    space.evaluate(samples[s].element, at, 0, bv);
    const auto dofs = space.dofs(samples[s].element);
    for (std::size_t a = 0; a < dofs.size(); ++a) entries.emplace_back(static_cast<Index>(s), dofs[a], bv.value(static_cast<Index>(a), 0));
  }
  Eigen::SparseMatrix<double> phi(static_cast<Index>(samples.size()), space.num_dofs());
  phi.setFromTriplets(entries.begin(), entries.end());
  const Eigen::SparseMatrix<double> phi_t = phi.transpose(), gram = phi_t * phi;
  const Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> normal(gram);
  Eigen::MatrixXd p = g.control_points();
  for (int it = 0; it < 12; ++it) {
    const Eigen::MatrixXd x = phi * p;
    Eigen::MatrixXd t(x.rows(), 3);
    for (Index s = 0; s < x.rows(); ++s) {
      double theta = std::clamp(std::atan2(x(s, 0), x(s, 2)), c.t0, c.t1), y = std::clamp(x(s, 1), 0.0, c.length);
      const int r = samples[static_cast<std::size_t>(s)].role;
      if (r == 0) y = 0;
      if (r == 1) y = c.length;
      if (r == 2) theta = c.t0;
      if (r == 3) theta = c.t1;
      t.row(s) = c.at(theta, y).transpose();
    }
    p = normal.solve(phi_t * t);
  }
  return basis::Geometry(g.space_ptr(), p);
}

// The fitted Catmull–Clark geometry of cylinder_net(c, m), refined `refine` times; its parts' roles.
basis::Geometry fitted_net(const Cylinder& c, int m, int refine, std::vector<int>& role) {
  const mesh::PolyMesh net = cylinder_net(c, m);
  basis::BackendOptions o;
  basis::BackendFacts facts;
  const basis::Geometry g0 = basis::make_geometry(basis::backend("cc"), &net, o, facts);
  role = part_roles(g0, c);
  return refine::refine_uniform(fit_to_cylinder(g0, c, role), refine).geometry;
}

// The largest | |x| − R | over a point of every element, and the valences of the extraordinary vertices.
double distance_from(const basis::Geometry& g, const Cylinder& c, std::set<int>& valences) {
  double err = 0;
  for (Index e = 0; e < g.space().num_elements(); ++e) {
    if (g.space().kind(e).family == basis::Family::Irregular) valences.insert(g.space().kind(e).valence);
    Eigen::Matrix2Xd at(2, 1);
    at << 0.37, 0.61;
    basis::GeometryValues gv;
    g.evaluate(e, at, gv);
    err = std::max(err, std::abs(std::hypot(gv.x(0, 0), gv.x(2, 0)) - c.r));
  }
  return err;
}

std::vector<int> parts_of(const std::vector<int>& role, std::initializer_list<int> which) {
  std::vector<int> out;
  for (std::size_t i = 0; i < role.size(); ++i) {
    if (std::find(which.begin(), which.end(), role[i]) != which.end()) out.push_back(static_cast<int>(i));
  }
  return out;
}

}  // namespace

// Measured (net m × m before the step; w against 0.3006): m = 8: −0.78 %, −0.32 %, −0.30 % at 0, 1, 2 uniform
// refinements (|r − R| of the fitted surface 5.8e-3: the geometry's error is what remains); m = 16: −0.073 %,
// −0.045 %, −0.042 % (|r − R| 1.5e-3). Within the 0.5 % from m = 8 refined once.
TEST(ShellNets, ScordelisLoOnACatmullClarkNetWithExtraordinaryVertices) {
  const Cylinder roof{25.0, 50.0, -40 * kDeg, 40 * kDeg};
  for (const auto& [m, refine] : {std::pair{8, 1}, std::pair{16, 0}, std::pair{16, 1}}) {
    std::vector<int> role;
    const basis::Geometry g = fitted_net(roof, m, refine, role);
    std::set<int> valences;
    const double err = distance_from(g, roof, valences);
    EXPECT_EQ(valences, (std::set<int>{3, 5}));
    pde::ShellData d;
    d.material = {4.32e8, 0.0, 0.25};
    d.area_load = {nullptr, nullptr, fem::constant_function(-90.0)};
    const std::vector<int> ends = parts_of(role, {0, 1});
    ASSERT_EQ(ends.size(), 2u);
    d.supports = {{0, ends, nullptr}, {2, ends, nullptr}};
    // The fitted surface passes within err of the cylinder's points: the nearest points stand for them.
    d.point_supports = {{basis::nearest_point(g, roof.at(0, 0)).x, 1}};
    const auto rules = quadrature::make_rule_provider("tiles:4:8", 4);
    const fem::ProblemResult r = fem::solve_problem(g, *rules, pde::make_shell(d));
    const basis::LocatedPoint mid = basis::nearest_point(g, roof.at(roof.t1, 25.0));
    const double w = -pde::shell_displacement(g.space(), r.u, mid.element, mid.uv)(2);
    std::cout << "roof net " << m << " x " << m << ", refine " << refine << ": " << r.dofs << " dofs, " << r.elements
              << " elements, |r - R| <= " << err << ": w = " << w << " (" << 100 * (w / 0.3006 - 1) << " % from 0.3006)\n";
    EXPECT_LT(err, 0.03 * roof.r / (m * m));  // measured 0.015 R/m² at m = 8 and 16: the fit's error falls as h²
    EXPECT_LT(std::abs(w / 0.3006 - 1), 0.005);
  }
}
