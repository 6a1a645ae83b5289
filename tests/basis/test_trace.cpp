// basis::TraceSpace and trace_geometry: the boundary of a planar Space as a CurveSpace. Checked against
// independent evaluations: the univariate Cox–de Boor B-splines of a patch side (bspline), the uniform cubic
// B-spline of the boundary polygon with interpolated corners (Catmull–Clark, OpenSubdiv's boundary rule), the
// surface functions evaluated on the sides (every backend, through the restriction map R, which carries the
// dependent traces of polyhedral and half-box splines), and closed forms (perimeter, area, corner angles).
#include "support/paths.hpp"
#include <gtest/gtest.h>

#include <Eigen/Core>
#include <cmath>
#include <map>
#include <numbers>
#include <random>
#include <string>

#include "basis/bspline/knot_vector.hpp"
#include "basis/bspline/tensor_space.hpp"
#include "basis/catmull_clark/space.hpp"
#include "basis/curve/trace_space.hpp"
#include "basis/registry.hpp"
#include "core/error.hpp"
#include "mesh/obj_reader.hpp"
#include "mesh/three_valent.hpp"

namespace {

using namespace iga;
using basis::BoundaryEdge;
using basis::CurveBasisValues;
using basis::CurveGeometry;
using basis::Geometry;
using basis::TraceSpace;

mesh::PolyMesh data_mesh(const std::string& file) {
  return mesh::read_obj(std::string(IGA_SOURCE_DIR) + "/data/meshes/" + file);
}

Geometry registry_geometry(const std::string& backend, const mesh::PolyMesh& net) {
  basis::BackendFacts facts;
  return basis::make_geometry(basis::backend(backend), &net, basis::BackendOptions{}, facts);
}

// Σ_i u_i φ_i at side_point(t) of a boundary edge, from the surface space directly.
double surface_value(const basis::Space& space, const Eigen::VectorXd& u, const BoundaryEdge& b, double t) {
  basis::BasisValues v;
  space.evaluate(b.element, Eigen::Matrix2Xd(basis::side_point(space.kind(b.element).shape, b.side, t)), 0, v);
  const auto dofs = space.dofs(b.element);
  double s = 0.0;
  for (std::size_t a = 0; a < dofs.size(); ++a) s += u(dofs[a]) * v.value(static_cast<Index>(a), 0);
  return s;
}

// Σ_k c_k ψ_k at t of trace element e (with t-derivative).
Eigen::Vector2d trace_value(const TraceSpace& trace, const Eigen::VectorXd& c, Index e, double t) {
  CurveBasisValues v;
  trace.evaluate(e, Eigen::VectorXd::Constant(1, t), 1, v);
  const auto dofs = trace.dofs(e);
  Eigen::Vector2d s = Eigen::Vector2d::Zero();
  for (std::size_t a = 0; a < dofs.size(); ++a) {
    s(0) += c(dofs[a]) * v.value(static_cast<Index>(a), 0);
    s(1) += c(dofs[a]) * v.dt(static_cast<Index>(a), 0);
  }
  return s;
}

// The restriction map carries every surface function to its trace: for random u, Σ (R u)_k ψ_k = u|Γ at random
// side parameters, to 1e-13 of max |u|.
void check_restriction(const Geometry& g, const std::string& what) {
  const TraceSpace trace(g.space_ptr(), g.space().boundary_edges());
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> uni(-1.0, 1.0), at(0.0, 1.0);
  Eigen::VectorXd u(g.space().num_dofs());
  for (Index i = 0; i < u.size(); ++i) u(i) = uni(rng);
  const Eigen::VectorXd c = trace.restriction() * u;
  double worst = 0.0;
  for (Index e = 0; e < trace.num_elements(); ++e) {
    for (int k = 0; k < 3; ++k) {
      const double t = at(rng);
      worst = std::max(worst, std::abs(trace_value(trace, c, e, t)(0) - surface_value(g.space(), u, trace.edge(e), t)));
    }
  }
  EXPECT_LT(worst, 1e-13) << what;
}

// The unit square's boundary: four corners of angle π/2 (to angle_tol), perimeter 4 and area 1 (to tol).
void expect_unit_square(const CurveGeometry& c, double angle_tol, double tol) {
  int corners = 0;
  double perimeter = 0.0;
  for (Index e = 0; e < c.num_elements(); ++e) {
    perimeter += c.length(e);
    if (c.corner_at_end(e)) {
      ++corners;
      EXPECT_NEAR(c.interior_angle(e), std::numbers::pi / 2, angle_tol);
    }
  }
  EXPECT_EQ(corners, 4);
  EXPECT_NEAR(perimeter, 4.0, tol);
  EXPECT_NEAR(c.signed_area(), 1.0, tol);
}

// Uniform knot vector helper: clamped, degree p, interior knots given.
basis::bspline::KnotVector knots(int p, std::vector<double> interior) {
  std::vector<double> k(static_cast<std::size_t>(p + 1), 0.0);
  k.insert(k.end(), interior.begin(), interior.end());
  k.insert(k.end(), static_cast<std::size_t>(p + 1), 1.0);
  return basis::bspline::KnotVector(p, k);
}

}  // namespace

TEST(Trace, BsplineSideIsTheUnivariateBasisOfItsKnots) {
  // Non-uniform cubic × quadratic patch with the Greville map x = u, y = v (linear precision): on the side v = 0
  // every trace function is a univariate B-spline N_i(x) of the u knots (Cox–de Boor, knot_vector.hpp), with
  // dN/dt = N'(x) dx/dt.
  const auto ku = knots(3, {0.2, 0.45, 0.45, 0.7}), kv = knots(2, {0.3, 0.6});
  auto space = std::make_shared<const basis::bspline::TensorSpace>(ku, kv);
  const Index nu = ku.num_basis(), nv = kv.num_basis();
  Eigen::MatrixXd cp(nu * nv, 2);
  auto greville = [](const basis::bspline::KnotVector& k, Index i) {
    double s = 0.0;
    for (int a = 1; a <= k.degree(); ++a) s += k[i + a];
    return s / k.degree();
  };
  for (Index j = 0; j < nv; ++j) {
    for (Index i = 0; i < nu; ++i) cp.row(i + nu * j) << greville(ku, i), greville(kv, j);
  }
  const Geometry g(space, cp);
  const basis::BoundaryTrace tr = basis::trace_geometry(g);
  const TraceSpace& trace = *tr.space;
  EXPECT_TRUE(trace.dependent().nonZeros() == 0);
  EXPECT_EQ(trace.num_dofs(), 2 * nu + 2 * nv - 4);
  int checked = 0;
  for (Index e = 0; e < trace.num_elements(); ++e) {
    if (trace.edge(e).part != 0) continue;  // v0
    for (double t : {0.0, 0.3, 0.77, 1.0}) {
      const Eigen::Vector2d x = tr.curve.point(e, t);
      ASSERT_NEAR(x.y(), 0.0, 1e-15);
      CurveBasisValues v;
      trace.evaluate(e, Eigen::VectorXd::Constant(1, t), 1, v);
      basis::CurvePoints p;
      tr.curve.evaluate(e, Eigen::VectorXd::Constant(1, t), p);
      const Index span = ku.span(x.x());
      const Eigen::MatrixXd n = basis::bspline::basis_functions(ku, span, x.x(), 1);
      const auto dofs = trace.dofs(e);
      for (std::size_t a = 0; a < dofs.size(); ++a) {
        const Index s = trace.surface_dofs()[static_cast<std::size_t>(dofs[a])];
        ASSERT_LT(s, nu) << "a trace function of the side v = 0 with j > 0";
        const Index r = s - (span - ku.degree());
        const double expect = r >= 0 && r <= ku.degree() ? n(0, r) : 0.0;
        const double dexpect = r >= 0 && r <= ku.degree() ? n(1, r) * p.dx(0, 0) : 0.0;
        EXPECT_NEAR(v.value(static_cast<Index>(a), 0), expect, 1e-14);
        EXPECT_NEAR(v.dt(static_cast<Index>(a), 0), dexpect, 1e-12);
        ++checked;
      }
    }
  }
  EXPECT_GT(checked, 40);
  // One closed loop with four right-angle corners; perimeter 4, area 1.
  ASSERT_EQ(tr.curve.loops().size(), 1u);
  EXPECT_TRUE(tr.curve.loops()[0].closed);
  expect_unit_square(tr.curve, 1e-12, 1e-13);
}

TEST(Trace, CatmullClarkBoundaryIsTheCubicBsplineOfTheBoundaryPolygon) {
  // OpenSubdiv's VTX_BOUNDARY_EDGE_AND_CORNER: the limit boundary between polygon vertices P_i and P_{i+1} is the
  // uniform cubic B-spline piece of P_{i-1} .. P_{i+2}, with P_{i-1} = 2 P_i − P_{i+1} when P_i is a corner (a
  // vertex of one face), likewise at the other end. Built here from the net's boundary loops alone.
  for (const std::string file : {"l_shape.obj", "square_three_holes.obj", "square_evs.obj"}) {
    const mesh::PolyMesh net = data_mesh(file);
    const Geometry g = registry_geometry("cc", net);
    const auto& cc = dynamic_cast<const basis::catmull_clark::CatmullClarkSpace&>(g.space());
    const mesh::PolyMesh& m = cc.control_mesh();
    const basis::BoundaryTrace tr = basis::trace_geometry(g);
    EXPECT_EQ(tr.curve.loops().size(), m.boundary_loops().size()) << file;
    // The boundary polygons as vertex loops (boundary_loops() lists half-edges; their origins in order).
    std::vector<std::vector<Index>> polygons;
    std::map<Index, std::pair<std::size_t, std::size_t>> where;  // vertex → (loop, position)
    for (std::size_t l = 0; l < m.boundary_loops().size(); ++l) {
      polygons.emplace_back();
      for (Index h : m.boundary_loops()[l]) polygons.back().push_back(m.half_edge(h).origin);
      for (std::size_t k = 0; k < polygons.back().size(); ++k) where[polygons.back()[k]] = {l, k};
    }
    auto corner = [&](Index v) { return m.num_vertex_faces(v) == 1; };
    double worst = 0.0, worst_tangent = 0.0;
    for (Index e = 0; e < tr.space->num_elements(); ++e) {
      const BoundaryEdge& b = tr.space->edge(e);
      const auto face = m.face(b.element);
      const int r = cc.rotation(b.element);
      const Index a = face[static_cast<std::size_t>((b.side + r) % 4)], c = face[static_cast<std::size_t>((b.side + 1 + r) % 4)];
      const auto [loop, ka] = where.at(a);
      const std::vector<Index>& poly = polygons[loop];
      const std::size_t n = poly.size();
      const int dir = poly[(ka + 1) % n] == c ? 1 : -1;
      ASSERT_EQ(poly[(ka + n + static_cast<std::size_t>(dir)) % n], c);
      auto at = [&](long k) { return m.point(poly[static_cast<std::size_t>(((static_cast<long>(ka) + dir * k) % static_cast<long>(n) + static_cast<long>(n)) % static_cast<long>(n))]); };
      const Eigen::Vector3d p1 = at(0), p2 = at(1);
      const Eigen::Vector3d p0 = corner(a) ? Eigen::Vector3d(2 * p1 - p2) : at(-1);
      const Eigen::Vector3d p3 = corner(c) ? Eigen::Vector3d(2 * p2 - p1) : at(2);
      for (double t : {0.0, 0.25, 0.6, 1.0}) {
        const double s = 1 - t;
        const Eigen::Vector3d x = (s * s * s * p0 + (3 * t * t * t - 6 * t * t + 4) * p1 +
                                   (-3 * t * t * t + 3 * t * t + 3 * t + 1) * p2 + t * t * t * p3) / 6.0;
        const Eigen::Vector3d dx = (-s * s * p0 + (3 * t * t - 4 * t) * p1 + (-3 * t * t + 2 * t + 1) * p2 + t * t * p3) / 2.0;
        basis::CurvePoints cp;
        tr.curve.evaluate(e, Eigen::VectorXd::Constant(1, t), cp);
        worst = std::max(worst, (cp.x.col(0) - x.head<2>()).norm());
        // Tangents too, also at the ends that are extraordinary vertices (interpolant there, trace_space.hpp).
        worst_tangent = std::max(worst_tangent, (cp.dx.col(0) - dx.head<2>()).norm());
      }
    }
    EXPECT_LT(worst, 1e-13) << file;
    EXPECT_LT(worst_tangent, 1e-11) << file;
    EXPECT_GT(tr.curve.signed_area(), 0.0) << file;
  }
}

TEST(Trace, CatmullClarkSquareHasStraightSidesAndRightAngles) {
  // square_evs.obj: the boundary polygon lies on the unit square's sides with its corners as one-face vertices,
  // so the limit boundary is the square itself: perimeter 4, area 1, four corners of angle π/2.
  const Geometry g = registry_geometry("cc", data_mesh("square_evs.obj"));
  const basis::BoundaryTrace tr = basis::trace_geometry(g);
  expect_unit_square(tr.curve, 1e-10, 1e-12);
}

TEST(Trace, RestrictionMapsSurfaceFunctionsToTheirTraces) {
  check_restriction(registry_geometry("cc", data_mesh("square_three_holes.obj")), "cc square_three_holes");
  check_restriction(registry_geometry("cc", data_mesh("l_shape.obj")), "cc l_shape");
  check_restriction(registry_geometry("halfbox", mesh::dual_net(data_mesh("tri_square.obj"))), "halfbox tri_square");
  const Geometry poly = registry_geometry("polyhedral", data_mesh("square_evs.obj"));
  check_restriction(poly, "polyhedral square_evs");
  // The polyhedral boundary curves depend on two rows of control points: dependent traces, found and coupled.
  const TraceSpace trace(poly.space_ptr(), poly.space().boundary_edges());
  EXPECT_GT(trace.dependent().nonZeros(), 0);
}

TEST(Trace, TraceOfTheGeometryIsTheBoundaryCurve) {
  // The curve's control points R P reproduce the geometry map on every boundary side (1e-13 of the size), also
  // where the traces are dependent (polyhedral, half-box).
  for (const std::string backend : {"cc", "polyhedral"}) {
    const Geometry g = registry_geometry(backend, data_mesh("l_shape.obj"));
    const basis::BoundaryTrace tr = basis::trace_geometry(g);
    double worst = 0.0;
    for (Index e = 0; e < tr.curve.num_elements(); ++e) {
      for (double t : {0.0, 0.4, 1.0}) {
        Eigen::VectorXd ux = g.control_points().col(0), uy = g.control_points().col(1);
        const Eigen::Vector2d x(surface_value(g.space(), ux, tr.space->edge(e), t),
                                surface_value(g.space(), uy, tr.space->edge(e), t));
        worst = std::max(worst, (tr.curve.point(e, t) - x).norm());
      }
    }
    EXPECT_LT(worst, 1e-13) << backend;
    ASSERT_EQ(tr.curve.loops().size(), 1u) << backend;
    EXPECT_TRUE(tr.curve.loops()[0].closed) << backend;
    EXPECT_GT(tr.curve.signed_area(), 0.0) << backend;
  }
}

TEST(Trace, BadInputIsRefused) {
  const Geometry g = registry_geometry("cc", data_mesh("square_evs.obj"));
  EXPECT_THROW(TraceSpace(g.space_ptr(), {}), InputError);
  EXPECT_THROW(TraceSpace(g.space_ptr(), {BoundaryEdge{g.space().num_elements(), 0, 0}}), InputError);
  EXPECT_THROW(TraceSpace(g.space_ptr(), {BoundaryEdge{0, 4, 0}}), InputError);
  const Geometry surface = registry_geometry("cc", data_mesh("torus_evs.obj"));
  EXPECT_THROW(basis::trace_geometry(surface), InputError);
}
