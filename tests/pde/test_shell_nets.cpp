// The shell obstacle course on Catmull–Clark nets with extraordinary vertices of valence 3 and 5 (the shell issue's
// item 3): quad nets with one edge rotated (two vertices of valence 3, two of valence 5), their control points fitted by
// least squares so that the limit surface lies on the exact shape. Scordelis and Lo's roof (one Catmull–Clark step so
// that no face touches two EVs, natural boundary rule, the roof's corners its corners), the pinched cylinder on the
// whole tube and the pinched hemisphere on the whole band (clamped rule), then the shell as on the NURBS patches.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <iostream>
#include <numbers>
#include <functional>
#include <set>
#include <tuple>

#include "basis/bspline/patches.hpp"
#include "basis/catmull_clark/quad_mesh.hpp"
#include "basis/fit_surface.hpp"
#include "basis/locate.hpp"
#include "basis/registry.hpp"
#include "fem/problem.hpp"
#include "mesh/poly_mesh.hpp"
#include "mesh/three_valent.hpp"
#include "pde/shell/shell.hpp"
#include "quadrature/rule_provider.hpp"
#include "refine/uniform.hpp"
#include "support/rates.hpp"

using namespace iga;

namespace {

constexpr double kDeg = std::numbers::pi / 180;

// A cylindrical shell x = (R sin θ, y, R cos θ), θ0 <= θ <= θ1, 0 <= y <= L (as basis::bspline::make_cylinder_patch).
struct Cylinder {
  double r, length, t0, t1;
  Eigen::Vector3d at(double t, double y) const { return {r * std::sin(t), y, r * std::cos(t)}; }
  basis::ExactSurface shape() const { return {basis::ExactSurface::Kind::kCylinder, r, {t0, t1}, {0.0, length}}; }
};

// The faces of ni × nj quads, vertex (i, j) being v(i, j), with the edge between quads (ri, rj) and (ri + 1, rj) rotated:
// the hexagon f a b c d e of the two (f = (ri, rj), a = (ri + 1, rj), b = (ri + 2, rj), c = (ri + 2, rj + 1),
// d = (ri + 1, rj + 1), e = (ri, rj + 1)) split by its other diagonal c f: two vertices of valence 3 (a, d), two of 5.
std::vector<std::vector<Index>> grid_faces(int ni, int nj, const std::function<Index(int, int)>& v, int ri, int rj) {
  std::vector<std::vector<Index>> f;
  for (int j = 0; j < nj; ++j)
    for (int i = 0; i < ni; ++i) {
      if (j == rj && i == ri) {
        f.push_back({v(ri, rj), v(ri + 1, rj), v(ri + 2, rj), v(ri + 2, rj + 1)});      // f a b c
        f.push_back({v(ri + 2, rj + 1), v(ri + 1, rj + 1), v(ri, rj + 1), v(ri, rj)});  // c d e f
      } else if (!(j == rj && i == ri + 1)) {
        f.push_back({v(i, j), v(i + 1, j), v(i + 1, j + 1), v(i, j + 1)});
      }
    }
  return f;
}

// m × m quads over the cylinder with one edge rotated in the middle (grid_faces), its two ends moved a quarter cell so
// that both quads are convex.
mesh::PolyMesh cylinder_net(const Cylinder& c, int m) {
  std::vector<Eigen::Vector3d> p;
  for (int j = 0; j <= m; ++j)
    for (int i = 0; i <= m; ++i) p.push_back(c.at(c.t0 + (c.t1 - c.t0) * i / m, c.length * j / m));
  auto v = [&](int i, int j) { return Index(j * (m + 1) + i); };
  const int ri = m / 2 - 1, rj = m / 2;  // quads (ri, rj) and (ri + 1, rj) share the edge a = (ri + 1, rj), d = (ri + 1, rj + 1)
  p[static_cast<std::size_t>(v(ri + 1, rj))].y() -= 0.25 * c.length / m;
  p[static_cast<std::size_t>(v(ri + 1, rj + 1))].y() += 0.25 * c.length / m;
  return mesh::PolyMesh::build(p, grid_faces(m, m, v, ri, rj));
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

// The fitted Catmull–Clark geometry of cylinder_net(c, m), refined `refine` times; its parts' roles.
basis::Geometry fitted_net(const Cylinder& c, int m, int refine, std::vector<int>& role) {
  const mesh::PolyMesh net = cylinder_net(c, m);
  basis::BackendOptions o;
  basis::BackendFacts facts;
  const basis::Geometry g0 = basis::make_geometry(basis::backend("cc"), &net, o, facts);
  role = part_roles(g0, c);
  return refine::refine_uniform(basis::fit_to_surface(g0, c.shape()).geometry, refine).geometry;
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

// m_t × m_y quads around a whole tube (θ over [−π, π), periodic), one edge rotated near θ = π/2 in the middle.
mesh::PolyMesh tube_net(const Cylinder& c, int mt, int my) {
  std::vector<Eigen::Vector3d> p;
  for (int j = 0; j <= my; ++j)
    for (int i = 0; i < mt; ++i) p.push_back(c.at(-std::numbers::pi + 2 * std::numbers::pi * i / mt, c.length * j / my));
  auto v = [&](int i, int j) { return Index(j * mt + (i % mt)); };
  const int ri = 3 * mt / 4 - 1, rj = my / 2 - 1;
  p[static_cast<std::size_t>(v(ri + 1, rj))].y() -= 0.25 * c.length / my;
  p[static_cast<std::size_t>(v(ri + 1, rj + 1))].y() += 0.25 * c.length / my;
  return mesh::PolyMesh::build(p, grid_faces(mt, my, v, ri, rj));
}

// mλ × mφ quads around the hemisphere's band from the equator to latitude 72° (the 18° hole), λ periodic, one edge
// rotated in the middle of the band.
mesh::PolyMesh band_net(int ml, int mp) {
  const double top = 72 * kDeg;
  std::vector<Eigen::Vector3d> p;
  for (int j = 0; j <= mp; ++j)
    for (int i = 0; i < ml; ++i) {
      const double l = 2 * std::numbers::pi * i / ml, f = top * j / mp;
      p.push_back(10 * Eigen::Vector3d(std::cos(f) * std::cos(l), std::cos(f) * std::sin(l), std::sin(f)));
    }
  auto v = [&](int i, int j) { return Index(j * ml + (i % ml)); };
  const int ri = ml / 8, rj = mp / 2 - 1;
  return mesh::PolyMesh::build(p, grid_faces(ml, mp, v, ri, rj));
}

// The Catmull–Clark geometry of a net (boundary rule `boundary`) fitted to the shape (basis::fit_to_surface), refined
// `refine` times.
basis::Geometry fitted(const mesh::PolyMesh& net, const std::string& boundary, const basis::ExactSurface& shape, int refine) {
  basis::BackendOptions o;
  o.cc_boundary = boundary;
  basis::BackendFacts facts;
  const basis::Geometry g0 = basis::make_geometry(basis::backend("cc"), &net, o, facts);
  return refine::refine_uniform(basis::fit_to_surface(g0, shape).geometry, refine).geometry;
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


// The pinched cylinder on a Catmull–Clark net of the whole tube (no symmetry planes: on the octant's net the natural
// rule's boundary functions converge slowly at the symmetry corner under the load, −5.6 % at 49,923 dofs), two EVs of
// valence 3 and 5, diaphragms at both ends, P = 1 at the top and the bottom of the middle section. Measured: 16 × 8 net
// refined once / twice: −2.58 % / −0.17 % (6,336 / 24,960 dofs); 32 × 16 refined twice +0.11 % (99,072).
TEST(ShellNets, PinchedCylinderOnAWholeTubeNet) {
  const Cylinder c{300.0, 600.0, -std::numbers::pi, std::numbers::pi};
  std::vector<double> w;
  for (int refine : {1, 2}) {
    const basis::Geometry g = fitted(tube_net(c, 16, 8), "natural", c.shape(), refine);
    std::set<int> valences;
    const double err = distance_from(g, c, valences);
    EXPECT_EQ(valences, (std::set<int>{3, 5}));
    const std::vector<int> ends = parts_of(part_roles(g, c), {0, 1});
    ASSERT_EQ(ends.size(), 2u);
    pde::ShellData d;
    d.material = {3e6, 0.3, 3.0};
    d.supports = {{0, ends, nullptr}, {2, ends, nullptr}};
    d.point_supports = {{basis::nearest_point(g, c.at(0, 0)).x, 1}};  // the axial translation
    const basis::LocatedPoint top = basis::nearest_point(g, c.at(0, 300.0));
    const basis::LocatedPoint bottom = basis::nearest_point(g, c.at(std::numbers::pi, 300.0));
    d.point_loads = {{top.x, Eigen::Vector3d(0.0, 0.0, -1.0)}, {bottom.x, Eigen::Vector3d(0.0, 0.0, 1.0)}};
    const auto rules = quadrature::make_rule_provider("tiles:4:8", 4);
    const fem::ProblemResult r = fem::solve_problem(g, *rules, pde::make_shell(d));
    // Half the closing of the diameter under the loads (free of any rigid motion).
    w.push_back(0.5 * (pde::shell_displacement(g.space(), r.u, bottom.element, bottom.uv)(2) -
                       pde::shell_displacement(g.space(), r.u, top.element, top.uv)(2)));
    std::cout << "tube net 16 x 8, refine " << refine << ": " << r.dofs << " dofs, |r - R| <= " << err << ": w = " << w.back()
              << " (" << 100 * (w.back() / 1.8248e-5 - 1) << " % from 1.8248e-5)\n";
  }
  EXPECT_LT(std::abs(w[1] / 1.8248e-5 - 1), 0.01);
  EXPECT_LT(std::abs(w[1] / 1.8248e-5 - 1), std::abs(w[0] / 1.8248e-5 - 1));
}

// The pinched cylinder on the whole tube with the other C1 surface backends: polyhedral splines on the quad net (G1
// at its extraordinary vertices; refining builds a new space on the refined net, which is then fitted) and half-box
// splines on the dual of the net split into triangles (three-valent: hexagons and the EVs' faces; triangular
// elements; fitted, then refined nested) — --fit-to's path, make_refined_geometry with BackendOptions::fit_to. Both
// name one boundary part (the two ends' receding curves), held in x and z. Measured: polyhedral (refine 1, 2, 3)
// −47.5 / −8.9 / −1.9 % at 1,632 / 6,336 / 24,960 dofs, half-box (refine 0, 1, 2) −29.7 / −8.4 / −2.1 % at 3,456 /
// 13,056 / 50,688 dofs: both converge, at about h² (the Catmull–Clark net: −2.6 / −0.16 % at 6,336 / 24,960 dofs).
TEST(ShellNets, PinchedCylinderOnPolyhedralAndHalfBoxTubes) {
  const Cylinder c{300.0, 600.0, -std::numbers::pi, std::numbers::pi};
  const mesh::PolyMesh quads = tube_net(c, 16, 8);
  std::vector<std::vector<Index>> triangles;
  for (Index f = 0; f < quads.num_faces(); ++f) {
    const auto q = quads.face(f);
    triangles.push_back({q[0], q[1], q[2]});
    triangles.push_back({q[0], q[2], q[3]});
  }
  const mesh::PolyMesh hexagons = mesh::dual_net(mesh::PolyMesh::build(quads.points(), triangles));
  for (const auto& [backend, net, rule, first] :
       {std::tuple{"polyhedral", &quads, "gauss:4", 1}, std::tuple{"halfbox", &hexagons, "tiles:4:20", 0}}) {
    basis::BackendOptions o;
    o.fit_to = c.shape();
    std::vector<double> gap;
    for (int refine = first; refine < first + 3; ++refine) {
      basis::BackendFacts facts;
      const basis::Geometry g = basis::make_refined_geometry(basis::backend(backend), net, o, refine, facts).geometry;
      ASSERT_EQ(g.space().boundary_part_names(), std::vector<std::string>{"boundary"});
      pde::ShellData d;
      d.material = {3e6, 0.3, 3.0};
      d.supports = {{0, {0}, nullptr}, {2, {0}, nullptr}};
      d.point_supports = {{basis::nearest_point(g, c.at(0, 0)).x, 1}};
      const basis::LocatedPoint top = basis::nearest_point(g, c.at(0, 300.0));
      const basis::LocatedPoint bottom = basis::nearest_point(g, c.at(std::numbers::pi, 300.0));
      d.point_loads = {{top.x, Eigen::Vector3d(0.0, 0.0, -1.0)}, {bottom.x, Eigen::Vector3d(0.0, 0.0, 1.0)}};
      const auto rules = quadrature::make_rule_provider(rule, 4);
      const fem::ProblemResult r = fem::solve_problem(g, *rules, pde::make_shell(d));
      const double w = 0.5 * (pde::shell_displacement(g.space(), r.u, bottom.element, bottom.uv)(2) -
                              pde::shell_displacement(g.space(), r.u, top.element, top.uv)(2));
      gap.push_back(std::abs(w / 1.8248e-5 - 1));
      std::cout << backend << " tube, refine " << refine << ": " << r.dofs << " dofs, fit " << facts.fit_distance
                << ": w = " << w << " (" << 100 * (w / 1.8248e-5 - 1) << " % from 1.8248e-5)\n";
    }
    EXPECT_GT(test::fitted_rate(gap), 1.6) << backend;
    EXPECT_LT(gap[2], 0.03) << backend;
  }
}

// The pinched hemisphere on a Catmull–Clark net of the whole band (latitudes 0 to 72°, EVs of valence 3 and 5, clamped
// boundary rule: the loads sit on the free equator), loads ±2 at the four points of the equator, held by six point
// supports on the hole's edge that take no reaction; half the opening of the diameter under the loads against the
// quarter NURBS patch with its symmetry planes (p = 4, 32 × 32): another space, another model, the same limit.
// Measured: 16 × 4 and 32 × 8 nets refined once, −0.49 % and −0.022 % from the patch (3,648 and 13,440 dofs).
TEST(ShellNets, PinchedHemisphereOnAWholeBandNetAgreesWithTheQuarterPatch) {
  const double top = 72 * kDeg, pi = std::numbers::pi;
  const basis::Geometry patch =
      refine::refine_uniform(basis::bspline::make_sphere_patch(4, 10.0, 0.0, 90 * kDeg, 0.0, top), 5).geometry;
  pde::ShellData q;
  q.material = {6.825e7, 0.3, 0.04};
  const auto slope = pde::Hold::kSlope;
  // The patch's sides by name: u0 (longitude 0) on the plane y = 0, u1 (longitude 90°) on x = 0.
  const std::vector<std::string> names = patch.space().boundary_part_names();
  const auto part = [&](const std::string& n) { return int(std::find(names.begin(), names.end(), n) - names.begin()); };
  const int u0 = part("u0"), u1 = part("u1");
  q.supports = {{1, {u0}, nullptr}, {0, {u1}, nullptr}, {0, {u0}, nullptr, slope}, {1, {u1}, nullptr, slope},
                {2, {u0, u1}, nullptr, slope}};
  const double rc = 10 * std::cos(top);
  q.point_supports = {{Eigen::Vector3d(rc * std::sqrt(0.5), rc * std::sqrt(0.5), 10 * std::sin(top)), 2}};
  q.point_loads = {{Eigen::Vector3d(10, 0, 0), Eigen::Vector3d(1, 0, 0)}, {Eigen::Vector3d(0, 10, 0), Eigen::Vector3d(0, -1, 0)}};
  const fem::ProblemResult rq = fem::solve_problem(patch, quadrature::Gauss(5), pde::make_shell(q));
  const basis::LocatedPoint pa = basis::locate_point(patch, Eigen::Vector3d(10, 0, 0), "A");
  const double quarter = pde::shell_displacement(patch.space(), rq.u, pa.element, pa.uv)(0);
  std::vector<double> gap;
  for (const auto& [ml, mp] : {std::pair{16, 4}, std::pair{32, 8}}) {
    const basis::ExactSurface band{basis::ExactSurface::Kind::kSphere, 10.0, {-pi, pi}, {0.0, top}};
    const basis::Geometry g = fitted(band_net(ml, mp), "clamped", band, 1);
    std::set<int> valences;
    for (Index e = 0; e < g.space().num_elements(); ++e) {
      if (g.space().kind(e).family == basis::Family::Irregular) valences.insert(g.space().kind(e).valence);
    }
    EXPECT_EQ(valences, (std::set<int>{3, 5}));
    pde::ShellData d;
    d.material = q.material;
    const auto on_top = [&](double l) {
      return basis::nearest_point(g, 10 * Eigen::Vector3d(std::cos(top) * std::cos(l), std::cos(top) * std::sin(l), std::sin(top))).x;
    };
    // z at three points, x at two opposite ones, y at one: the six rigid motions, statically determinate.
    d.point_supports = {{on_top(0), 2}, {on_top(2 * pi / 3), 2}, {on_top(4 * pi / 3), 2}, {on_top(pi / 2), 0},
                        {on_top(3 * pi / 2), 0}, {on_top(0), 1}};
    const basis::LocatedPoint a = basis::nearest_point(g, Eigen::Vector3d(10, 0, 0)), a2 = basis::nearest_point(g, Eigen::Vector3d(-10, 0, 0));
    d.point_loads = {{a.x, Eigen::Vector3d(2, 0, 0)}, {a2.x, Eigen::Vector3d(-2, 0, 0)},
                     {basis::nearest_point(g, Eigen::Vector3d(0, 10, 0)).x, Eigen::Vector3d(0, -2, 0)},
                     {basis::nearest_point(g, Eigen::Vector3d(0, -10, 0)).x, Eigen::Vector3d(0, 2, 0)}};
    const auto rules = quadrature::make_rule_provider("tiles:4:8", 4);
    const fem::ProblemResult r = fem::solve_problem(g, *rules, pde::make_shell(d));
    const double u = 0.5 * (pde::shell_displacement(g.space(), r.u, a.element, a.uv)(0) -
                            pde::shell_displacement(g.space(), r.u, a2.element, a2.uv)(0));
    gap.push_back(std::abs(u / quarter - 1));
    std::cout << "hemisphere band net " << ml << " x " << mp << ", refine 1: " << r.dofs << " dofs: u = " << u << " ("
              << 100 * (u / quarter - 1) << " % from the quarter patch's " << quarter << ", " << 100 * (u / 0.0924 - 1)
              << " % from 0.0924)\n";
  }
  EXPECT_LT(gap[1], 1e-3);
  EXPECT_LT(gap[1], gap[0]);
}
