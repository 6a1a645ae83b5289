// B-splines: Cox–de Boor (reference) against Bézier extraction, partition of unity, derivatives against
// finite differences, knot insertion leaves the spline unchanged.
#include <gtest/gtest.h>

#include <random>
#include <set>

#include "basis/bspline/bernstein.hpp"
#include "basis/bspline/extraction.hpp"
#include "basis/bspline/knot_insertion.hpp"
#include "basis/bspline/tensor_space.hpp"
#include "core/error.hpp"

using namespace iga;
using namespace iga::basis::bspline;

namespace {
// Open knot vector on [0, 3] with random interior knots, some repeated up to the degree.
KnotVector random_knots(int p, std::mt19937& rng) {
  std::uniform_real_distribution<double> u(0.0, 3.0);
  std::uniform_int_distribution<int> mult(1, p);
  std::vector<double> t(static_cast<std::size_t>(p + 1), 0.0);
  std::vector<double> inner;
  for (int i = 0; i < 4; ++i) inner.push_back(u(rng));
  std::sort(inner.begin(), inner.end());
  for (double x : inner) {
    const int m = mult(rng);
    for (int k = 0; k < m; ++k) t.push_back(x);
  }
  for (int i = 0; i <= p; ++i) t.push_back(3.0);
  return KnotVector(p, t);
}

// Spline value sum c_i N_i(x) by Cox–de Boor.
double spline_value(const KnotVector& kv, const Eigen::VectorXd& c, double x) {
  const Index mu = kv.span(x);
  const Eigen::MatrixXd n = basis_functions(kv, mu, x, 0);
  double s = 0;
  for (int i = 0; i <= kv.degree(); ++i) s += c(mu - kv.degree() + i) * n(0, i);
  return s;
}
}  // namespace

TEST(KnotVector, RejectsInvalidInput) {
  EXPECT_THROW(KnotVector(2, {0, 0, 0, 1, 1}), InputError);            // too short
  EXPECT_THROW(KnotVector(2, {0, 0, 0, 0.5, 0.4, 1, 1, 1}), InputError);  // decreasing
  EXPECT_THROW(KnotVector(2, {0, 0, 0.1, 1, 1, 1}), InputError);       // not clamped
  EXPECT_THROW(KnotVector(2, {0, 0, 0, 0.5, 0.5, 0.5, 1, 1, 1}), InputError);  // multiplicity 3 > 2
  EXPECT_THROW(KnotVector(0, {0, 1}), InputError);
  EXPECT_THROW(KnotVector(1, {0, 0, NAN, 1, 1}), InputError);
  const KnotVector kv(2, {0, 0, 0, 0.5, 0.5, 1, 1, 1});
  EXPECT_EQ(kv.num_basis(), 5);
  EXPECT_EQ(kv.num_intervals(), 2);
  EXPECT_EQ(kv.span(0.0), 2);
  EXPECT_EQ(kv.span(0.5), 4);
  EXPECT_EQ(kv.span(1.0), 4);
}

// Known values: the quadratic B-splines on the uniform open vector [0,0,0,1,2,2,2]/2 at x = 1/2:
// N_0 = 1/4, N_1 = 5/8, N_2 = 1/8 (hand evaluation of the Cox–de Boor recursion).
TEST(CoxDeBoor, KnownValues) {
  const KnotVector kv(2, {0, 0, 0, 0.5, 1, 1, 1});
  const Eigen::MatrixXd n = basis_functions(kv, kv.span(0.25), 0.25, 1);
  EXPECT_NEAR(n(0, 0), 0.25, 1e-15);
  EXPECT_NEAR(n(0, 1), 0.625, 1e-15);
  EXPECT_NEAR(n(0, 2), 0.125, 1e-15);
  // Derivatives: N_0 = (1-2x)^2 -> -4(1-2x) = -2; N_2 = 2x^2 -> 4x = 1; N_1 = 1 - N_0 - N_2 -> 1.
  EXPECT_NEAR(n(1, 0), -2.0, 1e-14);
  EXPECT_NEAR(n(1, 1), 1.0, 1e-14);
  EXPECT_NEAR(n(1, 2), 1.0, 1e-14);
}

TEST(Bernstein, MatchesClosedForm) {
  Eigen::RowVectorXd t(3);
  t << 0.0, 0.3, 1.0;
  Eigen::MatrixXd b, d1, d2;
  bernstein(3, t, 2, b, &d1, &d2);
  for (int k = 0; k < 3; ++k) {
    const double x = t(k);
    EXPECT_NEAR(b(1, k), 3 * x * (1 - x) * (1 - x), 1e-15);
    EXPECT_NEAR(d1(1, k), 3 * (1 - x) * (1 - x) - 6 * x * (1 - x), 1e-14);
    EXPECT_NEAR(d2(1, k), -12 + 18 * x, 1e-13);
  }
}

// N = C B on every interval equals Cox–de Boor, values and first and second derivatives, degrees 1..5.
TEST(BezierExtraction, MatchesCoxDeBoor) {
  std::mt19937 rng(42);
  std::uniform_real_distribution<double> s01(0.0, 1.0);
  for (int p = 1; p <= 5; ++p) {
    for (int trial = 0; trial < 5; ++trial) {
      const KnotVector kv = random_knots(p, rng);
      const auto ops = extraction_operators(kv);
      for (std::size_t e = 0; e < ops.size(); ++e) {
        const Index mu = kv.interval_spans()[e];
        const double a = kv[mu], h = kv[mu + 1] - kv[mu];
        Eigen::RowVectorXd s(7);
        for (int k = 0; k < 7; ++k) s(k) = k == 0 ? 0.0 : (k == 6 ? 1.0 : s01(rng));
        Eigen::MatrixXd b, d1, d2;
        bernstein(p, s, 2, b, &d1, &d2);
        const Eigen::MatrixXd n0 = ops[e] * b, n1 = ops[e] * d1 / h, n2 = ops[e] * d2 / (h * h);
        for (int k = 0; k < 7; ++k) {
          const Eigen::MatrixXd ref = basis_functions(kv, mu, a + s(k) * h, 2);
          for (int i = 0; i <= p; ++i) {
            EXPECT_NEAR(n0(i, k), ref(0, i), 1e-13) << "p " << p << " e " << e;
            EXPECT_NEAR(n1(i, k), ref(1, i), 1e-11 * (1 + std::abs(ref(1, i))));
            if (p >= 2) {
              EXPECT_NEAR(n2(i, k), ref(2, i), 1e-9 * (1 + std::abs(ref(2, i))));
            }
          }
        }
      }
    }
  }
}

TEST(TensorSpace, PartitionOfUnityAndDerivativesAgainstFiniteDifferences) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> s01(0.05, 0.95);
  for (int p = 1; p <= 5; ++p) {
    const TensorSpace space(random_knots(p, rng), random_knots(std::max(1, p - 1), rng));
    Eigen::Matrix2Xd pts(2, 5);
    for (int k = 0; k < 5; ++k) pts.col(k) << s01(rng), s01(rng);
    const double h = 1e-6;
    for (Index e = 0; e < space.num_elements(); ++e) {
      iga::basis::BasisValues v, vp, vm;
      space.evaluate(e, pts, 2, v);
      EXPECT_LE((v.value.colwise().sum().array() - 1.0).abs().maxCoeff(), 1e-14);
      EXPECT_LE(v.du.colwise().sum().cwiseAbs().maxCoeff(), 1e-11);
      EXPECT_LE(v.value.minCoeff(), 1.0 + 1e-15);
      EXPECT_GE(v.value.minCoeff(), -1e-15);
      for (int dir = 0; dir < 2; ++dir) {
        Eigen::Matrix2Xd shifted = pts;
        shifted.row(dir).array() += h;
        space.evaluate(e, shifted, 1, vp);
        shifted.row(dir).array() -= 2 * h;
        space.evaluate(e, shifted, 1, vm);
        const Eigen::MatrixXd fd = (vp.value - vm.value) / (2 * h);
        const Eigen::MatrixXd fd2 = ((dir == 0 ? vp.du : vp.dv) - (dir == 0 ? vm.du : vm.dv)) / (2 * h);
        const Eigen::MatrixXd& d = dir == 0 ? v.du : v.dv;
        const Eigen::MatrixXd& dd = dir == 0 ? v.duu : v.dvv;
        EXPECT_LE((fd - d).cwiseAbs().maxCoeff(), 1e-6 * (1 + d.cwiseAbs().maxCoeff())) << "p " << p;
        EXPECT_LE((fd2 - dd).cwiseAbs().maxCoeff(), 1e-5 * (1 + dd.cwiseAbs().maxCoeff())) << "p " << p;
        if (dir == 0) {
          const Eigen::MatrixXd fdm = (vp.dv - vm.dv) / (2 * h);
          EXPECT_LE((fdm - v.duv).cwiseAbs().maxCoeff(), 1e-5 * (1 + v.duv.cwiseAbs().maxCoeff()));
        }
      }
    }
  }
}

// The tensor space's values are products of Cox–de Boor values in knot coordinates.
TEST(TensorSpace, ValuesAreProductsOfCoxDeBoor) {
  std::mt19937 rng(3);
  const TensorSpace space(random_knots(3, rng), random_knots(2, rng));
  Eigen::Matrix2Xd pts(2, 2);
  pts << 0.3, 0.8, 0.6, 0.1;
  for (Index e = 0; e < space.num_elements(); ++e) {
    iga::basis::BasisValues v;
    space.evaluate(e, pts, 0, v);
    const Eigen::Vector4d box = space.element_box(e);
    const auto dofs = space.dofs(e);
    for (int k = 0; k < 2; ++k) {
      const double x = box(0) + pts(0, k) * (box(1) - box(0)), y = box(2) + pts(1, k) * (box(3) - box(2));
      const Index mx = space.knots_u().span(x), my = space.knots_v().span(y);
      const Eigen::MatrixXd nu = basis_functions(space.knots_u(), mx, x, 0);
      const Eigen::MatrixXd nv = basis_functions(space.knots_v(), my, y, 0);
      for (int b = 0; b <= 2; ++b) {
        for (int a = 0; a <= 3; ++a) {
          const Index local = a + 4 * b;
          EXPECT_EQ(dofs[static_cast<std::size_t>(local)], (mx - 3 + a) + space.num_basis_u() * (my - 2 + b));
          EXPECT_NEAR(v.value(local, k), nu(0, a) * nv(0, b), 1e-14);
        }
      }
    }
  }
}

// Knot insertion: the refined spline equals the coarse one (Cox–de Boor on both knot vectors).
// Space::reference_element: on uniform knots with spacing 0.1 (not a power of two: the operators differ by rounding),
// the operator of an interval depends on the p − 1 knot spans on either side, so all but p − 1 intervals at each end
// share one and (2p − 1)² elements are distinct; every element's twin is its lowest, itself a twin of nothing lower,
// with the same functions at random points. Irregular spacing (spans 1, 2, 1.5, 3, ...) leaves every interval
// distinct. (Geometric spacing would not: the operator depends on span ratios only.)
TEST(TensorSpace, TwinElementsHaveTheSameFunctions) {
  const int p = 3;
  std::vector<double> t(p + 1, 0.0), graded(p + 1, 0.0);
  const double spans[] = {1.0, 2.0, 1.5, 3.0, 1.2, 2.5, 1.0, 1.7, 2.2, 1.4};
  double x = 0.0;
  for (int i = 1; i < 10; ++i) {
    t.push_back(0.1 * i);
    graded.push_back(x += spans[i - 1]);
  }
  for (int i = 0; i <= p; ++i) {
    t.push_back(1.0);
    graded.push_back(x + spans[9]);
  }
  const TensorSpace uniform(KnotVector(p, t), KnotVector(p, t));
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u01(0.0, 1.0);
  Eigen::Matrix2Xd pts(2, 9);
  for (Index k = 0; k < pts.cols(); ++k) pts.col(k) << u01(rng), u01(rng);
  std::set<Index> distinct;
  basis::BasisValues a, b;
  for (Index e = 0; e < uniform.num_elements(); ++e) {
    const Index twin = uniform.reference_element(e);
    ASSERT_LE(twin, e);
    EXPECT_EQ(uniform.reference_element(twin), twin);
    distinct.insert(twin);
    uniform.evaluate(e, pts, 2, a);
    uniform.evaluate(twin, pts, 2, b);
    EXPECT_LE((a.value - b.value).cwiseAbs().maxCoeff(), 1e-14) << "element " << e;
    EXPECT_LE((a.du - b.du).cwiseAbs().maxCoeff(), 1e-12) << "element " << e;
    EXPECT_LE((a.duv - b.duv).cwiseAbs().maxCoeff(), 1e-11) << "element " << e;
  }
  EXPECT_EQ(distinct.size(), static_cast<std::size_t>((2 * p - 1) * (2 * p - 1)));
  const TensorSpace geometric(KnotVector(p, graded), KnotVector(p, t));
  for (Index ex = 0; ex < geometric.num_elements_u(); ++ex) EXPECT_EQ(geometric.reference_element(ex), ex);
}

TEST(KnotInsertion, RefinedSplineIsUnchanged) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> x01(0.0, 3.0), c(-1.0, 1.0);
  for (int p = 1; p <= 6; ++p) {
    for (int trial = 0; trial < 5; ++trial) {
      const KnotVector coarse = random_knots(p, rng);
      // Insert the midpoints and a few random knots, one of them at an existing knot.
      std::vector<double> t = insert_midpoints(coarse).knots();
      for (int k = 0; k < 3; ++k) t.push_back(x01(rng));
      t.push_back(coarse[p + 1] < 3.0 ? coarse[p + 1] : 1.5);
      std::sort(t.begin(), t.end());
      // Keep interior multiplicities <= p.
      std::vector<double> kept;
      for (double x : t) {
        const auto m = std::count(kept.begin(), kept.end(), x);
        if (x == 0.0 || x == 3.0 || m < p) kept.push_back(x);
      }
      const KnotVector fine(p, kept);
      const Eigen::SparseMatrix<double> r = refinement_matrix(coarse, fine);
      Eigen::VectorXd cc(coarse.num_basis());
      for (Index i = 0; i < cc.size(); ++i) cc(i) = c(rng);
      const Eigen::VectorXd cf = r * cc;
      for (int k = 0; k < 50; ++k) {
        const double x = k == 0 ? 0.0 : (k == 1 ? 3.0 : x01(rng));
        EXPECT_NEAR(spline_value(fine, cf, x), spline_value(coarse, cc, x), 1e-12) << "p " << p;
      }
      // Rows of a refinement matrix are convex combinations.
      const Eigen::VectorXd ones = r * Eigen::VectorXd::Ones(coarse.num_basis());
      EXPECT_LE((ones.array() - 1.0).abs().maxCoeff(), 1e-14);
    }
  }
  EXPECT_THROW(refinement_matrix(KnotVector::uniform(2, 2), KnotVector::uniform(2, 3)), InputError);
}
