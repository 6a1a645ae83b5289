// Second derivatives through the geometry map (Assembler::prepare(e, ctx, 2)): physical Hessians and
// Laplacians on a curved planar map, the Laplace–Beltrami operator on surfaces. References: central
// differences of the first-derivative pipeline (independent code path), exactly reproduced functions, and the
// closed-form mean-curvature vector of a polynomial graph.
#include "support/paths.hpp"
#include <gtest/gtest.h>

#include <numbers>

#include <Eigen/SparseCholesky>
#include <algorithm>
#include <cmath>
#include <iostream>

#include "basis/bspline/patches.hpp"
#include "basis/catmull_clark/space.hpp"
#include "core/error.hpp"
#include "fem/assembler.hpp"
#include "mesh/obj_reader.hpp"
#include "quadrature/rule_provider.hpp"
#include "refine/uniform.hpp"

using namespace iga;

namespace {

constexpr double kStep = 1e-5;  // central-difference step in the reference coordinates

// Physical (surface) gradients of the local functions at pts, nloc × (dim·q) in ElementContext::grad's
// layout, from the first-derivative pipeline only (basis with derivatives = 1, Geometry::evaluate's tu, tv).
Eigen::MatrixXd gradients(const basis::Geometry& g, Index e, const Eigen::Matrix2Xd& pts) {
  basis::BasisValues bv;
  basis::GeometryValues gv;
  g.space().evaluate(e, pts, 1, bv);
  g.evaluate(e, bv, gv);
  const Index q = pts.cols();
  Eigen::MatrixXd out(bv.value.rows(), g.dim() * q);
  for (int c = 0; c < g.dim(); ++c) {
    out.middleCols(c * q, q) =
        bv.du.array().rowwise() * gv.tu.row(c).array() + bv.dv.array().rowwise() * gv.tv.row(c).array();
  }
  return out;
}

// Central differences of the gradients at the points of ctx: du[c], dv[c] (nloc × q) approximate
// ∂(∇φ)_c/∂u and ∂(∇φ)_c/∂v.
struct GradientDifferences {
  std::vector<Eigen::MatrixXd> du, dv;
};

GradientDifferences differences(const basis::Geometry& g, const fem::ElementContext& ctx) {
  const Index q = ctx.num_points();
  Eigen::Matrix2Xd pts(2, 4 * q);  // per point: +u, −u, +v, −v
  for (Index k = 0; k < q; ++k) {
    const Eigen::Vector2d p = ctx.rule->points.col(k);
    pts.col(4 * k) = p + Eigen::Vector2d(kStep, 0);
    pts.col(4 * k + 1) = p - Eigen::Vector2d(kStep, 0);
    pts.col(4 * k + 2) = p + Eigen::Vector2d(0, kStep);
    pts.col(4 * k + 3) = p - Eigen::Vector2d(0, kStep);
  }
  const Eigen::MatrixXd gr = gradients(g, ctx.element, pts);
  const Index nloc = gr.rows();
  GradientDifferences d;
  for (int c = 0; c < g.dim(); ++c) {
    Eigen::MatrixXd du(nloc, q), dv(nloc, q);
    for (Index k = 0; k < q; ++k) {
      const Index o = c * 4 * q + 4 * k;
      du.col(k) = (gr.col(o) - gr.col(o + 1)) / (2 * kStep);
      dv.col(k) = (gr.col(o + 2) - gr.col(o + 3)) / (2 * kStep);
    }
    d.du.push_back(du);
    d.dv.push_back(dv);
  }
  return d;
}

// max over the elements of max|a − b| / max|b| (b the reference, per element).
struct RelativeError {
  double max = 0.0;
  void add(const Eigen::MatrixXd& a, const Eigen::MatrixXd& b) {
    max = std::max(max, (a - b).cwiseAbs().maxCoeff() / b.cwiseAbs().maxCoeff());
  }
};

// The element's control points, nloc × dim.
Eigen::MatrixXd local_control_points(const basis::Geometry& g, Index e) {
  const auto dofs = g.space().dofs(e);
  Eigen::MatrixXd p(static_cast<Index>(dofs.size()), g.dim());
  for (Index a = 0; a < p.rows(); ++a) p.row(a) = g.control_points().row(dofs[a]);
  return p;
}

mesh::PolyMesh net(const std::string& name) {
  return mesh::read_obj(std::string(IGA_SOURCE_DIR) + "/data/meshes/" + name);
}

// z = f(x, y) over [0,1]² as one bicubic Bézier patch: x = u, y = v, z = f(u, v) with f of bidegree <= 3,
// written in Bernstein form through u^a = Σ_i C(i,a)/C(3,a) B_i(u) (the blossom of u^a), so the surface is
// exactly the graph.
struct Monomial {
  int a, b;
  double c;
};
const std::vector<Monomial> kGraph = {{2, 0, 0.5}, {1, 2, 0.25}, {0, 3, -0.3}, {3, 1, 0.2}};

basis::Geometry make_graph_surface() {
  auto choose = [](int n, int k) {
    double r = 1.0;
    for (int t = 1; t <= k; ++t) r = r * (n - k + t) / t;  // C(n, k), 0 for k > n
    return k > n ? 0.0 : r;
  };
  Eigen::MatrixXd cp(16, 3);
  for (int j = 0; j < 4; ++j) {
    for (int i = 0; i < 4; ++i) {
      double z = 0;
      for (const Monomial& m : kGraph) z += m.c * choose(i, m.a) / choose(3, m.a) * choose(j, m.b) / choose(3, m.b);
      cp.row(i + 4 * j) << i / 3.0, j / 3.0, z;
    }
  }
  using basis::bspline::KnotVector;
  return basis::bspline::make_patch(KnotVector::uniform(3, 1), KnotVector::uniform(3, 1), cp);
}

// f and its derivatives up to order 2 at (x, y): {f_x, f_y, f_xx, f_xy, f_yy}.
Eigen::Matrix<double, 5, 1> graph_derivatives(double x, double y) {
  Eigen::Matrix<double, 5, 1> d = Eigen::Matrix<double, 5, 1>::Zero();
  auto pw = [](double t, int k) { return k < 0 ? 0.0 : std::pow(t, k); };
  for (const Monomial& m : kGraph) {
    d(0) += m.c * m.a * pw(x, m.a - 1) * pw(y, m.b);
    d(1) += m.c * m.b * pw(x, m.a) * pw(y, m.b - 1);
    d(2) += m.c * m.a * (m.a - 1) * pw(x, m.a - 2) * pw(y, m.b);
    d(3) += m.c * m.a * m.b * pw(x, m.a - 1) * pw(y, m.b - 1);
    d(4) += m.c * m.b * (m.b - 1) * pw(x, m.a) * pw(y, m.b - 2);
  }
  return d;
}

}  // namespace

// On the quarter annulus (degree 3, refined once: 4 curved elements), the Hessian of every local function at
// the 4×4 Gauss points against H_x = [∂g/∂u ∂g/∂v] J^{-1}, g = ∇_x φ from the first-derivative pipeline
// differenced centrally with step 1e-5 (truncation ~h²|g'''| ~ 1e-10, rounding ~eps|g|/h ~ 1e-11, relative
// to the element's largest Hessian entry; measured 9e-11, xy vs yx 1.5e-10, so 1e-8 leaves a margin of 60);
// the Laplacian is the Hessian's trace to rounding (measured 2e-16).
TEST(SecondDerivatives, PlanarHessianMatchesDifferencesOfTheGradient) {
  const basis::Geometry g = refine::refine_uniform(basis::bspline::make_quarter_annulus(3), 1).geometry;
  const quadrature::Gauss rules(4);
  const fem::Assembler assembler(g, rules);
  fem::ElementContext ctx;
  RelativeError hess, sym, trace;
  for (Index e = 0; e < g.space().num_elements(); ++e) {
    assembler.prepare(e, ctx, 2);
    ASSERT_EQ(ctx.derivatives, 2);
    const Index q = ctx.num_points();
    ASSERT_EQ(ctx.hessian.cols(), 3 * q);
    ASSERT_EQ(ctx.laplacian.cols(), q);
    const GradientDifferences d = differences(g, ctx);
    // FD Hessian entry (c, b) = ∂g_c/∂u (∇u)_b + ∂g_c/∂v (∇v)_b, with ∇u = tu, ∇v = tv on planar maps.
    auto fd = [&](int c, int b) -> Eigen::MatrixXd {
      return (d.du[static_cast<std::size_t>(c)].array().rowwise() * ctx.geo.tu.row(b).array() +
              d.dv[static_cast<std::size_t>(c)].array().rowwise() * ctx.geo.tv.row(b).array()).matrix();
    };
    Eigen::MatrixXd all_fd(ctx.hessian.rows(), 3 * q);
    all_fd << fd(0, 0), fd(0, 1), fd(1, 1);
    hess.add(ctx.hessian, all_fd);
    sym.add(ctx.hessian_block(1), fd(1, 0));
    trace.add(ctx.laplacian, ctx.hessian_block(0) + ctx.hessian_block(2));
  }
  std::cout << "planar Hessian vs FD: " << hess.max << " (xy vs yx " << sym.max << "), Laplacian vs trace "
            << trace.max << "\n";
  EXPECT_LE(hess.max, 1e-8);
  EXPECT_LE(sym.max, 1e-8);
  EXPECT_LE(trace.max, 1e-14);
}

// Σ_a P_a φ_a = x (the map is in the space): Σ_a P_{a,c} ∇φ_a = e_c, Σ_a P_{a,c} H(φ_a) = 0 and
// Σ_a P_{a,c} Δφ_a = 0, up to rounding (relative to Σ_a |P_{a,c}| |H φ_a|).
TEST(SecondDerivatives, CoordinatesHaveNoHessian) {
  const basis::Geometry g = refine::refine_uniform(basis::bspline::make_quarter_annulus(3), 1).geometry;
  const quadrature::Gauss rules(4);
  const fem::Assembler assembler(g, rules);
  fem::ElementContext ctx;
  double worst = 0.0, worst_grad = 0.0;
  for (Index e = 0; e < g.space().num_elements(); ++e) {
    assembler.prepare(e, ctx, 2);
    const Eigen::MatrixXd p = local_control_points(g, e);
    const Index q = ctx.num_points();
    for (int c = 0; c < 2; ++c) {
      const double scale = (p.col(c).cwiseAbs().transpose() * ctx.hessian.cwiseAbs()).maxCoeff();
      worst = std::max(worst, (p.col(c).transpose() * ctx.hessian).cwiseAbs().maxCoeff() / scale);
      worst = std::max(worst, (p.col(c).transpose() * ctx.laplacian).cwiseAbs().maxCoeff() / scale);
      for (int b = 0; b < 2; ++b) {
        const Eigen::RowVectorXd gcb = p.col(c).transpose() * ctx.grad.middleCols(b * q, q);
        worst_grad = std::max(worst_grad, (gcb.array() - (b == c ? 1.0 : 0.0)).abs().maxCoeff());
      }
    }
  }
  std::cout << "coordinates: relative Hessian/Laplacian " << worst << ", gradient " << worst_grad << "\n";
  EXPECT_LE(worst, 1e-12);
  EXPECT_LE(worst_grad, 1e-12);
}

// On the L-shape (degree 2, refined once) each half of the patch is a bilinear map of a quadrilateral that is not a
// parallelogram, so f = x² + xy + 2y² (bidegree (2,2) in (u,v)) is in the space; its L2 projection u_h reproduces
// it (the projection with any rule is exact for a member of the space), so H u_h = [[2,1],[1,4]] and Δu_h = 6 at
// every point: the Christoffel correction −Σ_k ∂_k u H_u x_k is exercised on a non-affine map. Pointwise through
// integrate_per_element(…, 2), and ∫ Δu_h = 6 · area (area 3). (The quarter annulus is a NURBS patch now: x² is
// not in its rational space.) Tolerance 1e-9 for the mass-matrix solve's rounding amplified by second derivatives.
TEST(SecondDerivatives, QuadraticInTheSpaceHasItsExactHessian) {
  const basis::Geometry g = refine::refine_uniform(basis::bspline::make_l_shape(2), 1).geometry;
  const quadrature::Gauss rules(4);
  const fem::Assembler assembler(g, rules);
  const fem::MassForm mass;
  const fem::SourceForm source(fem::make_function(
      [](const Eigen::Vector3d& x) { return x(0) * x(0) + x(0) * x(1) + 2 * x(1) * x(1); }));
  const std::vector<const fem::BilinearForm*> bm{&mass};
  const std::vector<const fem::LinearForm*> lf{&source};
  Eigen::SparseMatrix<double> m;
  Eigen::VectorXd b;
  assembler.assemble(bm, lf, m, b);
  const Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> ldlt(m);
  ASSERT_EQ(ldlt.info(), Eigen::Success);
  const Eigen::VectorXd c = ldlt.solve(b);
  const Eigen::MatrixXd per_element = assembler.integrate_per_element(
      3,
      [&](const fem::ElementContext& ctx, Eigen::Ref<Eigen::VectorXd> out) {
        const auto dofs = g.space().dofs(ctx.element);
        Eigen::VectorXd cl(static_cast<Index>(dofs.size()));
        for (Index a = 0; a < cl.size(); ++a) cl(a) = c(dofs[a]);
        const Eigen::RowVectorXd h = cl.transpose() * ctx.hessian;  // [xx | xy | yy]
        const Eigen::RowVectorXd lap = cl.transpose() * ctx.laplacian;
        const Index q = ctx.num_points();
        out(0) = std::max({(h.segment(0, q).array() - 2).abs().maxCoeff(), (h.segment(q, q).array() - 1).abs().maxCoeff(),
                           (h.segment(2 * q, q).array() - 4).abs().maxCoeff()});
        out(1) = (lap.array() - 6).abs().maxCoeff();
        out(2) = lap.dot(ctx.weight);
      },
      2);
  const double hess_err = per_element.row(0).maxCoeff(), lap_err = per_element.row(1).maxCoeff();
  std::cout << "x²+xy+2y² in the degree-2 space on the L-shape: Hessian error " << hess_err << ", Laplacian error "
            << lap_err << ", ∫Δu_h − 18 = " << per_element.row(2).sum() - 18.0 << "\n";
  EXPECT_LE(hess_err, 1e-9);
  EXPECT_LE(lap_err, 1e-9);
  EXPECT_NEAR(per_element.row(2).sum(), 18.0, 1e-9);
}

// The coordinate functions on a surface: Δ_Γ x = H⃗, the mean-curvature vector. For the graph z = f(x, y)
// (exactly a bicubic Bézier patch, refined twice), H⃗ = div(∇f/W) ν with W = sqrt(1 + |∇f|²),
// ν = (−f_x, −f_y, 1)/W and div(∇f/W) = ((1 + f_y²) f_xx − 2 f_x f_y f_xy + (1 + f_x²) f_yy)/W³ (the minimal
// surface operator; a paraboloid z = r²/(2R) gives 2/R at its vertex, the sphere's −(2/R²)(x − centre)).
// Exact up to rounding. The Hessian stays empty on surfaces.
TEST(SecondDerivatives, LaplaceBeltramiOfTheCoordinatesIsTheMeanCurvatureVector) {
  const basis::Geometry g = refine::refine_uniform(make_graph_surface(), 2).geometry;
  ASSERT_EQ(g.dim(), 3);
  const quadrature::Gauss rules(4);
  const fem::Assembler assembler(g, rules);
  fem::ElementContext ctx;
  double worst = 0.0, largest = 0.0;
  for (Index e = 0; e < g.space().num_elements(); ++e) {
    assembler.prepare(e, ctx, 2);
    EXPECT_EQ(ctx.hessian.size(), 0);
    const Eigen::MatrixXd lb = local_control_points(g, e).transpose() * ctx.laplacian;  // 3 × q
    for (Index k = 0; k < ctx.num_points(); ++k) {
      const auto d = graph_derivatives(ctx.geo.x(0, k), ctx.geo.x(1, k));
      const double w = std::sqrt(1 + d(0) * d(0) + d(1) * d(1));
      const double kappa = ((1 + d(1) * d(1)) * d(2) - 2 * d(0) * d(1) * d(3) + (1 + d(0) * d(0)) * d(4)) / (w * w * w);
      const Eigen::Vector3d exact = kappa * Eigen::Vector3d(-d(0), -d(1), 1) / w;
      worst = std::max(worst, (lb.col(k) - exact).cwiseAbs().maxCoeff());
      largest = std::max(largest, exact.cwiseAbs().maxCoeff());
    }
  }
  std::cout << "graph surface: |Δ_Γ x − H⃗| max " << worst << " (|H⃗| up to " << largest << ")\n";
  EXPECT_GT(largest, 0.5);
  EXPECT_LE(worst, 1e-10);
}

// Δ_Γ φ = div_Γ ∇_Γ φ = Σ_c (∇_Γ (∇_Γ φ)_c)_c with ∇_Γ h = tu h_u + tv h_v, the surface gradient differenced
// centrally (step 1e-5), for every local function: on the graph surface and on a Catmull–Clark surface with
// extraordinary vertices (the cube's limit surface refined once, valence-3 elements included; 4×4 Gauss points
// keep away from the vertex where second derivatives are singular). Relative to the element's largest value;
// measured 5e-11 (graph) and 3.6e-10 (cube), the difference step's accuracy as in the planar test.
TEST(SecondDerivatives, SurfaceLaplaceBeltramiMatchesDifferencesOfTheSurfaceGradient) {
  const basis::Geometry graph = refine::refine_uniform(make_graph_surface(), 1).geometry;
  const basis::Geometry cube =
      refine::refine_uniform(basis::catmull_clark::make_catmull_clark_geometry(net("cube.obj")), 1).geometry;
  const quadrature::Gauss rules(4);
  for (const basis::Geometry* g : {&graph, &cube}) {
    ASSERT_EQ(g->dim(), 3);
    const fem::Assembler assembler(*g, rules);
    fem::ElementContext ctx;
    RelativeError err;
    for (Index e = 0; e < g->space().num_elements(); ++e) {
      assembler.prepare(e, ctx, 2);
      const GradientDifferences d = differences(*g, ctx);
      Eigen::MatrixXd div = Eigen::MatrixXd::Zero(ctx.laplacian.rows(), ctx.num_points());
      for (int c = 0; c < 3; ++c) {
        div.array() += d.du[static_cast<std::size_t>(c)].array().rowwise() * ctx.geo.tu.row(c).array() +
                       d.dv[static_cast<std::size_t>(c)].array().rowwise() * ctx.geo.tv.row(c).array();
      }
      err.add(ctx.laplacian, div);
    }
    std::cout << g->space().name() << " surface: Laplace–Beltrami vs FD divergence " << err.max << "\n";
    EXPECT_LE(err.max, 1e-8);
  }
}

// integrate(…, 2) prepares the same first-order data as integrate(…, 1) (the area of the quarter annulus,
// 3π/4 up to the 4-point rule's error on its rational integrand, agrees to rounding), records derivatives, leaves laplacian/hessian empty with 1, and rejects 0 and 3.
TEST(SecondDerivatives, IntegrateAsksForWhatTheIntegrandNeeds) {
  const basis::Geometry g = refine::refine_uniform(basis::bspline::make_quarter_annulus(3), 1).geometry;
  const quadrature::Gauss rules(4);
  const fem::Assembler assembler(g, rules);
  auto area = [](const fem::ElementContext& c, Eigen::Ref<Eigen::VectorXd> out) {
    out(0) = c.weight.sum();
    out(1) = c.derivatives;
    out(2) = static_cast<double>(c.laplacian.size() + c.hessian.size());
  };
  const Eigen::VectorXd one = assembler.integrate(3, area);
  const Eigen::VectorXd two = assembler.integrate(3, area, 2);
  const double ne = static_cast<double>(g.space().num_elements());
  EXPECT_NEAR(one(0), 0.75 * std::numbers::pi, 1e-7);
  EXPECT_NEAR(two(0), one(0), 1e-14);
  EXPECT_EQ(one(1), ne);
  EXPECT_EQ(two(1), 2 * ne);
  EXPECT_EQ(one(2), 0.0);
  EXPECT_EQ(two(2), ne * 16 * (16 + 48));  // 16 local functions, 16 points: laplacian 16×16, hessian 16×48
  // A context used with 2 and then 1 drops the second-order data.
  fem::ElementContext ctx;
  assembler.prepare(0, ctx, 2);
  assembler.prepare(0, ctx);
  EXPECT_EQ(ctx.derivatives, 1);
  EXPECT_EQ(ctx.laplacian.size() + ctx.hessian.size(), 0);
  EXPECT_THROW(assembler.prepare(0, ctx, 3), InputError);
  EXPECT_THROW(assembler.integrate(1, area, 0), InputError);
}
