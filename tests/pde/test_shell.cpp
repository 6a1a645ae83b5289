// The linear Kirchhoff–Love shell (pde/shell): the assembled stiffness vanishes on the six rigid motions and is
// positive on a stretch, the plate limit against Navier's series, the membrane limit against plane-stress elasticity
// (an independent implementation), Scordelis–Lo's roof against its reference value, and the refusals.
#include <gtest/gtest.h>

#include <Eigen/Dense>

#include <cmath>
#include <iostream>
#include <numbers>

#include "basis/bspline/patches.hpp"
#include "basis/locate.hpp"
#include "basis/registry.hpp"
#include "mesh/obj_reader.hpp"
#include "pde/elasticity/elasticity.hpp"
#include "pde/elasticity/kirsch.hpp"
#include "core/error.hpp"
#include "fem/assembler.hpp"
#include "fem/problem.hpp"
#include "pde/shell/output.hpp"
#include "pde/shell/shell.hpp"
#include "quadrature/rule_provider.hpp"
#include "refine/uniform.hpp"
#include "support/paths.hpp"
#include "support/rates.hpp"

using namespace iga;

namespace {

constexpr int kV0 = 0, kU1 = 1, kV1 = 2, kU0 = 3;  // TensorSpace's boundary parts
constexpr double kDeg = std::numbers::pi / 180;

// Scordelis–Lo: R = 25, L = 50, ±40°, t = 0.25, E = 4.32e8, ν = 0, self-weight 90 per unit area, rigid diaphragms at
// the curved ends (u_x = u_z = 0), held axially at one point of the first diaphragm.
pde::ShellData roof_data() {
  pde::ShellData d;
  d.material = {4.32e8, 0.0, 0.25};
  d.area_load = {nullptr, nullptr, fem::constant_function(-90.0)};
  d.supports = {{0, {kV0, kV1}, nullptr}, {2, {kV0, kV1}, nullptr}};
  d.point_supports = {{Eigen::Vector3d(0.0, 0.0, 25.0), 1}};
  return d;
}

Eigen::SparseMatrix<double> stiffness(const basis::Geometry& g, const quadrature::RuleProvider& rules,
                                      const pde::ShellMaterial& m);

double roof_midpoint_deflection(int degree, int refine) {
  const basis::Geometry g =
      refine::refine_uniform(basis::bspline::make_cylinder_patch(degree, 25.0, 50.0, -40 * kDeg, 40 * kDeg), refine)
          .geometry;
  const quadrature::Gauss rules(degree + 1);
  const fem::ProblemResult r = fem::solve_problem(g, rules, pde::make_shell(roof_data()));
  // The strain energy the problem reports is ½ uᵀ K u, K the form's matrix (another path through the same strains).
  const double energy = 0.5 * r.u.dot(stiffness(g, rules, roof_data().material) * r.u);
  EXPECT_EQ(r.quantities.at(0).first, "strain energy");
  EXPECT_NEAR(r.quantities.at(0).second, energy, 1e-9 * energy);
  EXPECT_NEAR(r.quantities.at(1).second + r.quantities.at(2).second, energy, 1e-9 * energy);
  EXPECT_GT(r.quantities.at(1).second, 0.0);
  EXPECT_GT(r.quantities.at(2).second, 0.0);
  const basis::LocatedPoint p =
      basis::locate_point(g, Eigen::Vector3d(25 * std::sin(40 * kDeg), 25.0, 25 * std::cos(40 * kDeg)), "midpoint");
  return pde::shell_displacement(g.space(), r.u, p.element, p.uv)(2);
}

// A planar geometry as a surface in 3D (z = 0).
basis::Geometry lifted(const basis::Geometry& g) {
  Eigen::MatrixXd p = Eigen::MatrixXd::Zero(g.control_points().rows(), 3);
  p.leftCols(2) = g.control_points();
  return basis::Geometry(g.space_ptr(), p);
}

// The stiffness of the shell form alone on g: a matrix of 3 × the space's dofs.
Eigen::SparseMatrix<double> stiffness(const basis::Geometry& g, const quadrature::RuleProvider& rules,
                                      const pde::ShellMaterial& m) {
  const fem::Assembler a(g, rules, 3);
  const pde::KirchhoffLoveForm form(m);
  const fem::BilinearForm* forms[] = {&form};
  Eigen::SparseMatrix<double> k;
  Eigen::VectorXd b;
  a.assemble(forms, {}, k, b);
  return k;
}

// ‖K r‖ / (‖K‖ ‖r‖) for the six rigid motions c + ω × x (coefficients from the control points) and for the stretch
// u = (x, 0, 0), which must not vanish.
void expect_rigid_kernel(const basis::Geometry& g, const quadrature::RuleProvider& rules, const std::string& name) {
  const Eigen::SparseMatrix<double> k = stiffness(g, rules, {2.1e5, 0.3, 0.05});
  const Eigen::MatrixXd& p = g.control_points();
  const Index n = p.rows();
  const double norm = Eigen::MatrixXd(k).norm();
  for (int mode = 0; mode < 7; ++mode) {
    Eigen::VectorXd r(3 * n);
    for (Index i = 0; i < n; ++i) {
      const Eigen::Vector3d x = p.row(i).transpose();
      Eigen::Vector3d u = Eigen::Vector3d::Zero();
      if (mode < 3) u(mode) = 1.0;
      if (mode >= 3 && mode < 6) u = Eigen::Vector3d::Unit(mode - 3).cross(x);
      if (mode == 6) u = Eigen::Vector3d(x(0), 0.0, 0.0);
      r.segment<3>(3 * i) = u;
    }
    const double ratio = (k * r).norm() / (norm * r.norm());
    if (mode < 6) {
      EXPECT_LT(ratio, 1e-12) << name << ", rigid mode " << mode;
    } else {
      EXPECT_GT(ratio, 1e-3) << name << ", the stretch";
    }
  }
}

// Navier's series for the centre deflection of a simply supported square plate of side a under a uniform load q:
// w = 16 q a⁴ / (π⁶ D) Σ_{m, n odd} (−1)^((m + n)/2 − 1) / (m n (m² + n²)²) (Timoshenko and Woinowsky-Krieger, §30).
double navier_centre(double q, double a, double d) {
  double sum = 0.0;
  for (int m = 1; m < 2000; m += 2) {
    for (int n = 1; n < 2000; n += 2) {
      const double sign = ((m + n) / 2 - 1) % 2 == 0 ? 1.0 : -1.0;
      sum += sign / (double(m) * n * std::pow(double(m) * m + double(n) * n, 2));
    }
  }
  return 16 * q * std::pow(a, 4) / (std::pow(std::numbers::pi, 6) * d) * sum;
}

// The centre moment M_xx = −D (w_,xx + ν w_,yy) of the same series: 16 q a² / π⁴ Σ (−1)^((m + n)/2 − 1)
// (m² + ν n²) / (m n (m² + n²)²) (0.0479 q a² for ν = 0.3: Timoshenko and Woinowsky-Krieger, Table 8).
double navier_centre_moment(double q, double a, double nu) {
  double sum = 0.0;
  for (int m = 1; m < 4000; m += 2) {
    for (int n = 1; n < 4000; n += 2) {
      const double sign = ((m + n) / 2 - 1) % 2 == 0 ? 1.0 : -1.0;
      sum += sign * (double(m) * m + nu * n * n) / (double(m) * n * std::pow(double(m) * m + double(n) * n, 2));
    }
  }
  return 16 * q * a * a / std::pow(std::numbers::pi, 4) * sum;
}

}  // namespace

TEST(Shell, RigidMotionsCostNoEnergy) {
  const basis::Geometry roof =
      refine::refine_uniform(basis::bspline::make_cylinder_patch(3, 25.0, 50.0, -40 * kDeg, 40 * kDeg), 2).geometry;
  expect_rigid_kernel(roof, quadrature::Gauss(4), "cylinder patch, p = 3");
  basis::BackendOptions options;
  basis::BackendFacts facts;
  const mesh::PolyMesh net = mesh::read_obj(std::string(IGA_SOURCE_DIR) + "/data/meshes/torus_evs.obj");
  const basis::Geometry torus = basis::make_geometry(basis::backend("cc"), &net, options, facts);
  const auto rules = quadrature::make_rule_provider("tiles:4:8", 4);
  expect_rigid_kernel(torus, *rules, "Catmull-Clark torus with EVs of valence 3 and 5");
}

// The strains are the derivatives of the nonlinear ones (Kiendl et al. 2009, eqs. 8 and 13: ε_αβ = ½ (a_αβ − A_αβ),
// κ_αβ = b_αβ − B_αβ, b_αβ = x_,αβ · a_3) along x + s u at s = 0, by central differences in s, on a doubly curved
// surface with a skew parametrisation and a displacement whose derivatives are all nonzero.
TEST(Shell, StrainsLineariseTheNonlinearStrains) {
  using V = Eigen::Vector3d;
  // x(u, v) = (u + 0.2 v, v, 0.3 u² + 0.2 u v − 0.25 v² + 0.1 u³) at (u, v) = (0.4, −0.3); u(u, v) per component
  // c0 + c1 u + c2 v + c3 u² + c4 u v + c5 v².
  const double pu = 0.4, pv = -0.3;
  const V xu(1.0, 0.0, 0.6 * pu + 0.2 * pv + 0.3 * pu * pu), xv(0.2, 1.0, 0.2 * pu - 0.5 * pv);
  const V xuu(0.0, 0.0, 0.6 + 0.6 * pu), xuv(0.0, 0.0, 0.2), xvv(0.0, 0.0, -0.5);
  const Eigen::Matrix<double, 3, 6> c{{0.1, -0.7, 0.3, 0.9, -0.4, 0.2}, {0.5, 0.2, -0.6, -0.3, 0.8, 0.5},
                                      {-0.2, 0.4, 0.7, 0.6, 0.3, -0.9}};
  const V du = c.col(1) + 2 * pu * c.col(3) + pv * c.col(4), dv = c.col(2) + pu * c.col(4) + 2 * pv * c.col(5);
  const V duu = 2 * c.col(3), duv = c.col(4), dvv = 2 * c.col(5);
  // (a_11, a_22, 2 a_12) and (b_11, b_22, 2 b_12) of x + s u.
  auto forms = [&](double s, Eigen::Vector3d& a, Eigen::Vector3d& b) {
    const V a1 = xu + s * du, a2 = xv + s * dv, a3 = a1.cross(a2).normalized();
    a = {a1.dot(a1), a2.dot(a2), 2 * a1.dot(a2)};
    b = {(xuu + s * duu).dot(a3), (xvv + s * dvv).dot(a3), 2 * (xuv + s * duv).dot(a3)};
  };
  const double h = 1e-5;
  Eigen::Vector3d ap, bp, am, bm;
  forms(h, ap, bp);
  forms(-h, am, bm);
  const Eigen::Vector3d membrane = (ap - am) / (4 * h), bending = (bp - bm) / (2 * h);
  const pde::ShellStrains s = pde::shell_strains(xu, xv, xuu, xuv, xvv, du, dv, duu, duv, dvv, {1.0, 0.3, 0.1});
  EXPECT_LT((s.membrane - membrane).norm(), 1e-9 * membrane.norm()) << s.membrane.transpose() << " | " << membrane.transpose();
  EXPECT_LT((s.bending - bending).norm(), 1e-9 * bending.norm()) << s.bending.transpose() << " | " << bending.transpose();
  EXPECT_GT(membrane.cwiseAbs().minCoeff(), 1e-2);  // every component is tested
  EXPECT_GT(bending.cwiseAbs().minCoeff(), 1e-2);
}

// On a plane the bending part is Kirchhoff's plate: the simply supported square under a uniform load against
// Navier's series; the error falls at a fitted rate over three levels.
TEST(Shell, PlateLimitIsNavier) {
  const double q = -1.0, young = 1e4, nu = 0.3, t = 0.1, dp = young * t * t * t / (12 * (1 - nu * nu));
  const double exact = navier_centre(q, 1.0, dp);
  pde::ShellData d;
  d.material = {young, nu, t};
  d.area_load = {nullptr, nullptr, fem::constant_function(q)};
  d.supports = {{0, {kV0, kU1, kV1, kU0}, nullptr}, {1, {kV0, kU1, kV1, kU0}, nullptr}, {2, {kV0, kU1, kV1, kU0}, nullptr}};
  const double moment = navier_centre_moment(q, 1.0, nu);
  std::vector<double> errors, moment_errors;
  for (int refine = 2; refine <= 4; ++refine) {
    const basis::Geometry g = lifted(refine::refine_uniform(basis::bspline::make_rectangle(3), refine).geometry);
    const fem::ProblemResult r = fem::solve_problem(g, quadrature::Gauss(4), pde::make_shell(d));
    const basis::LocatedPoint c = basis::locate_point(g, Eigen::Vector3d(0.5, 0.5, 0.0), "centre");
    const double w = pde::shell_displacement(g.space(), r.u, c.element, c.uv)(2);
    errors.push_back(std::abs(w / exact - 1));
    const pde::ShellResultants m = pde::shell_resultants_at(g, r.u, c.element, c.uv, d.material);
    moment_errors.push_back(std::abs(m.moments(0, 0) / moment - 1));
    std::cout << "plate, p = 3, refine " << refine << ": w = " << w << " (Navier " << exact << "), relative error "
              << errors.back() << "; M_xx = " << m.moments(0, 0) << " (Navier " << moment << "), relative error "
              << moment_errors.back() << "\n";
    EXPECT_NEAR(m.moments(1, 0), m.moments(0, 0), 1e-9 * std::abs(moment));  // M_yy = M_xx by symmetry
    EXPECT_NEAR(m.forces.col(0).norm(), 0.0, 1e-12);                           // no membrane force
  }
  EXPECT_NEAR(moment / q, 0.0479, 5e-5);
  EXPECT_LT(moment_errors.back(), 2e-3);  // measured 1.3e-3: second derivatives converge at h^(p-1)
  EXPECT_GT(test::fitted_rate(moment_errors), 1.5);
  EXPECT_LT(errors.back(), 1e-5);
  EXPECT_GT(test::fitted_rate(errors), 3.5);
  // A planar geometry is the plate in z = 0: the same solution as the lifted one.
  const basis::Geometry plane = refine::refine_uniform(basis::bspline::make_rectangle(3), 2).geometry;
  const fem::ProblemResult a = fem::solve_problem(plane, quadrature::Gauss(4), pde::make_shell(d));
  const fem::ProblemResult b = fem::solve_problem(lifted(plane), quadrature::Gauss(4), pde::make_shell(d));
  EXPECT_LT((a.u - b.u).cwiseAbs().maxCoeff(), 1e-12 * b.u.cwiseAbs().maxCoeff());
}

// In its plane the membrane part is plane-stress elasticity times t: the quarter annulus under a body force and a
// traction on the outer arc gives pde/elasticity's displacement (another implementation) to round-off.
TEST(Shell, MembraneLimitIsPlaneStress) {
  const double young = 1e5, nu = 0.3, t = 0.2;
  const basis::Geometry plane = refine::refine_uniform(basis::bspline::make_quarter_annulus(3), 2).geometry;
  const auto f = std::array<std::shared_ptr<const fem::Function>, 2>{fem::constant_function(1.0), fem::constant_function(2.0)};
  const auto q = std::array<std::shared_ptr<const fem::BoundaryFunction>, 2>{
      fem::normal_flux(fem::make_function([](const Eigen::Vector3d& x) { return 3 * x(0) + x(1); })), nullptr};
  pde::ElasticityData e;
  e.young = young * t;
  e.poisson = nu;
  e.model = pde::PlaneModel::kStress;
  e.body_force = {fem::constant_function(t * 1.0), fem::constant_function(t * 2.0)};
  e.displacement = {{1, {kV0}, nullptr}, {0, {kV1}, nullptr}};
  e.traction = {{{kU1}, {q[0], q[1]}}};
  const quadrature::Gauss rules(4);
  const fem::ProblemResult pe = fem::solve_problem(plane, rules, pde::make_elasticity(e));
  pde::ShellData s;
  s.material = {young, nu, t};
  s.area_load = {fem::constant_function(t * 1.0), fem::constant_function(t * 2.0), nullptr};
  s.supports = {{1, {kV0}, nullptr}, {0, {kV1}, nullptr}, {2, {kV0, kU1, kV1, kU0}, nullptr}};
  s.line_loads = {{{kU1}, {q[0], q[1], nullptr}}};
  const fem::ProblemResult ps = fem::solve_problem(lifted(plane), rules, pde::make_shell(s));
  const Index n = plane.space().num_dofs();
  double difference = 0.0, largest = 0.0;
  for (Index i = 0; i < n; ++i) {
    for (int c = 0; c < 2; ++c) {
      difference = std::max(difference, std::abs(ps.u(3 * i + c) - pe.u(2 * i + c)));
      largest = std::max(largest, std::abs(pe.u(2 * i + c)));
    }
    EXPECT_LT(std::abs(ps.u(3 * i + 2)), 1e-12 * largest);
  }
  EXPECT_GT(largest, 1e-6);
  EXPECT_LT(difference, 1e-9 * largest);
}

// Scordelis–Lo's roof: the vertical deflection at the middle of a free edge converges to 0.3006 (the Kirchhoff–Love
// value; Kiendl et al. 2009, Table 1, and the shell obstacle course of Belytschko et al. 1985, which quotes 0.3024 for
// shear-deformable shells); within 0.5 % from 8 × 8 cubic elements on, its changes shrinking level by level.
TEST(Shell, ScordelisLoRoof) {
  for (int degree : {3, 4}) {
    std::vector<double> w;
    for (int refine = 2; refine <= 5; ++refine) {
      w.push_back(-roof_midpoint_deflection(degree, refine));
      std::cout << "Scordelis-Lo, p = " << degree << ", " << (1 << refine) << " x " << (1 << refine)
                << " elements: w = " << w.back() << " (" << 100 * (w.back() / 0.3006 - 1) << " % from 0.3006)\n";
    }
    for (std::size_t k = 1; k < w.size(); ++k) EXPECT_LT(std::abs(w[k] / 0.3006 - 1), 0.005) << degree << ", " << k;
    std::vector<double> changes;
    for (std::size_t k = 1; k < w.size(); ++k) changes.push_back(std::abs(w[k] - w[k - 1]));
    EXPECT_GT(test::fitted_rate(changes), 2.0) << degree;
  }
}

TEST(Shell, Refusals) {
  const basis::Geometry roof = basis::bspline::make_cylinder_patch(3, 25.0, 50.0, -40 * kDeg, 40 * kDeg);
  const quadrature::Gauss rules(4);
  auto message = [&](const basis::Geometry& g, pde::ShellData d) {
    try {
      fem::solve_problem(g, rules, pde::make_shell(std::move(d)));
    } catch (const Error& e) {
      return std::string(e.what());
    }
    return std::string("(no error)");
  };
  pde::ShellData d = roof_data();
  d.material.thickness = 0.0;
  EXPECT_EQ(message(roof, d), "shell: the thickness t must be a finite number > 0, got 0");
  d = roof_data();
  d.point_supports.clear();
  EXPECT_EQ(message(roof, d),
            "shell: the supports leave a rigid-body mode free (the translation along (0, 1, 0)): the stiffness matrix is "
            "singular; support more components or parts");
  d = roof_data();
  d.supports = {{2, {kV0, kV1}, nullptr}};
  d.point_supports.clear();
  EXPECT_NE(message(roof, d).find("shell: the supports leave a rigid-body mode free"), std::string::npos);
  d = roof_data();
  d.point_loads = {{Eigen::Vector3d(0.0, 25.0, 20.0), Eigen::Vector3d(0.0, 0.0, -1.0)}};
  EXPECT_EQ(message(roof, d).substr(0, 61), "shell: point load 1: (0, 25, 20) is not on the surface: the n");
  d = roof_data();
  d.supports.push_back({0, {kU0}, fem::constant_function(0.1)});
  EXPECT_EQ(message(roof, d), "shell: support u_x has a value and another support: give it one condition over all its parts");
  EXPECT_EQ(message(lifted(basis::bspline::make_plate_with_hole(3)), roof_data()).substr(0, 82),
            "shell: the space is only C0 across the side shared by elements 0 and 1 (midpoint (");
}


// basis::locate_point finds images of reference points again, on a NURBS patch and on a Catmull–Clark net with
// extraordinary vertices (element corners at the vertices included).
TEST(Shell, LocatesPointsOnTheSurface) {
  const basis::Geometry roof =
      refine::refine_uniform(basis::bspline::make_cylinder_patch(3, 25.0, 50.0, -40 * kDeg, 40 * kDeg), 2).geometry;
  basis::BackendOptions options;
  basis::BackendFacts facts;
  const mesh::PolyMesh net = mesh::read_obj(std::string(IGA_SOURCE_DIR) + "/data/meshes/torus_evs.obj");
  const basis::Geometry torus = basis::make_geometry(basis::backend("cc"), &net, options, facts);
  for (const basis::Geometry* g : {&roof, &torus}) {
    const Index n = g->space().num_elements();
    for (Index e = 0; e < n; e += std::max<Index>(1, n / 7)) {
      for (const Eigen::Vector2d& uv : {Eigen::Vector2d(0.0, 0.0), Eigen::Vector2d(0.3, 0.8), Eigen::Vector2d(1.0, 0.45)}) {
        Eigen::Matrix2Xd at(2, 1);
        at.col(0) = uv;
        basis::GeometryValues gv;
        g->evaluate(e, at, gv);
        const Eigen::Vector3d x = gv.x.col(0);
        const basis::LocatedPoint p = basis::locate_point(*g, x, "point");
        EXPECT_LT(p.distance, 1e-9 * x.norm()) << g->space().name() << " element " << e;
        EXPECT_LT((p.x - x).norm(), 1e-9 * x.norm());
      }
    }
  }
}

// The cylinder and sphere patches are exact: every point at the radius from the axis or the centre.
TEST(Shell, CylinderAndSpherePatchesAreExact) {
  for (int degree : {2, 3, 5}) {
    const basis::Geometry cylinder =
        refine::refine_uniform(basis::bspline::make_cylinder_patch(degree, 300.0, 600.0, 0.0, 90 * kDeg), 1).geometry;
    const basis::Geometry sphere =
        refine::refine_uniform(basis::bspline::make_sphere_patch(degree, 10.0, 0.0, 90 * kDeg, 0.0, 72 * kDeg), 1).geometry;
    Eigen::Matrix2Xd at(2, 3);
    at << 0.0, 0.37, 1.0, 0.0, 0.81, 0.5;
    for (Index e = 0; e < 4; ++e) {
      basis::GeometryValues c, s;
      cylinder.evaluate(e, at, c);
      sphere.evaluate(e, at, s);
      for (Index k = 0; k < 3; ++k) {
        EXPECT_NEAR(std::hypot(c.x(0, k), c.x(2, k)), 300.0, 1e-10);
        EXPECT_NEAR(s.x.col(k).norm(), 10.0, 1e-12);
        EXPECT_LE(s.x(2, k), 10 * std::sin(72 * kDeg) + 1e-12);
      }
    }
  }
}

// The pinched cylinder (R = 300, L = 600, t = 3, E = 3e6, ν = 0.3, rigid diaphragms, two opposite loads P = 1 at
// mid-length): one octant, x >= 0, z >= 0, y in [0, 300], with the diaphragm at y = 0 and symmetry planes x = 0, z = 0
// and y = 300, P/4 at the corner (0, 300, 300). The radial displacement under the load converges to 1.8248e-5
// (Belytschko et al. 1985; the thin-shell value).
TEST(Shell, PinchedCylinder) {
  std::vector<double> w;
  for (int refine = 3; refine <= 5; ++refine) {
    const basis::Geometry g =
        refine::refine_uniform(basis::bspline::make_cylinder_patch(4, 300.0, 300.0, 0.0, 90 * kDeg), refine).geometry;
    pde::ShellData d;
    d.material = {3e6, 0.3, 3.0};
    const auto slope = pde::Hold::kSlope;
    d.supports = {{0, {kV0, kU0}, nullptr}, {2, {kV0, kU1}, nullptr}, {1, {kV1}, nullptr},
                  {0, {kU1, kV1}, nullptr, slope}, {1, {kU0, kU1}, nullptr, slope}, {2, {kU0, kV1}, nullptr, slope}};
    d.point_loads = {{Eigen::Vector3d(0.0, 300.0, 300.0), Eigen::Vector3d(0.0, 0.0, -0.25)}};
    const fem::ProblemResult r = fem::solve_problem(g, quadrature::Gauss(5), pde::make_shell(d));
    const basis::LocatedPoint p = basis::locate_point(g, Eigen::Vector3d(0.0, 300.0, 300.0), "load");
    w.push_back(-pde::shell_displacement(g.space(), r.u, p.element, p.uv)(2));
    std::cout << "pinched cylinder, p = 4, " << (1 << refine) << " x " << (1 << refine) << ", " << r.dofs
              << " dofs: w = " << w.back() << " (" << 100 * (w.back() / 1.8248e-5 - 1) << " % from 1.8248e-5)\n";
  }
  EXPECT_LT(std::abs(w[1] / 1.8248e-5 - 1), 0.01);
  EXPECT_LT(std::abs(w[2] / 1.8248e-5 - 1), 0.01);
  EXPECT_LT(std::abs(w[2] - w[1]), 0.5 * std::abs(w[1] - w[0]));
}

// The pinched hemisphere with an 18° hole (R = 10, t = 0.04, E = 6.825e7, ν = 0.3): one quarter, symmetry planes
// y = 0 and x = 0, held vertically at one point of the hole's edge, loads 1 outward along x at (10, 0, 0) and inward
// along y at (0, 10, 0) (the quarter's share: F = 2 on the whole hemisphere, MacNeal and Harder 1985). The displacement
// under the load converges to 0.09352 here: 1.2 % above 0.0924 (Belytschko et al. 1985, the value the issue names)
// and 0.5 % below MacNeal and Harder's 0.094 — within 1.5 % and 1 % of them, and changing by 2e-4 between the last two levels.
TEST(Shell, PinchedHemisphere) {
  std::vector<double> w;
  for (int refine = 3; refine <= 5; ++refine) {
    const basis::Geometry g =
        refine::refine_uniform(basis::bspline::make_sphere_patch(4, 10.0, 0.0, 90 * kDeg, 0.0, 72 * kDeg), refine).geometry;
    pde::ShellData d;
    d.material = {6.825e7, 0.3, 0.04};
    const auto slope = pde::Hold::kSlope;
    d.supports = {{1, {kU0}, nullptr}, {0, {kU1}, nullptr}, {0, {kU0}, nullptr, slope}, {1, {kU1}, nullptr, slope},
                  {2, {kU0, kU1}, nullptr, slope}};
    const double rc = 10 * std::cos(72 * kDeg);
    d.point_supports = {{Eigen::Vector3d(rc * std::sqrt(0.5), rc * std::sqrt(0.5), 10 * std::sin(72 * kDeg)), 2}};
    d.point_loads = {{Eigen::Vector3d(10.0, 0.0, 0.0), Eigen::Vector3d(1.0, 0.0, 0.0)},
                     {Eigen::Vector3d(0.0, 10.0, 0.0), Eigen::Vector3d(0.0, -1.0, 0.0)}};
    const fem::ProblemResult r = fem::solve_problem(g, quadrature::Gauss(5), pde::make_shell(d));
    const basis::LocatedPoint p = basis::locate_point(g, Eigen::Vector3d(10.0, 0.0, 0.0), "load");
    w.push_back(pde::shell_displacement(g.space(), r.u, p.element, p.uv)(0));
    std::cout << "pinched hemisphere, p = 4, " << (1 << refine) << " x " << (1 << refine) << ", " << r.dofs
              << " dofs: u = " << w.back() << " (" << 100 * (w.back() / 0.0924 - 1) << " % from 0.0924, "
              << 100 * (w.back() / 0.094 - 1) << " % from 0.094)\n";
  }
  EXPECT_LT(std::abs(w[2] / 0.0924 - 1), 0.015);
  EXPECT_LT(std::abs(w[2] / 0.094 - 1), 0.01);
  EXPECT_LT(std::abs(w[2] - w[1]), 5e-4 * w[2]);  // measured 2.0e-4
}

// The hole of the pinched hemisphere: closing it (18°, 9°, 4.5°, 2.25°; quartic, 32 × 32) the displacement under the
// load falls to 0.0924, the value for the hemisphere without a hole (Morley and Morris 1978, quoted by the obstacle
// course for the hemisphere with the 18° hole); the changes fall as the hole's angle squared, so one Richardson step
// gives the closed hemisphere. Measured: 0.093519, 0.092680, 0.092479, 0.092428 (64 × 64: within 3e-6 of these).
TEST(Shell, PinchedHemisphereClosesToTheValueWithoutAHole) {
  std::vector<double> u;
  for (double hole : {18.0, 9.0, 4.5, 2.25}) {
    const double top = (90 - hole) * kDeg;
    const basis::Geometry g =
        refine::refine_uniform(basis::bspline::make_sphere_patch(4, 10.0, 0.0, 90 * kDeg, 0.0, top), 5).geometry;
    pde::ShellData d;
    d.material = {6.825e7, 0.3, 0.04};
    const auto slope = pde::Hold::kSlope;
    d.supports = {{1, {kU0}, nullptr}, {0, {kU1}, nullptr}, {0, {kU0}, nullptr, slope}, {1, {kU1}, nullptr, slope},
                  {2, {kU0, kU1}, nullptr, slope}};
    const double rc = 10 * std::cos(top);
    d.point_supports = {{Eigen::Vector3d(rc * std::sqrt(0.5), rc * std::sqrt(0.5), 10 * std::sin(top)), 2}};
    d.point_loads = {{Eigen::Vector3d(10.0, 0.0, 0.0), Eigen::Vector3d(1.0, 0.0, 0.0)},
                     {Eigen::Vector3d(0.0, 10.0, 0.0), Eigen::Vector3d(0.0, -1.0, 0.0)}};
    const fem::ProblemResult r = fem::solve_problem(g, quadrature::Gauss(5), pde::make_shell(d));
    const basis::LocatedPoint p = basis::locate_point(g, Eigen::Vector3d(10.0, 0.0, 0.0), "load");
    u.push_back(pde::shell_displacement(g.space(), r.u, p.element, p.uv)(0));
    std::cout << "pinched hemisphere, hole " << hole << "°: u = " << u.back() << " (" << 100 * (u.back() / 0.0924 - 1)
              << " % from 0.0924)\n";
  }
  std::vector<double> changes;
  for (std::size_t k = 1; k < u.size(); ++k) changes.push_back(u[k - 1] - u[k]);
  for (double c : changes) EXPECT_GT(c, 0.0);
  const double rate = test::fitted_rate(changes);  // per halving of the angle
  EXPECT_NEAR(rate, 2.0, 0.2);
  const double closed = u.back() - changes.back() / (std::pow(2.0, rate) - 1);
  std::cout << "changes fall at rate " << rate << "; closed hemisphere " << closed << " (" << 100 * (closed / 0.0924 - 1) << " %)\n";
  EXPECT_LT(std::abs(closed / 0.0924 - 1), 1e-3);
}
