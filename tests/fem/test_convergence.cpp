// fem::ConvergenceTable: rates between levels and the least-squares rate, against closed-form error sequences.
#include <gtest/gtest.h>

#include <cmath>

#include "core/error.hpp"
#include "fem/convergence.hpp"

using iga::fem::ConvergenceRow;
using iga::fem::ConvergenceTable;

TEST(ConvergenceTable, ExactPowerLawGivesItsExponent) {
  // e = 3 h^2.5 and 0.5 h^1.5 on h = 2^-k, N = (2^k + 2)^2: every rate against h is the exponent (closed form).
  ConvergenceTable t({"L2", "H1"});
  for (int k = 1; k <= 4; ++k) {
    const double h = std::pow(2.0, -k);
    const double n = std::pow(std::pow(2.0, k) + 2.0, 2);
    t.add_row({k, static_cast<iga::Index>(n), 1 << (2 * k), h, {3.0 * std::pow(h, 2.5), 0.5 * std::pow(h, 1.5)}, 0.0});
  }
  const auto l2 = t.rates(0), h1 = t.rates(1);
  EXPECT_FALSE(l2[0].has_value());
  for (int k = 1; k < 4; ++k) {
    EXPECT_NEAR(*l2[k], 2.5, 1e-12);
    EXPECT_NEAR(*h1[k], 1.5, 1e-12);
  }
  EXPECT_NEAR(*t.fitted_rate(0), 2.5, 1e-12);
  EXPECT_NEAR(*t.fitted_rate(1), 1.5, 1e-12);
  // Against N^(-1/2) = 1/(2^k + 2): log(e_{k-1}/e_k) / log(N_k/N_{k-1})^(1/2), here between levels 1 and 2:
  // 2.5 log 2 / log(6/4).
  EXPECT_NEAR(*t.rates(0, ConvergenceTable::Against::dofs)[1], 2.5 * std::log(2.0) / std::log(1.5), 1e-12);
  EXPECT_NE(t.text().find("fitted rate (least squares over 4 levels): L2 2.500 H1 1.500"), std::string::npos) << t.text();
}

TEST(ConvergenceTable, LeastSquaresSlope) {
  // log e = 2 log h + d_k, d = (0, 0.3, 0, 0.3), h_k = 2^-k, k = 0..3 (closed form below).
  ConvergenceTable t({"L2"});
  const double d[4] = {0.0, 0.3, 0.0, 0.3};
  for (int k = 0; k < 4; ++k) {
    const double h = std::pow(2.0, -k);
    t.add_row({k, 4, 1, h, {std::pow(h, 2.0) * std::exp(d[k])}, 0.0});
  }
  // X - X̄ = (1.5, 0.5, -0.5, -1.5) log 2; Σ(X - X̄) d = 0.3 (0.5 - 1.5) log 2 = -0.3 log 2; Σ(X - X̄)² = 5 log² 2.
  // Slope in log e over log h: 2 + (-0.3 log 2) / (5 log² 2) = 2 - 0.06 / log 2.
  EXPECT_NEAR(*t.fitted_rate(0), 2.0 - 0.06 / std::log(2.0), 1e-12);
}

TEST(ConvergenceTable, ZeroErrorHasNoRateAndBadRowsAreRefused) {
  ConvergenceTable t({"L2"});
  t.add_row({0, 4, 1, 1.0, {0.0}, 0.0});
  t.add_row({1, 9, 4, 0.5, {0.0}, 0.0});
  EXPECT_FALSE(t.rates(0)[1].has_value());
  EXPECT_FALSE(t.fitted_rate(0).has_value());
  EXPECT_THROW(t.add_row({2, 9, 4, 0.5, {1.0, 2.0}, 0.0}), iga::InputError);
  EXPECT_THROW(t.add_row({2, 9, 4, 0.0, {1.0}, 0.0}), iga::InputError);
  EXPECT_THROW(t.add_row({2, 9, 4, 0.5, {NAN}, 0.0}), iga::InputError);
}
