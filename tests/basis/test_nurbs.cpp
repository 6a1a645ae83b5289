// NURBS patches: the rational basis against its definition (Cox–de Boor B-splines, weights, the quotient), exact
// circles, refinement with weights, and the JSON patch format (round trip and refusals).
#include "support/paths.hpp"
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include "basis/bspline/patch_file.hpp"
#include "basis/bspline/patches.hpp"
#include "basis/bspline/rational_space.hpp"
#include "basis/registry.hpp"
#include "core/error.hpp"
#include "refine/uniform.hpp"

using namespace iga;
using namespace iga::basis::bspline;

namespace {

// A NURBS patch of degrees (2, 3) with an interior knot in each direction and random weights in [0.3, 3].
basis::Geometry random_patch(unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> w(0.3, 3.0), x(-0.2, 0.2);
  KnotVector u(2, {0, 0, 0, 0.4, 1, 1, 1}), v(3, {0, 0, 0, 0, 0.7, 1, 1, 1, 1});
  const Index nu = u.num_basis(), nv = v.num_basis();
  Eigen::MatrixXd cp(nu * nv, 2);
  Eigen::VectorXd weights(nu * nv);
  for (Index j = 0; j < nv; ++j) {
    for (Index i = 0; i < nu; ++i) {
      cp.row(i + nu * j) << static_cast<double>(i) + x(rng), static_cast<double>(j) + x(rng);
      weights(i + nu * j) = w(rng);
    }
  }
  return make_rational_patch(std::move(u), std::move(v), cp, weights);
}

// The element containing knot-parameter (x, y) and its reference point.
std::pair<Index, Eigen::Vector2d> locate(const TensorSpace& s, double x, double y) {
  for (Index e = 0; e < s.num_elements(); ++e) {
    const Eigen::Vector4d b = s.element_box(e);
    if (x >= b(0) && x <= b(1) && y >= b(2) && y <= b(3)) {
      return {e, Eigen::Vector2d((x - b(0)) / (b(1) - b(0)), (y - b(2)) / (b(3) - b(2)))};
    }
  }
  ADD_FAILURE() << "no element holds (" << x << ", " << y << ")";
  return {0, Eigen::Vector2d::Zero()};
}

// R_i(x, y) for every function of the patch, from the definition: Cox–de Boor values of N_i, then w_i N_i / W.
Eigen::VectorXd rational_by_definition(const RationalSpace& s, double x, double y) {
  const KnotVector &ku = s.base().knots_u(), &kv = s.base().knots_v();
  const Index su = ku.span(x), sv = kv.span(y);
  const Eigen::MatrixXd nu = basis_functions(ku, su, x, 0), nv = basis_functions(kv, sv, y, 0);
  Eigen::VectorXd r = Eigen::VectorXd::Zero(s.num_dofs());
  for (int b = 0; b <= kv.degree(); ++b) {
    for (int a = 0; a <= ku.degree(); ++a) {
      const Index i = (su - ku.degree() + a) + s.base().num_basis_u() * (sv - kv.degree() + b);
      r(i) = s.weights()(i) * nu(0, a) * nv(0, b);
    }
  }
  return r / r.sum();
}

Eigen::Vector3d map_point(const basis::Geometry& g, double x, double y) {
  const RationalSpace& s = *rational_space(g.space());
  const auto [e, ref] = locate(s.base(), x, y);
  basis::GeometryValues gv;
  g.evaluate(e, Eigen::Matrix2Xd(ref), gv);
  return gv.x.col(0);
}

}  // namespace

// Values against the definition at random points (1e-14); first and second derivatives against central
// differences of the values with step h = 1e-5 of the element (truncation h²/6 times the third derivative, which
// random weights make large: at h = 1e-4 the v derivatives of the cubic direction were 5e-6 off; rounding
// ε/h ≈ 1e-11 for the first, ε/h² ≈ 1e-6 for the second derivatives); the functions sum to 1 and their
// derivatives to 0.
TEST(Nurbs, RationalBasisMatchesItsDefinition) {
  const basis::Geometry g = random_patch(3);
  const RationalSpace& s = *rational_space(g.space());
  EXPECT_EQ(s.name(), "bspline");
  EXPECT_EQ(s.polynomial_degree(0), std::nullopt);
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u01(0.02, 0.98);
  const double h = 1e-5;
  for (int k = 0; k < 40; ++k) {
    const Index e = static_cast<Index>(rng() % static_cast<unsigned>(s.num_elements()));
    const Eigen::Vector2d p(u01(rng), u01(rng));
    Eigen::Matrix2Xd pts(2, 9);
    for (int j = 0; j < 3; ++j) {
      for (int i = 0; i < 3; ++i) pts.col(i + 3 * j) = p + h * Eigen::Vector2d(i - 1, j - 1);
    }
    basis::BasisValues r;
    s.evaluate(e, pts, 2, r);
    const Eigen::Vector4d box = s.base().element_box(e);
    const Eigen::VectorXd def = rational_by_definition(s, box(0) + p(0) * (box(1) - box(0)), box(2) + p(1) * (box(3) - box(2)));
    const auto dofs = s.dofs(e);
    for (std::size_t a = 0; a < dofs.size(); ++a) EXPECT_NEAR(r.value(static_cast<Index>(a), 4), def(dofs[a]), 1e-14);
    EXPECT_NEAR(r.value.col(4).sum(), 1.0, 1e-14);
    EXPECT_NEAR(r.du.col(4).sum(), 0.0, 1e-12);
    EXPECT_NEAR(r.duv.col(4).sum(), 0.0, 1e-11);
    const Eigen::VectorXd du = (r.value.col(5) - r.value.col(3)) / (2 * h), dv = (r.value.col(7) - r.value.col(1)) / (2 * h);
    const Eigen::VectorXd duu = (r.value.col(5) - 2 * r.value.col(4) + r.value.col(3)) / (h * h);
    const Eigen::VectorXd dvv = (r.value.col(7) - 2 * r.value.col(4) + r.value.col(1)) / (h * h);
    const Eigen::VectorXd duv = (r.value.col(8) - r.value.col(6) - r.value.col(2) + r.value.col(0)) / (4 * h * h);
    EXPECT_LE((du - r.du.col(4)).cwiseAbs().maxCoeff(), 1e-7);
    EXPECT_LE((dv - r.dv.col(4)).cwiseAbs().maxCoeff(), 1e-7);
    EXPECT_LE((duu - r.duu.col(4)).cwiseAbs().maxCoeff(), 1e-5);
    EXPECT_LE((dvv - r.dvv.col(4)).cwiseAbs().maxCoeff(), 1e-5);
    EXPECT_LE((duv - r.duv.col(4)).cwiseAbs().maxCoeff(), 1e-5);
  }
}

// Every point of the inner and outer arcs at distance r_inner and r_outer from the origin (1e-14), for every
// degree and after refinement; the corners where they should be.
// Twin classes of a NURBS space are its B-spline space's; each element applies its own weights to the shared
// B-spline values (from_reference), which gives its own rational functions (to rounding, against evaluate()).
TEST(Nurbs, TwinsShareBsplineValuesAndKeepTheirWeights) {
  const basis::Geometry g = refine::refine_uniform(make_quarter_annulus(3), 3).geometry;  // 8 × 8 intervals
  const basis::Space& space = g.space();
  const RationalSpace* r = rational_space(space);
  ASSERT_NE(r, nullptr);
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u01(0.0, 1.0);
  Eigen::Matrix2Xd pts(2, 7);
  for (Index k = 0; k < pts.cols(); ++k) pts.col(k) << u01(rng), u01(rng);
  Index twins = 0;
  basis::BasisValues reference, derived, direct;
  for (Index e = 0; e < space.num_elements(); ++e) {
    const Index twin = space.reference_element(e);
    EXPECT_EQ(twin, r->base().reference_element(e));
    twins += twin != e;
    space.evaluate_reference(twin, pts, 2, reference);
    space.from_reference(e, reference, 2, derived);
    space.evaluate(e, pts, 2, direct);
    EXPECT_LE((derived.value - direct.value).cwiseAbs().maxCoeff(), 1e-14) << "element " << e;
    EXPECT_LE((derived.du - direct.du).cwiseAbs().maxCoeff(), 1e-12) << "element " << e;
    EXPECT_LE((derived.duv - direct.duv).cwiseAbs().maxCoeff(), 1e-11) << "element " << e;
  }
  EXPECT_EQ(twins, 64 - 25);  // (2p − 1)² distinct B-spline operators at p = 3
}

TEST(Nurbs, QuarterAnnulusArcsAreCircles) {
  for (int p = 2; p <= 5; ++p) {
    for (int steps : {0, 2}) {
      const basis::Geometry g = refine::refine_uniform(make_quarter_annulus(p, 1.0, 2.0), steps).geometry;
      for (int k = 0; k <= 20; ++k) {
        const double v = k / 20.0;
        EXPECT_NEAR(map_point(g, 0.0, v).head(2).norm(), 1.0, 1e-14) << p << " " << steps << " " << v;
        EXPECT_NEAR(map_point(g, 1.0, v).head(2).norm(), 2.0, 1e-14) << p << " " << steps << " " << v;
      }
      EXPECT_LE((map_point(g, 0.0, 0.0) - Eigen::Vector3d(1, 0, 0)).norm(), 1e-15);
      EXPECT_LE((map_point(g, 1.0, 1.0) - Eigen::Vector3d(0, 2, 0)).norm(), 1e-15);
    }
  }
}

// Refinement keeps the map (1e-13) and the coarse rational functions are the prolongation's combinations of the
// fine ones: Σ_k P(k, i) R^fine_k = R^coarse_i at random points (1e-13).
TEST(Nurbs, RefinementKeepsTheMapAndTheFunctions) {
  const basis::Geometry coarse = random_patch(7);
  const refine::Refinement r = refine::refine_uniform(coarse, 2);
  const RationalSpace& cs = *rational_space(coarse.space());
  const RationalSpace* fs = rational_space(r.geometry.space());
  ASSERT_NE(fs, nullptr);
  EXPECT_EQ(fs->num_elements(), 16 * cs.num_elements());
  std::mt19937 rng(2);
  std::uniform_real_distribution<double> u01(0.0, 1.0);
  for (int k = 0; k < 50; ++k) {
    const double x = u01(rng), y = u01(rng);
    EXPECT_LE((map_point(coarse, x, y) - map_point(r.geometry, x, y)).norm(), 1e-13);
    const Eigen::VectorXd combined = Eigen::MatrixXd(r.prolongation).transpose() * rational_by_definition(*fs, x, y);
    EXPECT_LE((combined - rational_by_definition(cs, x, y)).cwiseAbs().maxCoeff(), 1e-13);
  }
}

// Written and read back: the same knots, control points and weights, bit for bit.
TEST(PatchFile, RoundTripIsExact) {
  const basis::Geometry g = refine::refine_uniform(random_patch(5), 1).geometry;
  const basis::Geometry back = parse_patch(patch_text(g), "mem.json");
  const RationalSpace &a = *rational_space(g.space()), *b = rational_space(back.space());
  ASSERT_NE(b, nullptr);
  EXPECT_EQ(b->base().knots_u().knots(), a.base().knots_u().knots());
  EXPECT_EQ(b->base().knots_v().knots(), a.base().knots_v().knots());
  EXPECT_EQ(back.control_points(), g.control_points());
  EXPECT_EQ(b->weights(), a.weights());
  // Without weights: a polynomial B-spline patch.
  const basis::Geometry plain = make_rectangle(2, 0.0, 3.0, 0.0, 1.0);
  const basis::Geometry plain_back = parse_patch(patch_text(plain), "plain.json");
  EXPECT_EQ(rational_space(plain_back.space()), nullptr);
  EXPECT_EQ(plain_back.space().polynomial_degree(0), 2);
  EXPECT_EQ(plain_back.control_points(), plain.control_points());
}

// A hand-written file (the one in the README): the quarter circle of radius 1 around the origin as a quadratic
// NURBS disc sector... here the annulus 1 <= r <= 2, whose arcs must come out as circles.
TEST(PatchFile, HandWrittenAnnulusIsExact) {
  const std::string text = R"({
    "format": "iga-patch", "version": 1,
    "degree": [1, 2],
    "knots": [[0, 0, 1, 1], [0, 0, 0, 1, 1, 1]],
    "control_points": [[1, 0], [2, 0], [1, 1], [2, 2], [0, 1], [0, 2]],
    "weights": [1, 1, 0.70710678118654752, 0.70710678118654752, 1, 1]
  })";
  const basis::Geometry g = parse_patch(text, "annulus.json");
  for (int k = 0; k <= 10; ++k) {
    EXPECT_NEAR(map_point(g, 0.0, k / 10.0).head(2).norm(), 1.0, 1e-15);
    EXPECT_NEAR(map_point(g, 1.0, k / 10.0).head(2).norm(), 2.0, 1e-15);
  }
}

// Each bad file gets one InputError naming the file and what is wrong, with its JSON path.
TEST(PatchFile, BadFilesAreRefusedWithTheirPath) {
  const std::string head = R"("format": "iga-patch", "version": 1, "degree": [1, 1], "knots": [[0, 0, 1, 1], [0, 0, 1, 1]])";
  const std::string cp = R"("control_points": [[0, 0], [1, 0], [0, 1], [1, 1]])";
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"{" + head + ", " + cp + ", \"weights\": [1, 1, -1, 1]}", "p.json: weights[2] is -1: weights must be positive"},
      {"{" + head + ", " + cp + ", \"weights\": [1, 1, 1]}", "p.json: weights has 3 entries, not 4"},
      {"{" + head + ", " + cp + ", \"weight\": [1, 1, 1, 1]}", "p.json: unknown key \"weight\""},
      {"{" + head + "}", "p.json: no \"control_points\""},
      {"{" + head + R"(, "control_points": [[0, 0], [1, 0], [0, "a"], [1, 1]]})", "p.json: control_points[2][1] must be a number, got \"a\""},
      {"{" + head + R"(, "control_points": [[0, 0], [1, 0], [0, 1]]})", "p.json: control_points has 3 entries, not 4"},
      {R"({"format": "iga-patch", "version": 1, "degree": [1, 1], "knots": [[0, 1, 0, 1], [0, 0, 1, 1]], )" + cp + "}",
       "p.json: knots[0] (degree 1): knot vector: knots decrease"},
      {R"({"format": "iga-patch", "version": 1, "degree": [1.5, 1], "knots": [[0, 0, 1, 1], [0, 0, 1, 1]], )" + cp + "}",
       "p.json: degree[0] is 1.5"},
      {R"({"format": "iga-patch", "version": 2})", "p.json: \"version\" is 2"},
      {"{" + head + ", " + cp, "p.json:1:"},
      {"{" + head + ", " + cp + ", \"weights\": [1, 1, 1, 1], \"weights\": [2, 2, 2, 2]}", "p.json: key 'weights' appears more than once"},
      {"{" + head + ", " + cp + ", \"a\\nb\": 1}", "p.json: unknown key \"a\\nb\""},
  };
  for (const auto& [text, message] : cases) {
    try {
      parse_patch(text, "p.json");
      ADD_FAILURE() << "accepted: " << text;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(message), std::string::npos) << e.what() << "\n  expected: " << message;
    }
  }
  EXPECT_THROW(read_patch("no/such/file.json"), InputError);
}

// Through the registry: --geometry FILE.json takes the file's degree, a different --degree is refused, and
// NURBS patches have no THB refinement (named, not a silent polynomial fallback).
TEST(PatchFile, RegistryReadsPatchFiles) {
  const std::string path = ::testing::TempDir() + "nurbs_annulus.json";
  write_patch(path, make_quarter_annulus(4));
  const basis::Backend& b = basis::backend("bspline");
  basis::BackendOptions o;
  o.geometry = path;
  EXPECT_EQ(basis::degree(b, o), 4);
  basis::BackendFacts facts;
  const basis::Geometry g = basis::make_geometry(b, nullptr, o, facts);
  EXPECT_NE(rational_space(g.space()), nullptr);
  o.degree = 3;
  EXPECT_THROW(basis::degree(b, o), InputError);
  EXPECT_THROW(basis::make_geometry(b, nullptr, o, facts), InputError);
  const std::vector<Index> marked = {0};
  EXPECT_THROW(basis::refine_marked(g, marked, 2, facts), InputError);
  EXPECT_THROW(b.bezier_patches(g, o, facts), UnsupportedError);
}

// The example file in data/patches is the default annulus at degree 2: the same control points and weights.
TEST(PatchFile, ExampleFileIsTheDefaultAnnulus) {
  const basis::Geometry file = read_patch(std::string(IGA_SOURCE_DIR) + "/data/patches/quarter_annulus.json");
  const basis::Geometry built = make_quarter_annulus(2);
  EXPECT_LE((file.control_points() - built.control_points()).cwiseAbs().maxCoeff(), 1e-15);
  EXPECT_LE((rational_space(file.space())->weights() - rational_space(built.space())->weights()).cwiseAbs().maxCoeff(), 1e-16);
}
