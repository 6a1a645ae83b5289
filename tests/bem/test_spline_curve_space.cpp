// basis::SplineCurveSpace: B-splines on open (clamped) and closed (periodic) segments.
#include <gtest/gtest.h>

#include <cmath>

#include "basis/curve/spline_curve_space.hpp"
#include "core/error.hpp"

using iga::Index;
using iga::basis::CurveBasisValues;
using iga::basis::SplineCurveSpace;

namespace {

SplineCurveSpace mixed(int p) { return SplineCurveSpace(p, {{3, false}, {p + 2, true}, {1, false}, {5, true}}); }

}  // namespace

TEST(SplineCurveSpace, CountsAndNumbering) {
  const SplineCurveSpace s = mixed(3);
  EXPECT_EQ(s.num_elements(), 3 + 5 + 1 + 5);
  EXPECT_EQ(s.num_dofs(), (3 + 3) + 5 + (1 + 3) + 5);
  EXPECT_EQ(s.first_element(2), 8);
  EXPECT_EQ(s.first_dof(2), 11);
  EXPECT_EQ(s.segment_of(8), 2);
  EXPECT_EQ(s.index_in_segment(9), 0);
  EXPECT_EQ(s.index_in_segment(12), 3);
  EXPECT_EQ(s.max_local_dofs(), 4);
  // Periodic dofs wrap: element 0 of segment 1 (global 3) has the segment's dofs 2, 3, 4, 0.
  const auto d = s.dofs(3);
  EXPECT_EQ(d[0], 6 + 2);
  EXPECT_EQ(d[3], 6 + 0);
  EXPECT_THROW(SplineCurveSpace(3, {{3, true}}), iga::InputError);
  EXPECT_THROW(SplineCurveSpace(0, {{3, false}}), iga::InputError);
  EXPECT_NO_THROW(SplineCurveSpace(3, {{4, true}}));
}

TEST(SplineCurveSpace, PartitionOfUnityAndDerivatives) {
  const Eigen::VectorXd t = Eigen::VectorXd::LinSpaced(7, 0.0, 1.0);
  for (int p = 1; p <= 4; ++p) {
    const SplineCurveSpace s = mixed(p);
    CurveBasisValues v, vp, vm;
    for (Index e = 0; e < s.num_elements(); ++e) {
      s.evaluate(e, t, 2, v);
      for (Index k = 0; k < t.size(); ++k) {
        EXPECT_NEAR(v.value.col(k).sum(), 1.0, 1e-14) << "p " << p << " e " << e;
        EXPECT_NEAR(v.dt.col(k).sum(), 0.0, 1e-12);
        EXPECT_NEAR(v.dtt.col(k).sum(), 0.0, 1e-11);
        EXPECT_GE(v.value.col(k).minCoeff(), -1e-15);
      }
      // Central differences inside the element (step 1e-5: error ~ h² ‖f'''‖ ≈ 1e-9).
      const double h = 1e-5;
      const Eigen::VectorXd ti = Eigen::VectorXd::LinSpaced(5, 0.1, 0.9);
      s.evaluate(e, ti, 2, v);
      s.evaluate(e, (ti.array() + h).matrix(), 2, vp);
      s.evaluate(e, (ti.array() - h).matrix(), 2, vm);
      EXPECT_LT(((vp.value - vm.value) / (2 * h) - v.dt).cwiseAbs().maxCoeff(), 1e-8);
      if (p >= 2) {
        EXPECT_LT(((vp.dt - vm.dt) / (2 * h) - v.dtt).cwiseAbs().maxCoeff(), 1e-7);
      }
    }
  }
}

TEST(SplineCurveSpace, ClosedFormCubic) {
  // The uniform cubic B-spline pieces on an interior element: (1−t)³/6, (3t³ − 6t² + 4)/6,
  // (−3t³ + 3t² + 3t + 1)/6, t³/6.
  const SplineCurveSpace s(3, {{6, true}});
  CurveBasisValues v;
  const double t = 0.3;
  s.evaluate(2, Eigen::VectorXd::Constant(1, t), 0, v);
  EXPECT_NEAR(v.value(0, 0), std::pow(1 - t, 3) / 6, 1e-15);
  EXPECT_NEAR(v.value(1, 0), (3 * t * t * t - 6 * t * t + 4) / 6, 1e-15);
  EXPECT_NEAR(v.value(2, 0), (-3 * t * t * t + 3 * t * t + 3 * t + 1) / 6, 1e-15);
  EXPECT_NEAR(v.value(3, 0), t * t * t / 6, 1e-15);
}

TEST(SplineCurveSpace, PeriodicWrapIsSmooth) {
  for (int p = 1; p <= 4; ++p) {
    const SplineCurveSpace s(p, {{p + 3, true}});
    const Index last = s.num_elements() - 1;
    CurveBasisValues a, b;
    s.evaluate(last, Eigen::VectorXd::Constant(1, 1.0), 2, a);
    s.evaluate(0, Eigen::VectorXd::Constant(1, 0.0), 2, b);
    // Dof-wise values and derivatives up to order min(p − 1, 2) agree across s = n ≡ 0.
    Eigen::MatrixXd fa = Eigen::MatrixXd::Zero(s.num_dofs(), 3), fb = fa;
    for (int side = 0; side < 2; ++side) {
      const Index e = side == 0 ? last : 0;
      const CurveBasisValues& v = side == 0 ? a : b;
      Eigen::MatrixXd& f = side == 0 ? fa : fb;
      const auto d = s.dofs(e);
      for (std::size_t j = 0; j < d.size(); ++j) {
        f(d[j], 0) += v.value(static_cast<Index>(j), 0);
        f(d[j], 1) += v.dt(static_cast<Index>(j), 0);
        f(d[j], 2) += v.dtt(static_cast<Index>(j), 0);
      }
    }
    for (int r = 0; r <= std::min(p - 1, 2); ++r) {
      EXPECT_LT((fa.col(r) - fb.col(r)).cwiseAbs().maxCoeff(), 1e-12) << "p " << p << " derivative " << r;
    }
  }
}

TEST(SplineCurveSpace, GrevilleReproducesLinearFunctions) {
  for (int p = 1; p <= 4; ++p) {
    const SplineCurveSpace s = mixed(p);
    CurveBasisValues v;
    const Eigen::VectorXd t = Eigen::VectorXd::LinSpaced(5, 0.0, 1.0);
    for (Index k = 0; k < s.num_segments(); ++k) {
      const Eigen::VectorXd g = s.greville(k);
      const double n = static_cast<double>(s.segments()[static_cast<std::size_t>(k)].elements);
      for (Index i = 0; i < s.segments()[static_cast<std::size_t>(k)].elements; ++i) {
        const Index e = s.first_element(k) + i;
        s.evaluate(e, t, 0, v);
        const auto d = s.dofs(e);
        for (Index q = 0; q < t.size(); ++q) {
          const double x = static_cast<double>(i) + t(q);
          double sum = 0.0;
          for (std::size_t j = 0; j < d.size(); ++j) {
            double gj = g(d[j] - s.first_dof(k));
            // periodic: the copy of the abscissa next to x
            if (s.segments()[static_cast<std::size_t>(k)].closed) gj += n * std::round((x - gj) / n);
            sum += gj * v.value(static_cast<Index>(j), q);
          }
          EXPECT_NEAR(sum, x, 1e-13) << "p " << p << " segment " << k;
        }
      }
    }
  }
}
