// The quadratic enrichment at extraordinary vertices (basis/catmull_clark/ev_enrichment.hpp): its functions
// are the cutoff quadratics of the physical point, written here independently from the formula; their
// parametric derivatives agree with central differences; refinement keeps them (nested); bad requests are
// named. The rates it buys are in tests/fem/test_cc_ev_rates.cpp and test_cc_poisson.cpp.
#include <gtest/gtest.h>

#include <cmath>

#include "basis/catmull_clark/ev_enrichment.hpp"
#include "basis/catmull_clark/space.hpp"
#include "basis/registry.hpp"
#include "core/error.hpp"
#include "fem/assembler.hpp"
#include "fem/expression.hpp"
#include "fem/forms.hpp"
#include "fem/threads.hpp"
#include "mesh/obj_reader.hpp"
#include "quadrature/per_tile.hpp"
#include "refine/uniform.hpp"
#include "support/nets.hpp"

using namespace iga;
using basis::catmull_clark::BoundaryRule;
using basis::catmull_clark::EnrichedSpace;

namespace {

basis::Geometry enriched_fan(int n) {
  const basis::Geometry g = basis::catmull_clark::make_catmull_clark_geometry(iga::test::closed_fan(n, 2, 0.5), "fan",
                                                                              BoundaryRule::kClamped);
  return basis::catmull_clark::enriched_geometry(g, basis::catmull_clark::extraordinary_centres(g));
}

Eigen::Matrix2Xd sample_points() {
  Eigen::Matrix2Xd p(2, 4);
  p << 0.3, 0.7, 0.05, 0.45, 0.6, 0.2, 0.1, 0.9;
  return p;
}

}  // namespace

// One centre per EV at its limit point (the origin of the fan), three functions (none at valence 3, which
// keeps full order); every element of the fan's EV ring has them, their values are (1 − r²/ρ²)⁸ times x², x y, y² over ρ² (planar frame), 1e-14.
TEST(CatmullClarkEnrichment, FunctionsAreCutoffQuadraticsOfThePhysicalPoint) {
  EXPECT_TRUE(dynamic_cast<const EnrichedSpace&>(enriched_fan(3).space()).centres().empty());
  for (int n : {5, 6, 8}) {
    const basis::Geometry g = enriched_fan(n);
    const auto& space = dynamic_cast<const EnrichedSpace&>(g.space());
    ASSERT_EQ(space.centres().size(), 1u) << n;
    const auto& c = space.centres()[0];
    EXPECT_EQ(c.valence, n);
    EXPECT_LE(c.point.norm(), 1e-14) << n;
    EXPECT_GT(c.radius, 0.1) << n;
    EXPECT_LT(c.radius, 0.5) << n;
    EXPECT_EQ(space.num_dofs(), space.base()->num_dofs() + 3);
    const Eigen::Matrix2Xd pts = sample_points();
    basis::BasisValues b, base;
    basis::GeometryValues gv;
    int enriched = 0;
    for (Index e = 0; e < space.num_elements(); ++e) {
      const auto dofs = space.dofs(e);
      const Index nb = static_cast<Index>(space.base()->dofs(e).size());
      space.evaluate(e, pts, 2, b);
      space.base()->evaluate(e, pts, 2, base);
      EXPECT_EQ((b.value.topRows(nb) - base.value).cwiseAbs().maxCoeff(), 0.0);
      EXPECT_EQ((b.duv.topRows(nb) - base.duv).cwiseAbs().maxCoeff(), 0.0);
      if (static_cast<Index>(dofs.size()) == nb) continue;
      ++enriched;
      ASSERT_EQ(static_cast<Index>(dofs.size()), nb + 3);
      EXPECT_EQ(dofs[static_cast<std::size_t>(nb)], space.base()->num_dofs());
      g.evaluate(e, b, gv);
      for (Index q = 0; q < pts.cols(); ++q) {
        const double x = gv.x(0, q) / c.radius, y = gv.x(1, q) / c.radius;
        const double t = x * x + y * y, chi = t < 1 ? std::pow(1 - t, 8) : 0.0;
        EXPECT_NEAR(b.value(nb, q), chi * x * x, 1e-14);
        EXPECT_NEAR(b.value(nb + 1, q), chi * x * y, 1e-14);
        EXPECT_NEAR(b.value(nb + 2, q), chi * y * y, 1e-14);
      }
    }
    EXPECT_GE(enriched, n) << n;  // at least the EV's ring
  }
}

// First and second parametric derivatives of the enrichment rows against central differences of the values
// and of the first derivatives (step 1e-5), on elements of the EV ring and next to it: relative 1e-6.
TEST(CatmullClarkEnrichment, DerivativesAgreeWithCentralDifferences) {
  const basis::Geometry g = enriched_fan(5);
  const basis::Space& space = g.space();
  const Eigen::Matrix2Xd pts = sample_points();
  const double h = 1e-5;
  basis::BasisValues b, plus, minus;
  double worst1 = 0, worst2 = 0, scale1 = 0, scale2 = 0;
  for (Index e = 0; e < space.num_elements(); ++e) {
    const Index nb = static_cast<Index>(dynamic_cast<const EnrichedSpace&>(space).base()->dofs(e).size());
    const Index n = static_cast<Index>(space.dofs(e).size());
    if (n == nb) continue;
    space.evaluate(e, pts, 2, b);
    for (int dir = 0; dir < 2; ++dir) {
      Eigen::Matrix2Xd pp = pts, pm = pts;
      pp.row(dir).array() += h;
      pm.row(dir).array() -= h;
      space.evaluate(e, pp, 1, plus);
      space.evaluate(e, pm, 1, minus);
      const Eigen::MatrixXd d1 = ((plus.value - minus.value) / (2 * h)).bottomRows(n - nb);
      const Eigen::MatrixXd& exact1 = dir == 0 ? b.du : b.dv;
      worst1 = std::max(worst1, (d1 - exact1.bottomRows(n - nb)).cwiseAbs().maxCoeff());
      scale1 = std::max(scale1, exact1.bottomRows(n - nb).cwiseAbs().maxCoeff());
      const Eigen::MatrixXd du = ((plus.du - minus.du) / (2 * h)).bottomRows(n - nb);
      const Eigen::MatrixXd dv = ((plus.dv - minus.dv) / (2 * h)).bottomRows(n - nb);
      const Eigen::MatrixXd& exact_u = dir == 0 ? b.duu : b.duv;  // d/d(dir) of du
      const Eigen::MatrixXd& exact_v = dir == 0 ? b.duv : b.dvv;  // d/d(dir) of dv
      worst2 = std::max({worst2, (du - exact_u.bottomRows(n - nb)).cwiseAbs().maxCoeff(),
                         (dv - exact_v.bottomRows(n - nb)).cwiseAbs().maxCoeff()});
      scale2 = std::max({scale2, exact_u.bottomRows(n - nb).cwiseAbs().maxCoeff(), exact_v.bottomRows(n - nb).cwiseAbs().maxCoeff()});
    }
  }
  ASSERT_GT(scale1, 0.0);
  ASSERT_GT(scale2, 0.0);
  EXPECT_LE(worst1, 1e-6 * scale1);
  EXPECT_LE(worst2, 1e-6 * scale2);
}

// Uniform refinement keeps the centres and functions: the prolongation is the base's with the identity on the
// enrichment dofs (the same centre and radius: the same functions of the physical point), and the map is
// unchanged (fine control points = P × coarse ones, enrichment rows zero). The base part's nestedness is
// test_cc_refine's and test_cc_clamped's.
TEST(CatmullClarkEnrichment, RefinementIsNested) {
  const basis::Geometry coarse = enriched_fan(6);
  const auto r = refine::refine_uniform(coarse, 1);
  const auto* fine = dynamic_cast<const EnrichedSpace*>(&r.geometry.space());
  ASSERT_NE(fine, nullptr);
  const auto& cs = dynamic_cast<const EnrichedSpace&>(coarse.space());
  ASSERT_EQ(fine->centres().size(), 1u);
  EXPECT_EQ(fine->centres()[0].radius, cs.centres()[0].radius);
  const Index nbf = fine->base()->num_dofs(), nbc = cs.base()->num_dofs();
  ASSERT_EQ(r.prolongation.rows(), nbf + 3);
  ASSERT_EQ(r.prolongation.cols(), nbc + 3);
  const Eigen::MatrixXd p = Eigen::MatrixXd(r.prolongation);
  EXPECT_EQ((p.bottomRightCorner(3, 3) - Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff(), 0.0);
  EXPECT_EQ(p.bottomLeftCorner(3, nbc).cwiseAbs().maxCoeff(), 0.0);
  EXPECT_EQ(p.topRightCorner(nbf, 3).cwiseAbs().maxCoeff(), 0.0);
  EXPECT_LE((r.geometry.control_points() - r.prolongation * coarse.control_points()).cwiseAbs().maxCoeff(), 1e-14);
  EXPECT_EQ(r.geometry.control_points().bottomRows(3).cwiseAbs().maxCoeff(), 0.0);
}

// Bad requests are named: an unknown --cc-enrich word, enriching twice, local refinement of an enriched space.
TEST(CatmullClarkEnrichment, BadRequestsAreNamed) {
  try {
    basis::catmull_clark::enrichment_option("cubic");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), "--cc-enrich 'cubic': expected none or quadratic");
  }
  const basis::Geometry g = enriched_fan(5);
  EXPECT_THROW(basis::catmull_clark::extraordinary_centres(g), InputError);
  const std::vector<Index> marked{0};
  basis::BackendFacts facts;
  try {
    basis::refine_marked(g, marked, 0, facts);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), "--cc-enrich quadratic with local refinement (--adaptive, --grade-evs): the enriched space has no "
                                     "hierarchical form; use uniform refinement (--refine)");
  }
}

// The registry builds it from the option and reports the count; a net without EVs gets a note and no functions;
// uniform refinement through the registry keeps it.
TEST(CatmullClarkEnrichment, BackendOption) {
  const basis::Backend& cc = basis::backend("cc");
  basis::BackendOptions o;
  o.cc_boundary = "clamped";
  o.cc_enrich = "quadratic";
  basis::BackendFacts facts;
  const mesh::PolyMesh fan = iga::test::closed_fan(5, 2, 0.5);
  const basis::Refinement r = basis::make_refined_geometry(cc, &fan, o, 2, facts);
  EXPECT_EQ(facts.counts.at("cc_enriched_vertices"), 1);
  const auto* en = dynamic_cast<const EnrichedSpace*>(&r.geometry.space());
  ASSERT_NE(en, nullptr);
  EXPECT_EQ(en->num_dofs(), en->base()->num_dofs() + 3);
  basis::BackendFacts plain;
  const mesh::PolyMesh grid = iga::test::square_grid(3);
  const basis::Geometry g = basis::make_geometry(cc, &grid, o, plain);
  EXPECT_EQ(plain.counts.at("cc_enriched_vertices"), 0);
  ASSERT_EQ(plain.notes.size(), 1u);
  EXPECT_EQ(plain.notes[0], "--cc-enrich quadratic: the net has no extraordinary vertex, nothing to enrich");
  EXPECT_EQ(g.space().num_dofs(), dynamic_cast<const EnrichedSpace&>(g.space()).base()->num_dofs());
}

// Enrichment dofs touch every element of their disc (thousands after a few refinements): the assembly plan
// calls them dense and leaves them out of the colouring (else one colour per disc element), and the assembler
// adds their mutual entries after each colour. Checked against a plain triplet assembly of the same element
// matrices (1e-13 relative), the colour count against the plain space's, and bitwise equality for 1 and 2
// threads.
TEST(CatmullClarkEnrichment, DenseDofsAreAssembledExactlyAndReproducibly) {
  const basis::Geometry g = refine::refine_uniform(enriched_fan(5), 3).geometry;
  const quadrature::PerTile rules(4, 8);
  const fem::Assembler assembler(g, rules);
  const fem::AssemblyPlan& plan = assembler.plan();
  const Index nb = dynamic_cast<const EnrichedSpace&>(g.space()).base()->num_dofs();
  for (Index d = 0; d < g.space().num_dofs(); ++d) EXPECT_EQ(plan.dense[static_cast<std::size_t>(d)] != 0, d >= nb) << d;
  const basis::Geometry plain_geometry = refine::refine_uniform(
      basis::catmull_clark::make_catmull_clark_geometry(iga::test::closed_fan(5, 2, 0.5), "fan", BoundaryRule::kClamped), 3).geometry;
  const fem::Assembler plain(plain_geometry, rules);
  EXPECT_EQ(plan.colors.size(), plain.plan().colors.size());
  const fem::StiffnessForm k;
  const fem::SourceForm load(std::make_shared<fem::Expression>("1 + x*y", "--source"));
  const std::vector<const fem::BilinearForm*> bf{&k};
  const std::vector<const fem::LinearForm*> lf{&load};
  Eigen::SparseMatrix<double> a1, a2;
  Eigen::VectorXd b1, b2;
  const int threads = fem::num_threads();
  fem::set_num_threads(1);
  assembler.assemble(bf, lf, a1, b1);
  fem::set_num_threads(2);
  assembler.assemble(bf, lf, a2, b2);
  fem::set_num_threads(threads);
  EXPECT_EQ((a1 - a2).cwiseAbs().sum(), 0.0);
  EXPECT_EQ((b1 - b2).cwiseAbs().sum(), 0.0);
  std::vector<Eigen::Triplet<double>> t;
  Eigen::VectorXd b = Eigen::VectorXd::Zero(g.space().num_dofs());
  fem::ElementContext ctx;
  for (Index e = 0; e < g.space().num_elements(); ++e) {
    assembler.prepare(e, ctx);
    const auto dofs = g.space().dofs(e);
    const Index n = static_cast<Index>(dofs.size());
    Eigen::MatrixXd m = Eigen::MatrixXd::Zero(n, n);
    Eigen::VectorXd f = Eigen::VectorXd::Zero(n);
    k.add(ctx, m);
    load.add(ctx, f);
    for (Index i = 0; i < n; ++i) {
      b(dofs[static_cast<std::size_t>(i)]) += f(i);
      for (Index j = 0; j < n; ++j) t.emplace_back(dofs[static_cast<std::size_t>(i)], dofs[static_cast<std::size_t>(j)], m(i, j));
    }
  }
  Eigen::SparseMatrix<double> ref(g.space().num_dofs(), g.space().num_dofs());
  ref.setFromTriplets(t.begin(), t.end());
  const double scale = Eigen::MatrixXd(ref).cwiseAbs().maxCoeff();
  EXPECT_LE(Eigen::MatrixXd(a1 - ref).cwiseAbs().maxCoeff(), 1e-13 * scale);
  EXPECT_LE((b1 - b).cwiseAbs().maxCoeff(), 1e-13 * b.cwiseAbs().maxCoeff());
  EXPECT_GT(Eigen::MatrixXd(ref).bottomRightCorner(3, 3).cwiseAbs().minCoeff(), 0.0);
}
