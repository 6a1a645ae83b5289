// Issue 32, item 2: on the quarter annulus, u = sin(πx) sin(πy) is approximated worse by degree 4 than by degree 3
// on the same mesh (refine 1 and 2), and degree 6 worse than 5. Decided by measurement: it is the space, not the
// solver. (a) Céa: the Galerkin H1 error is within 1.2 of the best approximation in the space (the H1 projection
// of u), at every degree; (b) the best approximation itself shows the same parity; (c) the library's L2 projection
// equals an independent one (polynomial B-splines by Cox–de Boor here, the annulus as (1 + u)·(rational quadratic
// arc in v), whose span is {P(u, v) / W(v)}), so the space is the NURBS space it should be. On the unit square
// (polynomial splines) the degrees order as expected. The same parity at refine 1 and 2 vanishes from refine 3 on
// (a pre-asymptotic effect of the coarse maximally smooth spaces: u has about one wave per element along the
// outer arc).
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <Eigen/SparseCholesky>
#include <cmath>
#include <numbers>
#include <vector>

#include "basis/bspline/patches.hpp"
#include "fem/assembler.hpp"
#include "fem/errors.hpp"
#include "fem/forms.hpp"
#include "fem/poisson.hpp"
#include "fem/problems.hpp"
#include "quadrature/rule_provider.hpp"
#include "refine/uniform.hpp"

using namespace iga;

namespace {

constexpr double kPi = std::numbers::pi;

struct Errors {
  double galerkin_h1, h1_projection_h1, l2_projection_l2;  // relative
};

// The Galerkin solution and the L2 and H1 projections of the sine problem's u, in the library's space.
Errors library_errors(const basis::Geometry& g0, int refine) {
  const fem::ManufacturedProblem mp = fem::manufactured_problem("sine");
  const basis::Geometry g = refine::refine_uniform(g0, refine).geometry;
  const quadrature::Gauss rule(14);  // the integrals exact to the digits compared below, at every degree
  const fem::Assembler a(g, rule);
  fem::MassForm mass;
  fem::StiffnessForm stiffness;
  fem::SourceForm load(mp.exact);
  const fem::BilinearForm* l2[1] = {&mass};
  const fem::BilinearForm* h1[2] = {&mass, &stiffness};
  const fem::LinearForm* f[1] = {&load};
  Eigen::SparseMatrix<double> m, h;
  Eigen::VectorXd bm, bh;
  a.assemble(l2, f, m, bm);
  a.assemble(h1, f, h, bh);
  const Eigen::VectorXd grad_load = a.integrate(a.num_dofs(), [&](const fem::ElementContext& ctx, Eigen::Ref<Eigen::VectorXd> out) {
    Eigen::Matrix3Xd gu;
    mp.exact->gradients(ctx.geo.x, gu);
    const auto dofs = g.space().dofs(ctx.element);
    for (int c = 0; c < 2; ++c) {
      const Eigen::VectorXd t = ctx.grad_component(c) * gu.row(c).transpose().cwiseProduct(ctx.weight);
      for (std::size_t i = 0; i < dofs.size(); ++i) out(dofs[i]) += t(static_cast<Eigen::Index>(i));
    }
  });
  const Eigen::VectorXd cl2 = Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>>(m).solve(bm);
  const Eigen::VectorXd ch1 = Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>>(h).solve(bh + grad_load);
  const fem::Norm norms[2] = {fem::Norm::kL2, fem::Norm::kH1};
  const Eigen::VectorXd sl2 = fem::norm_squares(a, cl2, *mp.exact, norms), sh1 = fem::norm_squares(a, ch1, *mp.exact, norms);
  fem::PoissonProblem p;
  p.source = mp.source;
  p.exact = mp.exact;
  p.dirichlet = mp.exact;
  const fem::PoissonResult r = fem::solve_poisson(g, rule, p);
  return {r.errors->h1 / r.errors->h1_exact, std::sqrt(sh1(2) / sh1(3)), std::sqrt(sl2(0) / sl2(1))};
}

// Cox–de Boor: the B-splines of degree p on the open uniform knot vector of n intervals of [0, 1] at t.
Eigen::VectorXd bsplines(int p, int n, double t) {
  std::vector<double> k;
  for (int i = 0; i < p; ++i) k.push_back(0.0);
  for (int i = 0; i <= n; ++i) k.push_back(static_cast<double>(i) / n);
  for (int i = 0; i < p; ++i) k.push_back(1.0);
  const int m = static_cast<int>(k.size()) - 1;
  Eigen::VectorXd b = Eigen::VectorXd::Zero(m);
  int span = std::min(static_cast<int>(t * n), n - 1) + p;
  b(span) = 1.0;
  for (int d = 1; d <= p; ++d) {
    Eigen::VectorXd c = Eigen::VectorXd::Zero(m);
    for (int i = 0; i + d < m; ++i) {
      const double l = k[i + d] > k[i] ? (t - k[i]) / (k[i + d] - k[i]) * b(i) : 0.0;
      const double r = k[i + d + 1] > k[i + 1] ? (k[i + d + 1] - t) / (k[i + d + 1] - k[i + 1]) * b(i + 1) : 0.0;
      c(i) = l + r;
    }
    b = c;
  }
  return b.head(p + n);
}

// The relative L2 error of the best approximation of u in {P(u, v) / W(v)}, P of degree p on n × n intervals, on
// the annulus x = (1 + u) (arc(v)), arc the rational quadratic quarter circle with weights 1, 1/√2, 1: the normal
// equations by 14 × 14 Gauss points per element (Gauss–Legendre from the Golub–Welsch matrix).
double independent_l2_projection(int p, int n) {
  const int g = 14;
  Eigen::MatrixXd jacobi = Eigen::MatrixXd::Zero(g, g);
  for (int i = 1; i < g; ++i) jacobi(i, i - 1) = jacobi(i - 1, i) = i / std::sqrt(4.0 * i * i - 1);
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(jacobi);
  const Eigen::VectorXd nodes = (eig.eigenvalues().array() + 1) / 2;
  const Eigen::VectorXd weights = eig.eigenvectors().row(0).transpose().array().square();  // sum 1 on [0, 1]
  const int dofs = (p + n) * (p + n);
  Eigen::MatrixXd mass = Eigen::MatrixXd::Zero(dofs, dofs);
  Eigen::VectorXd load = Eigen::VectorXd::Zero(dofs);
  double norm = 0.0, uu = 0.0;
  const double w1 = 1 / std::sqrt(2.0);
  for (int eu = 0; eu < n; ++eu) {
    for (int ev = 0; ev < n; ++ev) {
      for (int i = 0; i < g; ++i) {
        for (int j = 0; j < g; ++j) {
          const double u = (eu + nodes(i)) / n, v = (ev + nodes(j)) / n;
          const double w = (1 - v) * (1 - v) + 2 * w1 * v * (1 - v) + v * v;
          const double ax = ((1 - v) * (1 - v) + 2 * w1 * v * (1 - v)) / w, ay = (2 * w1 * v * (1 - v) + v * v) / w;
          // |det J| = |∂x/∂u × ∂x/∂v| = (1 + u) |arc'(v)| (arc' ⟂ arc, |arc| = 1), |arc'| by a central difference
          // of the closed form (exact enough: 1e-10 relative).
          const double h = 1e-5;
          auto arc = [w1](double t) {
            const double d = (1 - t) * (1 - t) + 2 * w1 * t * (1 - t) + t * t;
            return Eigen::Vector2d(((1 - t) * (1 - t) + 2 * w1 * t * (1 - t)) / d, (2 * w1 * t * (1 - t) + t * t) / d);
          };
          const double speed = ((arc(v + h) - arc(v - h)) / (2 * h)).norm();
          const double dx = (1 + u) * speed * weights(i) * weights(j) / (n * n);
          const double x = (1 + u) * ax, y = (1 + u) * ay, f = std::sin(kPi * x) * std::sin(kPi * y);
          const Eigen::VectorXd bu = bsplines(p, n, u), bv = bsplines(p, n, v);
          Eigen::VectorXd phi(dofs);
          for (int a = 0; a < p + n; ++a) {
            for (int b = 0; b < p + n; ++b) phi(a + (p + n) * b) = bu(a) * bv(b) / w;
          }
          mass.noalias() += dx * phi * phi.transpose();
          load += dx * f * phi;
          uu += dx * f * f;
        }
      }
    }
  }
  const Eigen::VectorXd c = mass.ldlt().solve(load);
  norm = uu - load.dot(c);  // ‖u − Πu‖² = ‖u‖² − (u, Πu) for the orthogonal projection
  return std::sqrt(std::max(norm, 0.0) / uu);
}

}  // namespace

TEST(AnnulusDegrees, EvenDegreesAreThePropertyOfTheSpaceNotTheSolver) {
  for (int refine : {1, 2}) {
    std::vector<Errors> e;
    for (int p = 2; p <= 6; ++p) {
      e.push_back(library_errors(basis::bspline::make_quarter_annulus(p), refine));
      const Errors& x = e.back();
      // (a) Céa's lemma with the projected Dirichlet data: measured 1.06 .. 1.16.
      EXPECT_LT(x.galerkin_h1, 1.2 * x.h1_projection_h1) << "refine " << refine << " degree " << p;
      EXPECT_GE(x.galerkin_h1, 0.99 * x.h1_projection_h1) << "refine " << refine << " degree " << p;
      // (c) The library's L2 projection is the independent one's (measured to 1e-9).
      EXPECT_NEAR(x.l2_projection_l2, independent_l2_projection(p, 1 << refine), 1e-6 * x.l2_projection_l2)
          << "refine " << refine << " degree " << p;
    }
    // (b) The best approximations show the parity the Galerkin errors show: 4 worse than 3, 6 worse than 5.
    EXPECT_GT(e[2].h1_projection_h1, e[1].h1_projection_h1) << "refine " << refine;
    EXPECT_GT(e[4].l2_projection_l2, e[3].l2_projection_l2) << "refine " << refine;
  }
  // Asymptotically the degrees order as they should: at refine 4, each degree beats the one below.
  double previous = 1.0;
  for (int p = 2; p <= 5; ++p) {
    const Errors x = library_errors(basis::bspline::make_quarter_annulus(p), 4);
    EXPECT_LT(x.galerkin_h1, 0.8 * previous) << "degree " << p;
    previous = x.galerkin_h1;
  }
}

TEST(AnnulusDegrees, OnTheUnitSquareEachDegreeBeatsTheOneBelow) {
  for (int refine : {1, 2}) {
    double previous = 1.0;
    for (int p = 2; p <= 6; ++p) {
      const Errors x = library_errors(basis::bspline::make_rectangle(p), refine);
      EXPECT_LT(x.galerkin_h1, 0.5 * previous) << "refine " << refine << " degree " << p;
      EXPECT_LT(x.galerkin_h1, 1.2 * x.h1_projection_h1);
      previous = x.galerkin_h1;
    }
  }
}
