// Catmull–Clark elements through the whole pipeline: areas of the project's nets (per-tile quadrature vs
// closed forms), the thesis §4.2.2 benchmarks, Laplace–Beltrami on closed surfaces.
#include "support/paths.hpp"
#include <gtest/gtest.h>

#include <cmath>

#include "basis/catmull_clark/ev_enrichment.hpp"
#include "basis/catmull_clark/space.hpp"
#include "core/error.hpp"
#include "fem/assembler.hpp"
#include "fem/expression.hpp"
#include "fem/poisson.hpp"
#include "mesh/obj_reader.hpp"
#include "quadrature/per_tile.hpp"
#include "quadrature/rule_provider.hpp"
#include "quadrature/spline_gauss/macro_rule.hpp"
#include "refine/uniform.hpp"
#include "support/nets.hpp"
#include "support/rates.hpp"

using namespace iga;
using iga::test::fitted_rate;
using iga::test::closed_fan;
using iga::test::square_grid;

namespace {
mesh::PolyMesh net(const std::string& name) { return mesh::read_obj(std::string(IGA_SOURCE_DIR) + "/data/meshes/" + name); }

double area(const basis::Geometry& g, const quadrature::RuleProvider& rules) {
  return fem::Assembler(g, rules).integrate(1, [](const fem::ElementContext& c, Eigen::Ref<Eigen::VectorXd> o) {
    o(0) = c.weight.sum();
  })(0);
}

// The area enclosed by the limit boundary, computed independently of the surface: by Green's theorem,
// (1/2) ∮ (x y' - y x') over the boundary curves, which are uniform cubic B-splines of the boundary polygon
// split at the corners (vertices with one face), with the end phantoms 2 P_0 - P_1 that interpolate corners.
double boundary_area(const mesh::PolyMesh& m) {
  const double g[3] = {0.5 - std::sqrt(0.15), 0.5, 0.5 + std::sqrt(0.15)};
  const double w[3] = {5.0 / 18, 8.0 / 18, 5.0 / 18};
  auto span = [&](const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& c, const Eigen::Vector2d& d) {
    double s = 0;
    for (int k = 0; k < 3; ++k) {
      const double t = g[k], t2 = t * t, t3 = t2 * t;
      const Eigen::Vector2d x = ((1 - t) * (1 - t) * (1 - t) * a + (3 * t3 - 6 * t2 + 4) * b + (-3 * t3 + 3 * t2 + 3 * t + 1) * c + t3 * d) / 6;
      const Eigen::Vector2d dx = (-3 * (1 - t) * (1 - t) * a + (9 * t2 - 12 * t) * b + (-9 * t2 + 6 * t + 3) * c + 3 * t2 * d) / 6;
      s += w[k] * 0.5 * (x(0) * dx(1) - x(1) * dx(0));
    }
    return s;
  };
  double total = 0;
  for (const auto& loop : m.boundary_loops()) {
    std::vector<Index> vs;
    for (Index h : loop) vs.push_back(m.half_edge(h).origin);
    const std::size_t n = vs.size();
    std::size_t first = n;
    for (std::size_t i = 0; i < n; ++i) {
      if (m.num_vertex_faces(vs[i]) == 1) {
        first = i;
        break;
      }
    }
    auto p = [&](std::size_t i) -> Eigen::Vector2d { return m.point(vs[i % n]).head<2>(); };
    if (first == n) {  // closed periodic B-spline
      for (std::size_t i = 0; i < n; ++i) total += span(p(i + n - 1), p(i), p(i + 1), p(i + 2));
      continue;
    }
    // Segments between consecutive corners.
    std::size_t s = first;
    do {
      std::size_t e = s + 1;
      while (m.num_vertex_faces(vs[e % n]) != 1) ++e;
      std::vector<Eigen::Vector2d> q;
      for (std::size_t i = s; i <= e; ++i) q.push_back(p(i));
      const std::size_t k = q.size();
      q.insert(q.begin(), 2 * q[0] - q[1]);
      q.push_back(2 * q[k] - q[k - 1]);
      for (std::size_t i = 0; i + 3 < q.size(); ++i) total += span(q[i], q[i + 1], q[i + 2], q[i + 3]);
      s = e;
    } while (s % n != first);
  }
  return total;
}

// Thesis §4.2.2 (ii): u = (cos πx − 1) sin 2πy, Dirichlet on x = 0, y = 0, y = 1, Neumann 0 on x = 1.
fem::PoissonProblem benchmark_ii() {
  fem::PoissonProblem p;
  p.source = std::make_shared<fem::Expression>("pi^2*(5*cos(pi*x)-4)*sin(2*pi*y)", "--source");
  p.exact = std::make_shared<fem::Expression>("(cos(pi*x)-1)*sin(2*pi*y)", "--exact");
  p.dirichlet = p.exact;
  p.neumann = std::make_shared<fem::Expression>("0", "--neumann", true);
  p.neumann_where = std::make_shared<fem::Expression>("x > 1 - 1e-9", "--neumann-where");
  return p;
}
}  // namespace

// The unit-square net with interior and boundary EVs: area 1 exactly in the limit (straight boundary, corners
// interpolated); per-tile quadrature converges geometrically in the number of levels.
TEST(CatmullClarkPoisson, SquareAreaConvergesGeometricallyInTileLevels) {
  const basis::Geometry g = basis::catmull_clark::make_catmull_clark_geometry(net("square_evs.obj"));
  double previous = 1.0;
  for (int levels = 2; levels <= 12; levels += 2) {
    const double err = std::abs(area(g, quadrature::PerTile(4, levels)) - 1.0);
    EXPECT_LT(err, 0.2 * previous) << levels;  // measured: a factor ~10 per two levels
    previous = err;
  }
  EXPECT_LE(std::abs(area(g, quadrature::PerTile(4, 24)) - 1.0), 1e-14);
}

TEST(CatmullClarkPoisson, AreasMatchTheBoundaryCurves) {
  for (const char* name : {"l_shape.obj", "square_three_holes.obj", "square_evs.obj"}) {
    const mesh::PolyMesh m = net(name);
    const double exact = boundary_area(m);
    const basis::Geometry g = basis::catmull_clark::make_catmull_clark_geometry(m);
    EXPECT_NEAR(area(g, quadrature::PerTile(4, 24)), exact, 1e-13 * exact) << name;
  }
  // The reflex corners are smooth boundary points (only one-face vertices are corners), so the L-shape is
  // rounded there: its area is not 3.
  EXPECT_GT(boundary_area(net("l_shape.obj")), 3.0 + 1e-3);
}

// Thesis §4.2.2 (i): u = 1 at x = 0, u = 0 at x = 1, homogeneous Neumann on y = 0, 1: the linear solution
// 1 - x is in the isoparametric space; only quadrature error remains, which the tile levels remove.
TEST(CatmullClarkPoisson, LinearSolutionIsReproduced) {
  const basis::Geometry g = basis::catmull_clark::make_catmull_clark_geometry(net("square_evs.obj"));
  fem::PoissonProblem p;
  p.exact = std::make_shared<fem::Expression>("1 - x", "--exact");
  p.dirichlet = p.exact;
  p.neumann = std::make_shared<fem::Expression>("0", "--neumann", true);
  p.neumann_where = std::make_shared<fem::Expression>("(y < 1e-9) + (y > 1 - 1e-9)", "--neumann-where");
  const fem::PoissonResult r = fem::solve_poisson(g, quadrature::PerTile(4, 24), p);
  EXPECT_GT(r.neumann_edges, 0);
  EXPECT_LE(r.errors->l2, 1e-10);
}

// Thesis §4.2.2 (ii): -Δu = π²(5 cos(πx) - 4) sin(2πy), u = (cos(πx) - 1) sin(2πy), Dirichlet on x = 0,
// y = 0, y = 1, homogeneous Neumann on x = 1. Measured fitted rates on square_evs.obj, refinements 1..4:
// L2 2.44, H1 1.53 — below the bicubic 4 and 3. The same problem on a regular 6 × 6 net without any EV
// gives the same 2.5 and 1.5: u has a non-zero second normal derivative on the boundary, while every
// Catmull–Clark function with the boundary rule (phantom 2 P_b - P_in) has a zero one there, an O(h²) error
// in a boundary strip of width h. u = sin(πx) sin(πy) has zero second normal derivatives on the boundary:
// on the regular net it converges at 4.0 and 3.0, on square_evs.obj at 2.4 and 1.6 (the EVs: the
// interior ones alone give 2.4 / 1.6, the boundary EV alone 2.6 / 1.5). These are the asserted floors.
TEST(CatmullClarkPoisson, ThesisPoissonBenchmarkRates) {
  const basis::Geometry coarse = basis::catmull_clark::make_catmull_clark_geometry(net("square_evs.obj"));
  const fem::PoissonProblem p = benchmark_ii();
  std::vector<double> l2, h1;
  for (int level = 1; level <= 3; ++level) {
    const basis::Geometry g = refine::refine_uniform(coarse, level).geometry;
    const fem::PoissonResult r = fem::solve_poisson(g, quadrature::PerTile(4, 12), p);
    l2.push_back(r.errors->l2);
    h1.push_back(r.errors->h1);
  }
  std::cout << "L2 rate " << fitted_rate(l2) << ", H1 rate " << fitted_rate(h1) << "\n";
  EXPECT_GE(fitted_rate(l2), 2.3);
  EXPECT_GE(fitted_rate(h1), 1.4);
}

namespace {
// d_l = ||P u_l − u_{l+1}||_L2 on level l + 1 for levels 1..4 of `coarse` (P the exact prolongation; one level at a
// time, so the nets are numbered consistently).
// d_l = ||P u_l − u_{l+1}||_L2 for l = first .. last − 1.
std::vector<double> self_convergence(const basis::Geometry& coarse, const fem::PoissonProblem& p,
                                     const quadrature::RuleProvider& rules, int first = 1, int last = 4) {
  std::vector<double> diffs;
  Eigen::VectorXd previous;
  basis::Geometry g = refine::refine_uniform(coarse, first).geometry;
  for (int level = first; level <= last; ++level) {
    Eigen::SparseMatrix<double> prolongation;
    if (level > first) {
      refine::Refinement step = refine::refine_uniform(g, 1);
      g = step.geometry;
      prolongation = step.prolongation;
    }
    const fem::PoissonResult r = fem::solve_poisson(g, rules, p);
    if (level > first) {
      const Eigen::VectorXd e = prolongation * previous - r.u;
      const fem::MassForm mass;
      const std::vector<const fem::BilinearForm*> bm{&mass};
      Eigen::SparseMatrix<double> m;
      Eigen::VectorXd unused;
      fem::Assembler(g, rules).assemble(bm, {}, m, unused);
      diffs.push_back(std::sqrt(e.dot(m * e)));
    }
    previous = r.u;
  }
  return diffs;
}
}  // namespace

// Laplace–Beltrami -Δ_Γ u + u = f on the closed cube net: self-convergence under uniform refinement,
// d_l = ||P u_l - u_{l+1}||_L2 on level l+1 (P the exact prolongation), rate log2(d_l / d_{l+1}) >= 2.
TEST(CatmullClarkPoisson, LaplaceBeltramiOnClosedSurfaceSelfConverges) {
  const basis::Geometry coarse = basis::catmull_clark::make_catmull_clark_geometry(net("cube.obj"));
  ASSERT_EQ(coarse.dim(), 3);
  fem::PoissonProblem p;
  p.source = std::make_shared<fem::Expression>("x + y*z + 1", "--source");
  p.reaction = 1.0;
  const std::vector<double> diffs = self_convergence(coarse, p, quadrature::PerTile(4, 8));
  for (std::size_t k = 0; k + 1 < diffs.size(); ++k) {
    const double rate = std::log2(diffs[k] / diffs[k + 1]);
    std::cout << "self-convergence rate " << rate << "\n";
    EXPECT_GE(rate, 2.0);
  }
  // Without reaction and without the mean-zero constraint the closed-surface problem is refused.
  p.reaction = 0.0;
  try {
    fem::solve_poisson(coarse, quadrature::PerTile(4, 4), p);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("closed surface"), std::string::npos);
  }
  // With it, the solution has mean zero (∫f = 17.2 ≠ 0: the defect is removed on request, refused otherwise).
  p.mean_zero = true;
  p.remove_incompatible = true;
  const fem::PoissonResult r = fem::solve_poisson(coarse, quadrature::PerTile(4, 6), p);
  EXPECT_TRUE(r.mean_zero);
}

namespace {


basis::Geometry clamped(const mesh::PolyMesh& m) {
  return basis::catmull_clark::make_catmull_clark_geometry(m, "net", basis::catmull_clark::BoundaryRule::kClamped);
}


// u = sin(πx) sin(πy) + x y², all Dirichlet (the benchmark of issue 16).
fem::PoissonProblem sine_plus_cubic() {
  fem::PoissonProblem p;
  p.source = std::make_shared<fem::Expression>("2*pi^2*sin(pi*x)*sin(pi*y) - 2*x", "--source");
  p.exact = std::make_shared<fem::Expression>("sin(pi*x)*sin(pi*y) + x*y^2", "--exact");
  p.dirichlet = p.exact;
  return p;
}

struct Rates {
  double l2, h1;
};

Rates rates(const basis::Geometry& coarse, const fem::PoissonProblem& p, int first, int last,
            const quadrature::RuleProvider& rules) {
  std::vector<double> l2, h1;
  for (int level = first; level <= last; ++level) {
    const fem::PoissonResult r = fem::solve_poisson(refine::refine_uniform(coarse, level).geometry, rules, p);
    l2.push_back(r.errors->l2);
    h1.push_back(r.errors->h1);
  }
  return {fitted_rate(l2), fitted_rate(h1)};
}

}  // namespace


// The clamped boundary reproduces quadratics up to the boundary (they are in the open-knot space): u = x² − y²
// (harmonic) with its Dirichlet data is solved exactly on a regular net; the natural rule cannot (u_nn = 2 ≠ 0
// on x = 0, 1). The affine patch test holds with interior EVs next to the boundary (closed fans of valence 3, 5,
// 6 whose EV faces reach it, and with 2 × 2 sectors) and after a global step (a net with triangles).
TEST(CatmullClarkPoisson, ClampedBoundaryReproducesQuadratics) {
  fem::PoissonProblem p;
  p.exact = std::make_shared<fem::Expression>("x^2 - y^2", "--exact");
  p.dirichlet = p.exact;
  const fem::PoissonResult c = fem::solve_poisson(clamped(square_grid(3)), quadrature::Gauss(4), p);
  EXPECT_LE(c.errors->l2 / c.errors->l2_exact, 1e-10);
  EXPECT_LE(c.errors->h1 / c.errors->h1_exact, 1e-10);
  const fem::PoissonResult n =
      fem::solve_poisson(basis::catmull_clark::make_catmull_clark_geometry(square_grid(3)), quadrature::Gauss(4), p);
  EXPECT_GE(n.errors->l2 / n.errors->l2_exact, 1e-4);
  p.exact = std::make_shared<fem::Expression>("1 - x + 2*y", "--exact");
  p.dirichlet = p.exact;
  std::vector<std::pair<std::string, mesh::PolyMesh>> nets;
  for (int n : {3, 5, 6}) {
    nets.emplace_back("closed fan " + std::to_string(n) + ", 1 x 1", closed_fan(n, 1));
    nets.emplace_back("closed fan " + std::to_string(n) + ", 2 x 2", closed_fan(n, 2));
  }
  mesh::PolyMesh g = square_grid(4);
  std::vector<std::vector<Index>> faces;
  for (Index f = 0; f < g.num_faces(); ++f) {
    const auto v = g.face(f);
    if (f == 5) {
      faces.push_back({v[0], v[1], v[2]});
      faces.push_back({v[0], v[2], v[3]});
    } else {
      faces.emplace_back(v.begin(), v.end());
    }
  }
  nets.emplace_back("grid with two triangles", mesh::PolyMesh::build(g.points(), faces));
  for (const auto& [name, m] : nets) {
    const fem::PoissonResult e = fem::solve_poisson(clamped(m), quadrature::PerTile(4, 24), p);
    EXPECT_LE(e.errors->l2 / e.errors->l2_exact, 1e-10) << name;
    EXPECT_LE(e.errors->h1 / e.errors->h1_exact, 1e-10) << name;
  }
}

// Where the clamped traces are independent only at ever smaller scales (boundary EVs; measured on
// square_evs.obj, pivot ratio 9.4e7 of the scaled boundary mass matrix against at most 7.3e3 elsewhere) strong
// Dirichlet conditions would be wrong (an affine solution came out 4e-3 wrong): refused with one line instead.
TEST(CatmullClarkPoisson, ClampedDirichletAtBoundaryEVsIsRefused) {
  fem::PoissonProblem p;
  p.exact = std::make_shared<fem::Expression>("1 - x + 2*y", "--exact");
  p.dirichlet = p.exact;
  try {
    fem::solve_poisson(clamped(net("square_evs.obj")), quadrature::PerTile(4, 24), p);
    FAIL() << "no error";
  } catch (const NumericalError& e) {
    EXPECT_NE(std::string(e.what()).find("nearly dependent"), std::string::npos) << e.what();
  }
}

// Full order on a regular net with u_nn ≠ 0 on the boundary (benchmark (ii), Dirichlet and Neumann parts):
// the natural rule gives 2.5 / 1.5 (ThesisPoissonBenchmarkRates), the clamped one the bicubic 4 / 3.
TEST(CatmullClarkPoisson, ClampedBoundaryRatesOnARegularNet) {
  const Rates r = rates(clamped(square_grid(4)), benchmark_ii(), 1, 4, quadrature::Gauss(4));
  std::cout << "clamped, regular 4x4 net, benchmark (ii): L2 rate " << r.l2 << ", H1 rate " << r.h1 << "\n";
  EXPECT_GE(r.l2, 3.8);
  EXPECT_GE(r.h1, 2.8);
}

// With Nitsche's method (no trace space needed) the clamped boundary takes boundary EVs: the affine patch test
// on square_evs.obj (a boundary EV with 3 faces, interior EVs, a straight-angle corner at (1/3, 0)) and the
// L-shape (reflex corner with 3 faces), and the rates of u = sin πx sin πy + x y² and of benchmark (ii) on
// square_evs.obj, levels 1..3. Measured: L2 2.43 / H1 1.63 and (ii) L2 2.41 / H1 1.52 (natural rule with
// Nitsche: 2.47 / 1.55): the interior EVs limit both rules here; asserted as floors.
TEST(CatmullClarkPoisson, ClampedBoundaryWithNitscheAtBoundaryEVs) {
  fem::PoissonProblem p;
  p.exact = std::make_shared<fem::Expression>("1 - x + 2*y", "--exact");
  p.dirichlet = p.exact;
  p.dirichlet_method = fem::DirichletMethod::kNitsche;
  for (const char* name : {"square_evs.obj", "l_shape.obj"}) {
    const fem::PoissonResult e = fem::solve_poisson(clamped(net(name)), quadrature::PerTile(4, 24), p);
    EXPECT_LE(e.errors->l2 / e.errors->l2_exact, 1e-10) << name;
    EXPECT_LE(e.errors->h1 / e.errors->h1_exact, 1e-9) << name;
  }
  fem::PoissonProblem a = sine_plus_cubic(), b = benchmark_ii();
  a.dirichlet_method = b.dirichlet_method = fem::DirichletMethod::kNitsche;
  const basis::Geometry g = clamped(net("square_evs.obj"));
  const Rates ra = rates(g, a, 1, 3, quadrature::PerTile(4, 8)), rb = rates(g, b, 1, 3, quadrature::PerTile(4, 8));
  std::cout << "clamped + Nitsche, square_evs: sine + x y^2 L2 " << ra.l2 << " H1 " << ra.h1 << "; (ii) L2 " << rb.l2
            << " H1 " << rb.h1 << "\n";
  EXPECT_GE(ra.l2, 2.3);
  EXPECT_GE(ra.h1, 1.5);
  EXPECT_GE(rb.l2, 2.3);
  EXPECT_GE(rb.h1, 1.4);
}

// The EV remedy on square_evs.obj (after its global step: interior EVs of valence 5 (three) and 6, one of valence
// 3 that keeps full order unenriched, and the boundary EV with 3 faces, valence 5 once extended): the clamped
// boundary, Nitsche, and --cc-enrich quadratic at those five; rates of u = sin πx sin πy + x y² and benchmark (ii),
// tiles:4:8. The full form (label slow, 25 s) fits over levels 2..4 and has the patch test at levels 1 and 3; the
// quick form (the default run) fits over levels 1..3 and has the patch test at level 1.
// Measured (2026-12-02), levels 2..4: L2 3.72 / H1 2.67 and (ii) L2 3.50 / H1 2.76 (without the enrichment: 2.43 /
// 1.63 and 2.41 / 1.52, above); asserted with floors 0.1 below. Levels 1..3 (measured 2026-12-04): L2 2.82 / H1
// 2.02 and (ii) L2 3.27 / H1 2.49, still before the asymptotic range; asserted with floors 0.1 below. The quick form
// is a regression check of these rates; the gain of the enrichment is asserted by the full form (and, in the
// default run, on the planar fans of CatmullClarkEvRates.QuadraticEnrichmentRestoresTheRates).
namespace {
struct EnrichedRates {
  Rates a, b;
};
EnrichedRates enriched_square_evs(int first, int last, const std::vector<int>& patch_levels) {
  fem::PoissonProblem a = sine_plus_cubic(), b = benchmark_ii();
  a.dirichlet_method = b.dirichlet_method = fem::DirichletMethod::kNitsche;
  const basis::Geometry plain = clamped(net("square_evs.obj"));
  const auto centres = basis::catmull_clark::extraordinary_centres(plain);
  EXPECT_EQ(centres.size(), 5u);  // after the net's global step: four interior valence-5/6 EVs and the boundary EV
  const basis::Geometry g = basis::catmull_clark::enriched_geometry(plain, centres);
  // The space contains the linear functions; the patch test holds up to the quadrature of the enrichment
  // functions, which are not polynomial on the elements (measured with tiles:8:12: 6.7e-10 at level 1,
  // 5.6e-11 at level 3; tiles:4:12: 2.6e-7 and 1.4e-10).
  fem::PoissonProblem affine;
  affine.exact = std::make_shared<fem::Expression>("1 + x - 2*y", "--exact");
  affine.dirichlet = affine.exact;
  affine.dirichlet_method = fem::DirichletMethod::kNitsche;
  for (int level : patch_levels) {
    const fem::PoissonResult e = fem::solve_poisson(refine::refine_uniform(g, level).geometry, quadrature::PerTile(8, 12), affine);
    EXPECT_LE(e.errors->l2 / e.errors->l2_exact, level == 1 ? 1e-9 : 1e-10) << level;
  }
  const EnrichedRates r{rates(g, a, first, last, quadrature::PerTile(4, 8)),
                        rates(g, b, first, last, quadrature::PerTile(4, 8))};
  std::cout << "clamped + Nitsche + enriched, square_evs, levels " << first << ".." << last << ": sine + x y^2 L2 "
            << r.a.l2 << " H1 " << r.a.h1 << "; (ii) L2 " << r.b.l2 << " H1 " << r.b.h1 << "\n";
  return r;
}
}  // namespace

TEST(CatmullClarkPoissonSlow, EnrichedExtraordinaryVerticesOnSquareEvs) {
  const EnrichedRates r = enriched_square_evs(2, 4, {1, 3});
  EXPECT_GE(r.a.l2, 3.6);
  EXPECT_GE(r.a.h1, 2.55);
  EXPECT_GE(r.b.l2, 3.4);
  EXPECT_GE(r.b.h1, 2.65);
}

TEST(CatmullClarkPoisson, EnrichedExtraordinaryVerticesOnSquareEvsQuick) {
  const EnrichedRates r = enriched_square_evs(1, 3, {1});
  EXPECT_GE(r.a.l2, 2.7);
  EXPECT_GE(r.a.h1, 1.9);
  EXPECT_GE(r.b.l2, 3.15);
  EXPECT_GE(r.b.h1, 2.4);
}

// Laplace–Beltrami on a closed surface with EVs, before and after the EV remedy: torus_evs.obj (EVs of valence 3
// and 5), −Δ_Γ u + u = x + y z + 1, self-convergence d_l = ||P u_l − u_{l+1}||_L2 (tiles:4:8); the enrichment uses
// the EVs' tangent planes (the four of valence 5; valence 3 gets none). The full form (label slow, 44 s) takes
// levels 1..4; measured (2026-12-02): the last two rates 2.91, 2.76 without and 2.77, 3.70 with the enrichment;
// asserted: the last one >= 2.6 and >= 3.5. The quick form (the default run) takes levels 0..3; measured
// (2026-12-04): 3.24, 2.91 without and 3.39, 2.77 with the enrichment, so the enrichment's gain does not show yet
// at these levels; asserted: both last rates 0.1 below the measured ones (a regression check of the convergence
// on a closed surface with EVs; the gain is asserted by the full form).
namespace {
std::pair<std::pair<double, double>, std::pair<double, double>> torus_rates(int first, int last) {
  const basis::Geometry plain = basis::catmull_clark::make_catmull_clark_geometry(net("torus_evs.obj"));
  const auto centres = basis::catmull_clark::extraordinary_centres(plain);
  EXPECT_FALSE(centres.empty());
  fem::PoissonProblem p;
  p.source = std::make_shared<fem::Expression>("x + y*z + 1", "--source");
  p.reaction = 1.0;
  const quadrature::PerTile rules(4, 8);
  auto self_rates = [&](const basis::Geometry& coarse) {
    const std::vector<double> d = self_convergence(coarse, p, rules, first, last);
    return std::make_pair(std::log2(d[0] / d[1]), std::log2(d[1] / d[2]));
  };
  const auto before = self_rates(plain);
  const auto after = self_rates(basis::catmull_clark::enriched_geometry(plain, centres));
  std::cout << "torus_evs Laplace-Beltrami self-convergence rates, levels " << first << ".." << last << ": plain "
            << before.first << ", " << before.second << "; enriched (" << centres.size() << " EVs) " << after.first
            << ", " << after.second << "\n";
  return {before, after};
}
}  // namespace

TEST(CatmullClarkPoissonSlow, LaplaceBeltramiOnTorusBeforeAndAfterEnrichment) {
  const auto [before, after] = torus_rates(1, 4);
  EXPECT_GE(before.second, 2.6);
  EXPECT_GE(after.second, 3.5);
}

TEST(CatmullClarkPoisson, LaplaceBeltramiOnTorusBeforeAndAfterEnrichmentQuick) {
  const auto [before, after] = torus_rates(0, 3);
  EXPECT_GE(before.second, 2.8);
  EXPECT_GE(after.second, 2.65);
}

// The clamped boundary EV is an interior vertex of the extended net but its ring of elements is open in the
// domain: its elements say kind.boundary, so the folded macro rules (exact only summed over a closed ring) give
// way to per-tile rules there, and their sides follow the tiles. Affine patch test with Nitsche on
// square_evs.obj: macro:2:8 1.04e-9 as tiles:4:8 (before: 3.2e-7 with Gauss sides, 1.4e-6 with the folded rule).
TEST(CatmullClarkPoisson, ClampedBoundaryEVsGetTiledRules) {
  const basis::Geometry g = clamped(net("square_evs.obj"));
  int boundary_evs = 0;
  for (Index e = 0; e < g.space().num_elements(); ++e) boundary_evs += g.space().kind(e).boundary ? 1 : 0;
  EXPECT_EQ(boundary_evs, 3);  // the boundary EV at (1/2, 0) and its 3 faces
  fem::PoissonProblem p;
  p.exact = std::make_shared<fem::Expression>("1 - x", "--exact");
  p.dirichlet = p.exact;
  p.dirichlet_method = fem::DirichletMethod::kNitsche;
  const double tiles = fem::solve_poisson(g, quadrature::PerTile(4, 8), p).errors->l2;
  const double macro = fem::solve_poisson(g, quadrature::spline_gauss::MacroPatch(2, 8), p).errors->l2;
  EXPECT_LE(tiles, 2e-9);
  EXPECT_LE(macro, 2e-9);
}
