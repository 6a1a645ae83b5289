// The refine-and-smooth algorithm (refine/refine_smooth.hpp): Cashman, Dodgson, Sabin's worked example (§3.3,
// Figure 4), equality with Boehm and Oslo, the unchanged curve, symmetry, the d·n operation count (§4), both
// variants (§3, §5), and the tensor-product prolongation.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "basis/bspline/knot_insertion.hpp"
#include "basis/bspline/tensor_space.hpp"
#include "core/error.hpp"
#include "random_splines.hpp"
#include "refine/refine_smooth.hpp"

using namespace iga;
using namespace iga::refine;
using iga::basis::bspline::SplineCurve;
using iga::refine::test::cox_de_boor;
using iga::refine::test::knots_diff;
using iga::refine::test::random_curve;
using iga::refine::test::rel_diff;

namespace {
const double nan_ = std::numeric_limits<double>::quiet_NaN();
constexpr RefineSmoothVariant variants[] = {RefineSmoothVariant::levels, RefineSmoothVariant::constant_memory};

// The reference for the polar convention: control point q of the result is the blossom of the original
// (a single polynomial piece here) at its labels u_q..u_{q+d-1} (what Boehm's insertions compute).
Eigen::MatrixXd blossom_reference(const PolarSpline& coarse, const PolarSpline& fine) {
  const SplineCurve c = to_standard(coarse, nan_, nan_);
  const Index mu = domain_intervals(c).front();
  Eigen::MatrixXd ref(fine.control_points.rows(), fine.control_points.cols());
  for (Index q = 0; q < ref.rows(); ++q) ref.row(q) = blossom(c, mu, &fine.knots[static_cast<std::size_t>(q)]);
  return ref;
}

// Every non-empty interval of the paper's knot vector gets a knot at fraction f.
std::vector<double> every_interval(const std::vector<double>& t, double f = 0.5) {
  std::vector<double> x(t.size() - 1, nan_);
  for (std::size_t j = 0; j + 1 < t.size(); ++j)
    if (t[j] < t[j + 1]) x[j] = t[j] + f * (t[j + 1] - t[j]);
  return x;
}
}  // namespace

TEST(RefineSmooth, PaperWorkedExample) {
  // Paper §3.3: d = 5, t = [0, 0, 4, 4, 4, 12, 16, 18, 18, 20] (6 control points, domain [4, 12]), a knot in
  // every non-zero interval; after the truncation of §7 the knots are [0, 2, 4, 4, 4, 8, 12, 14, 16, 17, 18].
  PolarSpline s;
  s.degree = 5;
  s.knots = {0, 0, 4, 4, 4, 12, 16, 18, 18, 20};
  s.control_points.resize(6, 2);
  s.control_points << 0, 0, 1, 2, 3, 3, 5, 2, 6, -1, 8, 0;
  const std::vector<double> x = every_interval(s.knots);
  // The knots of Figure 4: 2, 8, 14, 17, 19.
  std::vector<double> inserted;
  for (double v : x)
    if (!std::isnan(v)) inserted.push_back(v);
  EXPECT_EQ(inserted, (std::vector<double>{2, 8, 14, 17, 19}));
  for (RefineSmoothVariant v : variants) {
    const RefineSmoothResult r = refine_smooth(s, x, v);
    EXPECT_EQ(r.spline.knots, (std::vector<double>{0, 2, 4, 4, 4, 8, 12, 14, 16, 17, 18}));
    ASSERT_EQ(r.spline.control_points.rows(), 7);
    EXPECT_LE(rel_diff(r.spline.control_points, blossom_reference(s, r.spline)), 1e-13);
    // The domain part agrees with Boehm inserting 8 (standard convention): the control point b(4,4,4,8,12).
    const SplineCurve boehm = insert_knot_boehm(to_standard(s, 0, 20), 8.0);
    EXPECT_LE(rel_diff(r.spline.control_points.row(2), boehm.control_points.row(2)), 1e-13);
    // Same curve on [4, 12].
    const SplineCurve fine = to_standard(r.spline, nan_, nan_);
    for (double t = 4.0; t <= 12.0; t += 0.5) {
      EXPECT_LE(rel_diff(evaluate(fine, t), evaluate(boehm, t)), 1e-13);
    }
  }
}

TEST(RefineSmooth, EqualsBoehmAndOsloForDegrees1To9) {
  std::mt19937 rng(5);
  for (int d = 1; d <= 9; ++d) {
    for (int trial = 0; trial < 8; ++trial) {
      const SplineCurve c = random_curve(rng, d, 2 + trial % 5);
      // A random subset of the non-empty domain intervals, a random knot inside each.
      const std::vector<Index> spans = domain_intervals(c);
      std::uniform_real_distribution<double> frac(0.05, 0.95);
      std::bernoulli_distribution pick(trial == 0 ? 1.0 : 0.6);
      std::vector<double> xs;
      for (Index mu : spans) {
        if (!pick(rng)) continue;
        const double a = c.knots[static_cast<std::size_t>(mu)], b = c.knots[static_cast<std::size_t>(mu) + 1];
        xs.push_back(a + frac(rng) * (b - a));
      }
      const SplineCurve boehm = insert_knots_boehm(c, xs);
      const SplineCurve oslo = insert_knots_oslo(c, xs);
      for (RefineSmoothVariant v : variants) {
        const SplineCurve rs = refine_smooth(c, xs, v);
        ASSERT_EQ(rs.knots, boehm.knots) << "degree " << d;
        EXPECT_LE(rel_diff(rs.control_points, boehm.control_points), 1e-12) << "degree " << d << " trial " << trial;
        EXPECT_LE(rel_diff(rs.control_points, oslo.control_points), 1e-12) << "degree " << d;
        std::uniform_real_distribution<double> at(c.domain_begin(), c.domain_end());
        for (int s = 0; s < 10; ++s) {
          const double t = at(rng);
          EXPECT_LE(rel_diff(cox_de_boor(rs, t), cox_de_boor(c, t)), 1e-12) << "degree " << d;
        }
        // Symmetry: the mirrored curve (knots -t reversed, points reversed) refined at -x gives the mirror.
        SplineCurve m = c;
        for (std::size_t i = 0; i < c.knots.size(); ++i) m.knots[i] = -c.knots[c.knots.size() - 1 - i];
        m.control_points = c.control_points.colwise().reverse();
        std::vector<double> mx;
        for (double x : xs) mx.push_back(-x);
        const SplineCurve mr = refine_smooth(m, mx, v);
        std::vector<double> back(mr.knots.size());
        for (std::size_t i = 0; i < back.size(); ++i) back[i] = -mr.knots[back.size() - 1 - i];
        EXPECT_LE(knots_diff(back, rs.knots), 1e-14);
        EXPECT_LE(rel_diff(mr.control_points.colwise().reverse(), rs.control_points), 1e-12) << "degree " << d;
      }
    }
  }
}

TEST(RefineSmooth, PolarConventionWithKnotsOutsideTheDomain) {
  // Paper convention, random non-clamped knots with multiplicities up to d, a knot in a random subset of
  // intervals (also outside the domain): every control point is the blossom at its labels, per piece.
  std::mt19937 rng(11);
  for (int d = 1; d <= 9; ++d) {
    for (int trial = 0; trial < 6; ++trial) {
      SplineCurve c = random_curve(rng, d, 3 + trial, 2);
      PolarSpline s = to_polar(c);
      std::bernoulli_distribution pick(0.7);
      std::vector<double> x = every_interval(s.knots, 0.3);
      for (double& v : x)
        if (!pick(rng)) v = nan_;
      const RefineSmoothResult a = refine_smooth(s, x, RefineSmoothVariant::levels);
      const RefineSmoothResult b = refine_smooth(s, x, RefineSmoothVariant::constant_memory);
      EXPECT_EQ(a.spline.knots, b.spline.knots);
      EXPECT_LE(rel_diff(a.spline.control_points, b.spline.control_points), 1e-14);
      EXPECT_EQ(a.affine_combinations, b.affine_combinations);
      // Oslo on the standard form gives the same points.
      std::vector<double> xs;
      for (double v : x)
        if (!std::isnan(v) && v > c.domain_begin() && v < c.domain_end()) xs.push_back(v);
      const SplineCurve fine = to_standard(a.spline, c.knots.front(), c.knots.back());
      std::uniform_real_distribution<double> at(c.domain_begin(), c.domain_end());
      for (int k = 0; k < 10; ++k) {
        const double t = at(rng);
        EXPECT_LE(rel_diff(evaluate(fine, t), cox_de_boor(c, t)), 1e-12) << "degree " << d;
      }
    }
  }
}

TEST(RefineSmooth, OperationCountIsDTimesNForEvenDegree) {
  // §4: one knot in every interval, even d: 2n points at d/2 levels, one two-point combination each = d·n,
  // ignoring end conditions. Asserted as: every further interval (knot) costs exactly d combinations, and
  // the total never exceeds d·n (the points dropped at the ends, §7, cost nothing).
  for (int d = 2; d <= 8; d += 2) {
    long long previous_n = -1, previous_count = -1;
    for (int intervals = 4; intervals <= 64; intervals *= 2) {
      PolarSpline s;
      s.degree = d;
      for (int i = 0; i < intervals + 2 * (d - 1) + 1; ++i) s.knots.push_back(i * 1.0 + 0.1 * (i % 3));
      s.control_points = Eigen::MatrixXd::Random(static_cast<Index>(s.knots.size()) - d + 1, 2);
      const std::vector<double> x = every_interval(s.knots);
      long long n = 0;
      for (double v : x) n += !std::isnan(v);
      for (RefineSmoothVariant v : variants) {
        const RefineSmoothResult r = refine_smooth(s, x, v);
        EXPECT_LE(r.affine_combinations, d * n);
        if (previous_n >= 0) {
          EXPECT_EQ(r.affine_combinations - previous_count, d * (n - previous_n)) << "d=" << d;
        }
        if (v == RefineSmoothVariant::constant_memory) {
          std::cout << "d=" << d << " n=" << n << " combinations=" << r.affine_combinations << " d*n=" << d * n
                    << "\n";
          previous_n = n;
          previous_count = r.affine_combinations;
        }
      }
    }
  }
}

TEST(RefineSmooth, TensorProlongationKeepsTheMap) {
  std::mt19937 rng(3);
  for (int p = 1; p <= 4; ++p) {
    const SplineCurve cu = random_curve(rng, p, 3, 1), cv = random_curve(rng, p + 1, 2, 1);
    auto space = std::make_shared<const basis::bspline::TensorSpace>(basis::bspline::KnotVector(p, cu.knots),
                                                                      basis::bspline::KnotVector(p + 1, cv.knots));
    Eigen::MatrixXd cp = Eigen::MatrixXd::Random(space->num_dofs(), 3);
    const basis::Geometry g(space, cp);
    for (int which = 0; which < 2; ++which) {
      const std::vector<Index> iu = which ? std::vector<Index>{0, 2} : std::vector<Index>{};
      const Refinement r = refine_smooth_tensor(g, iu, which ? std::vector<Index>{1} : std::vector<Index>{});
      const auto& fine = dynamic_cast<const basis::bspline::TensorSpace&>(r.geometry.space());
      ASSERT_EQ(r.prolongation.rows(), fine.num_dofs());
      ASSERT_EQ(r.prolongation.cols(), space->num_dofs());
      if (!which) {
        // Every interval: the same space as the Oslo midpoint refinement, the same matrix.
        const auto ou = basis::bspline::insert_midpoints(space->knots_u());
        EXPECT_EQ(ou.knots(), fine.knots_u().knots());
        const Eigen::SparseMatrix<double> oslo = basis::bspline::refinement_matrix(*space, fine);
        EXPECT_LE(Eigen::MatrixXd(oslo - r.prolongation).cwiseAbs().maxCoeff(), 1e-12);
      }
      // A field and the map, coarse and fine, at random points.
      const Eigen::VectorXd field = Eigen::VectorXd::Random(space->num_dofs());
      const Eigen::VectorXd fine_field = r.prolongation * field;
      std::uniform_real_distribution<double> su(cu.domain_begin(), cu.domain_end()), sv(cv.domain_begin(), cv.domain_end());
      for (int k = 0; k < 20; ++k) {
        const double u = su(rng), v = sv(rng);
        auto value = [&](const basis::bspline::TensorSpace& sp, const Eigen::MatrixXd& coef) {
          const auto& ku = sp.knots_u();
          const auto& kv = sp.knots_v();
          const Index mu = ku.span(u), mv = kv.span(v);
          const Eigen::MatrixXd nu = basis::bspline::basis_functions(ku, mu, u, 0);
          const Eigen::MatrixXd nv = basis::bspline::basis_functions(kv, mv, v, 0);
          Eigen::RowVectorXd s = Eigen::RowVectorXd::Zero(coef.cols());
          for (int j = 0; j <= kv.degree(); ++j)
            for (int i = 0; i <= ku.degree(); ++i)
              s += nu(0, i) * nv(0, j) * coef.row((mu - ku.degree() + i) + sp.num_basis_u() * (mv - kv.degree() + j));
          return s;
        };
        EXPECT_LE(rel_diff(value(fine, r.geometry.control_points()), value(*space, cp)), 1e-12);
        EXPECT_LE(rel_diff(value(fine, fine_field), value(*space, field)), 1e-12);
      }
    }
  }
}

TEST(RefineSmooth, RejectsMisplacedKnots) {
  PolarSpline s;
  s.degree = 2;
  s.knots = {0, 0, 1, 2, 2};
  s.control_points = Eigen::MatrixXd::Zero(4, 1);
  EXPECT_THROW(refine_smooth(s, {nan_, 1.5, nan_, nan_}), InputError);
  EXPECT_THROW(refine_smooth(s, {nan_}), InputError);
}

TEST(RefineSmooth, LongCurvesSweptInParallelChunks) {
  // Beyond 2^15 positions the constant-memory variant sweeps chunks of blocks on the OpenMP threads (each
  // block started `levels` positions early); the result must equal Boehm and the count the §3 variant's.
  std::mt19937 rng(29);
  for (int d : {1, 2, 3, 4, 7}) {
    SplineCurve c = random_curve(rng, d, 150000, d % 2 ? 2 : 3);
    const std::vector<Index> spans = domain_intervals(c);
    std::uniform_real_distribution<double> frac(0.05, 0.95);
    std::bernoulli_distribution pick(0.9);
    std::vector<double> xs;
    for (Index mu : spans) {
      if (!pick(rng)) continue;
      const double a = c.knots[static_cast<std::size_t>(mu)], b = c.knots[static_cast<std::size_t>(mu) + 1];
      xs.push_back(a + frac(rng) * (b - a));
    }
    long long count_levels = 0, count_stream = 0;
    const SplineCurve boehm = insert_knots_boehm(c, xs);
    const SplineCurve levels = refine_smooth(c, xs, RefineSmoothVariant::levels, &count_levels);
    const SplineCurve stream = refine_smooth(c, xs, RefineSmoothVariant::constant_memory, &count_stream);
    ASSERT_GT(stream.num_control_points(), 4 * (1 << 15)) << "the parallel path must be reached";
    ASSERT_EQ(stream.knots, boehm.knots);
    EXPECT_LE(rel_diff(stream.control_points, boehm.control_points), 1e-12) << "degree " << d;
    EXPECT_LE(rel_diff(stream.control_points, levels.control_points), 1e-14) << "degree " << d;
    EXPECT_EQ(count_stream, count_levels) << "degree " << d;
  }
}

namespace {
// Knots to insert into c: in a random subset of the non-empty domain intervals a knot strictly inside, at the
// interval's left knot (where its multiplicity stays <= d) or at the domain end, sometimes a second one in
// the same interval (a second pass).
std::vector<double> mixed_knots(std::mt19937& rng, const SplineCurve& c) {
  std::uniform_real_distribution<double> frac(0.05, 0.95), coin(0.0, 1.0);
  auto multiplicity = [&](double x) { return std::count(c.knots.begin(), c.knots.end(), x); };
  std::vector<double> xs;
  for (Index mu : domain_intervals(c)) {
    const double a = c.knots[static_cast<std::size_t>(mu)], b = c.knots[static_cast<std::size_t>(mu) + 1];
    const double r = coin(rng);
    if (r < 0.2) continue;
    if (r < 0.35 && multiplicity(a) < c.degree) {
      xs.push_back(a);
    } else if (r < 0.4 && b == c.domain_end() && multiplicity(b) < c.degree) {
      xs.push_back(b);
    } else {
      xs.push_back(a + frac(rng) * (b - a));
    }
    if (coin(rng) < 0.05) xs.push_back(a + frac(rng) * (b - a));
  }
  return xs;
}

// The same curve with unclamped ends (the domain ends become simple knots).
SplineCurve unclamped(SplineCurve c) {
  const auto p = static_cast<std::size_t>(c.degree), m = c.knots.size();
  for (std::size_t i = 0; i < p; ++i) {
    c.knots[i] = c.knots[p] - 0.7 * static_cast<double>(p - i);
    c.knots[m - 1 - i] = c.knots[m - 1 - p] + 0.7 * static_cast<double>(p - i);
  }
  return c;
}
}  // namespace

TEST(RefineSmooth, ConstantMemoryVariantTakesEveryPath) {
  // The §5 variant reads sorted knots directly when each has an interval of its own, and otherwise goes
  // pass by pass through the per-interval form: knots at existing knots and at the domain end (the last
  // interval is closed), two knots in one interval, unsorted input, clamped and unclamped ends, short
  // curves (every block meets the end conditions) and long ones (blocks away from the ends on both threads),
  // 1 to 7 coordinates (compile-time dimensions up to 4, run-time beyond).
  std::mt19937 rng(41);
  for (int d = 1; d <= 9; ++d) {
    for (int trial = 0; trial < 12; ++trial) {
      const int breaks = trial < 10 ? 1 + 3 * trial : 20000;
      SplineCurve c = random_curve(rng, d, breaks, 1 + (5 * trial) % 7);
      if (trial % 2) c = unclamped(c);
      std::vector<double> xs = mixed_knots(rng, c);
      long long count_levels = 0, count_stream = 0;
      const SplineCurve levels = refine_smooth(c, xs, RefineSmoothVariant::levels, &count_levels);
      std::shuffle(xs.begin(), xs.end(), rng);
      const SplineCurve stream = refine_smooth(c, xs, RefineSmoothVariant::constant_memory, &count_stream);
      const SplineCurve boehm = insert_knots_boehm(c, xs);
      ASSERT_EQ(stream.knots, boehm.knots) << "degree " << d << " trial " << trial;
      EXPECT_LE(rel_diff(stream.control_points, boehm.control_points), 1e-12) << "degree " << d << " trial " << trial;
      EXPECT_LE(rel_diff(stream.control_points, levels.control_points), 1e-14) << "degree " << d << " trial " << trial;
      EXPECT_EQ(count_stream, count_levels) << "degree " << d << " trial " << trial;
    }
  }
}

TEST(RefineSmooth, RejectsAKnotOfTooHighMultiplicity) {
  // Degree 2, knot 1 already double: a third copy is above the degree, in either variant and either form.
  SplineCurve c;
  c.degree = 2;
  c.knots = {0, 0, 0, 1, 1, 2, 2, 2};
  c.control_points = Eigen::MatrixXd::Zero(5, 2);
  for (RefineSmoothVariant v : variants) {
    EXPECT_THROW(refine_smooth(c, {0.5, 1.0, 1.5}, v), InputError);
    EXPECT_NO_THROW(refine_smooth(c, {0.5, 1.5}, v));
    EXPECT_THROW(refine_smooth(c, {2.5}, v), InputError);  // outside the domain
  }
}

TEST(RefineSmooth, MatrixEqualsTheOsloMatrix) {
  // refine_smooth_matrix (degree + 2 runs on sums of unit vectors, columns told apart by supports) against
  // the Oslo refinement matrix of basis/bspline (blossom rows), with multiple knots and a random subset of
  // intervals refined at random positions.
  std::mt19937 rng(41);
  for (int d = 1; d <= 7; ++d) {
    for (int breaks : {2, 9, 400}) {
      const SplineCurve c = random_curve(rng, d, breaks, 1);
      const std::vector<Index> spans = domain_intervals(c);
      std::uniform_real_distribution<double> frac(0.1, 0.9);
      std::bernoulli_distribution pick(0.7);
      std::vector<double> xs;
      for (Index mu : spans) {
        if (!pick(rng)) continue;
        const double a = c.knots[static_cast<std::size_t>(mu)], b = c.knots[static_cast<std::size_t>(mu) + 1];
        xs.push_back(a + frac(rng) * (b - a));
      }
      std::vector<double> fine_knots;
      const Eigen::SparseMatrix<double> m = refine_smooth_matrix(d, c.knots, xs, fine_knots);
      const Eigen::SparseMatrix<double> oslo = basis::bspline::refinement_matrix(
          basis::bspline::KnotVector(d, c.knots), basis::bspline::KnotVector(d, fine_knots));
      ASSERT_EQ(m.rows(), oslo.rows());
      ASSERT_EQ(m.cols(), oslo.cols());
      EXPECT_LE(Eigen::MatrixXd(oslo - m).cwiseAbs().maxCoeff(), 1e-12) << "degree " << d << " breaks " << breaks;
    }
  }
}
