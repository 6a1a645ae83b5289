#include "basis/catmull_clark/stam.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <memory>
#include <mutex>
#include <string>

#include "basis/catmull_clark/eigen_structure.hpp"
#include "basis/catmull_clark/subdivision_matrix.hpp"
#include "core/error.hpp"

namespace iga::basis::catmull_clark {
namespace {

constexpr int kMaxPoints = 2 * kMaxValence + 8;
// Columns of a tile's nets: the 4×4 value net and its differenced nets, each laid out a + (4 − ds) b for the
// differencing orders (ds, dt) in s and t.
constexpr int kValueColumn = 0;  // (0,0): 16 entries, N3_a(s) N3_b(t)
constexpr int kDuColumn = 16;    // (1,0): 12 entries, N2_a(s) N3_b(t)
constexpr int kDvColumn = 28;    // (0,1): 12 entries, N3_a(s) N2_b(t)
constexpr int kDuuColumn = 40;   // (2,0):  8 entries, N1_a(s) N3_b(t)
constexpr int kDuvColumn = 48;   // (1,1):  9 entries, N2_a(s) N2_b(t)
constexpr int kDvvColumn = 57;   // (0,2):  8 entries, N3_a(s) N1_b(t)
constexpr int kNetColumns = 65;
constexpr std::array<std::array<int, 2>, 6> kOrders = {{{0, 0}, {1, 0}, {0, 1}, {2, 0}, {1, 1}, {0, 2}}};
constexpr std::array<int, 7> kBlockStart = {kValueColumn, kDuColumn,  kDvColumn,  kDuuColumn,
                                            kDuvColumn,   kDvvColumn, kNetColumns};
// A differenced net whose largest entry is below this fraction of the mode's value net is zero (a mode that is
// constant, or linear, in that direction on the tile).
constexpr double kVanishingNet = 1e-12;

using Vec16 = Eigen::Matrix<double, 16, 1>;

// Uniform B-splines of degree 3, 2, 1 on the segment [0,1] (local parameter x).
struct UniformBasis {
  double cubic[4], quadratic[3], linear[2];
  explicit UniformBasis(double x) {
    const double y = 1.0 - x, x2 = x * x, x3 = x2 * x;
    cubic[0] = y * y * y / 6.0;
    cubic[1] = (4.0 - 6.0 * x2 + 3.0 * x3) / 6.0;
    cubic[2] = (1.0 + 3.0 * x + 3.0 * x2 - 3.0 * x3) / 6.0;
    cubic[3] = x3 / 6.0;
    quadratic[0] = 0.5 * y * y;
    quadratic[1] = 0.5 + x - x2;
    quadratic[2] = 0.5 * x2;
    linear[0] = y;
    linear[1] = x;
  }
};

// 65 × 16: rows are the entries of the value net and of the forward-differenced nets (orders kOrders) of a 4×4
// net indexed a + 4b. d/ds sum N3_a P_a = sum N2_a (P_{a+1} − P_a), d²/ds² = sum N1_a (P_{a+2} − 2 P_{a+1} + P_a).
Eigen::MatrixXd net_operator() {
  constexpr double kDiff[3][3] = {{1.0, 0.0, 0.0}, {-1.0, 1.0, 0.0}, {1.0, -2.0, 1.0}};
  Eigen::MatrixXd d = Eigen::MatrixXd::Zero(kNetColumns, 16);
  for (std::size_t o = 0; o < kOrders.size(); ++o) {
    const int ds = kOrders[o][0], dt = kOrders[o][1];
    for (int b = 0; b + dt < 4; ++b) {
      for (int a = 0; a + ds < 4; ++a) {
        for (int y = 0; y <= dt; ++y) {
          for (int x = 0; x <= ds; ++x) {
            d(kBlockStart[o] + a + (4 - ds) * b, (a + x) + 4 * (b + y)) += kDiff[ds][x] * kDiff[dt][y];
          }
        }
      }
    }
  }
  return d;
}

// Outer product basis vectors for the nets: f_a(s) g_b(t) at a + rows_f b.
template <int F, int G>
Eigen::Matrix<double, F * G, 1> tensor(const double (&f)[F], const double (&g)[G]) {
  Eigen::Matrix<double, F * G, 1> out;
  for (int b = 0; b < G; ++b) {
    for (int a = 0; a < F; ++a) out(a + F * b) = f[a] * g[b];
  }
  return out;
}

}  // namespace

StamEvaluator::StamEvaluator(int valence) : n_(valence) {
  check_valence(valence);
  const int np = num_points();
  a_bar_ = catmull_clark::extended_subdivision_matrix(n_);
  a_ = a_bar_.topRows(np);
  EigenStructure eigen = eigen_structure(n_, a_);
  lambda_ = std::move(eigen.values);
  v_ = std::move(eigen.vectors);
  v_inv_ = std::move(eigen.inverse);
  v_inv_t_ = v_inv_.transpose();

  // Limit point (n² EV + 4 sum e_k + sum f_k) / (n (n + 5)) (Halstead et al.; row 0 of V^{-1}).
  const double denominator = static_cast<double>(n_) * (n_ + 5);
  limit_ = Eigen::VectorXd::Zero(np);
  limit_(0) = static_cast<double>(n_) * n_ / denominator;
  for (int k = 0; k < n_; ++k) {
    limit_(2 * k + 1) = 4.0 / denominator;
    limit_(2 * k + 2) = 1.0 / denominator;
  }

  // Mode-space nets of each tile, G_k = (D X^k Ā V)^T, with vanishing differenced nets set to exactly zero.
  const Eigen::MatrixXd d = net_operator();
  for (int k = 0; k < 3; ++k) {
    picking_[k] = catmull_clark::picking_matrix(n_, k + 1);
    const Eigen::MatrixXd g = d * (picking_[k] * a_bar_ * v_);  // 65 × np
    modes_[k] = g.transpose();
    for (int j = 0; j < np; ++j) {
      const double scale = g.block(kValueColumn, j, 16, 1).cwiseAbs().maxCoeff();
      for (std::size_t o = 1; o < kOrders.size(); ++o) {
        auto block = modes_[k].block(j, kBlockStart[o], 1, kBlockStart[o + 1] - kBlockStart[o]);
        if (block.cwiseAbs().maxCoeff() <= kVanishingNet * scale) block.setZero();
      }
    }
  }

  // Cached (tile, level) matrices V^{-T} Λ^{l-1} G_k, derivative blocks times 2^l and 4^l.
  cached_.resize(np, static_cast<Eigen::Index>(kNetColumns) * 3 * kCachedLevels);
  Eigen::VectorXd power = Eigen::VectorXd::Ones(np);  // lambda^(l-1)
  for (int level = 1; level <= kCachedLevels; ++level) {
    for (int k = 0; k < 3; ++k) {
      auto block = cached_.middleCols(static_cast<Eigen::Index>((level - 1) * 3 + k) * kNetColumns, kNetColumns);
      block.noalias() = v_inv_t_ * (power.asDiagonal() * modes_[k]);
      block.middleCols(kDuColumn, kDuuColumn - kDuColumn) *= std::ldexp(1.0, level);
      block.middleCols(kDuuColumn, kNetColumns - kDuuColumn) *= std::ldexp(1.0, 2 * level);
    }
    power = power.cwiseProduct(lambda_);
  }
}

const Eigen::MatrixXd& StamEvaluator::picking_matrix(int tile) const {
  tile_origin(tile);  // validates
  return picking_[tile - 1];
}

StamEvaluator::Tile StamEvaluator::locate(double u, double v) {
  const double m = std::max(u, v);
  if (!(m >= std::ldexp(1.0, -kMaxLevel))) return {};
  int exponent = 0;
  std::frexp(m, &exponent);  // m = f 2^exponent, f in [1/2, 1): m in [2^(exponent-1), 2^exponent)
  const int level = std::max(1, 1 - exponent);
  const double uu = std::ldexp(u, level), vv = std::ldexp(v, level);
  return {level, uu >= 1.0 ? (vv >= 1.0 ? 2 : 1) : 3};
}

template <int Cols>
void StamEvaluator::apply(int tile, int level, int column, const Eigen::Matrix<double, Cols, 1>& basis, double scale,
                          Eigen::Ref<Eigen::VectorXd> out) const {
  if (level <= kCachedLevels) {
    const Eigen::Index offset = static_cast<Eigen::Index>((level - 1) * 3 + tile - 1) * kNetColumns + column;
    out.noalias() = cached_.middleCols<Cols>(offset) * basis;
    return;
  }
  // Deep levels: coefficients of the modes, times lambda^(l-1) and the derivative factor, mapped back by V^{-T}.
  Eigen::Matrix<double, Eigen::Dynamic, 1, 0, kMaxPoints, 1> coefficients(num_points());
  coefficients.noalias() = modes_[tile - 1].middleCols<Cols>(column) * basis;
  for (Eigen::Index j = 0; j < coefficients.size(); ++j) coefficients(j) *= scale * std::pow(lambda_(j), level - 1);
  out.noalias() = v_inv_t_ * coefficients;
}

void StamEvaluator::evaluate_ev(double u, double v, int derivatives, BasisValues& out, Eigen::Index p) const {
  if (n_ == 4) {
    // Regular: the bicubic B-spline of the 4×4 net (i, j) in {-1..2}^2, exact at any (u, v).
    const UniformBasis bu(u), bv(v);
    out.zero_column(p, derivatives);
    // Derivatives of N3 from the differenced form: N3_a' = N2_{a-1} − N2_a, N3_a'' = N1_{a-2} − 2 N1_{a-1} + N1_a.
    const auto d1 = [](const UniformBasis& b, int a) {
      return (a >= 1 ? b.quadratic[a - 1] : 0.0) - (a <= 2 ? b.quadratic[a] : 0.0);
    };
    const auto d2 = [](const UniformBasis& b, int a) {
      return (a >= 2 ? b.linear[a - 2] : 0.0) - 2.0 * (a >= 1 && a <= 2 ? b.linear[a - 1] : 0.0) +
             (a <= 1 ? b.linear[a] : 0.0);
    };
    for (int b = 0; b < 4; ++b) {
      for (int a = 0; a < 4; ++a) {
        const int r = local_index(4, a - 1, b - 1);
        out.value(r, p) = bu.cubic[a] * bv.cubic[b];
        if (derivatives >= 1) {
          out.du(r, p) = d1(bu, a) * bv.cubic[b];
          out.dv(r, p) = bu.cubic[a] * d1(bv, b);
        }
        if (derivatives >= 2) {
          out.duu(r, p) = d2(bu, a) * bv.cubic[b];
          out.duv(r, p) = d1(bu, a) * d1(bv, b);
          out.dvv(r, p) = bu.cubic[a] * d2(bv, b);
        }
      }
    }
    return;
  }
  out.value.col(p) = limit_;
  if (derivatives >= 1) {
    out.du.col(p) = v_inv_.row(1).transpose();
    out.dv.col(p) = v_inv_.row(2).transpose();
  }
  if (derivatives >= 2) {
    out.duu.col(p).setZero();
    out.duv.col(p).setZero();
    out.dvv.col(p).setZero();
  }
}

void StamEvaluator::evaluate(const Eigen::Matrix2Xd& pts, int derivatives, BasisValues& out) const {
  if (derivatives < 0 || derivatives > 2) {
    throw InputError("catmull_clark: derivatives must be 0, 1 or 2, not " + std::to_string(derivatives));
  }
  const Eigen::Index q = pts.cols(), np = num_points();
  out.resize(np, q, derivatives);
  for (Eigen::Index p = 0; p < q; ++p) {
    const double u = pts(0, p), v = pts(1, p);
    if (!(u >= 0.0 && u <= 1.0 && v >= 0.0 && v <= 1.0)) {
      throw InputError("catmull_clark: evaluation point (" + std::to_string(u) + ", " + std::to_string(v) +
                       ") is outside [0,1]^2");
    }
    const Tile at = locate(u, v);
    if (at.level == 0) {
      evaluate_ev(u, v, derivatives, out, p);
      continue;
    }
    // t_{k,l}: the tile mapped to the unit square (exact in floating point).
    const double uu = std::ldexp(u, at.level), vv = std::ldexp(v, at.level);
    const UniformBasis bs(at.tile == 3 ? uu : uu - 1.0), bt(at.tile == 1 ? vv : vv - 1.0);
    apply<16>(at.tile, at.level, kValueColumn, tensor(bs.cubic, bt.cubic), 1.0, out.value.col(p));
    if (derivatives >= 1) {
      const double scale = std::ldexp(1.0, at.level);
      apply<12>(at.tile, at.level, kDuColumn, tensor(bs.quadratic, bt.cubic), scale, out.du.col(p));
      apply<12>(at.tile, at.level, kDvColumn, tensor(bs.cubic, bt.quadratic), scale, out.dv.col(p));
    }
    if (derivatives >= 2) {
      const double scale = std::ldexp(1.0, 2 * at.level);
      apply<8>(at.tile, at.level, kDuuColumn, tensor(bs.linear, bt.cubic), scale, out.duu.col(p));
      apply<9>(at.tile, at.level, kDuvColumn, tensor(bs.quadratic, bt.quadratic), scale, out.duv.col(p));
      apply<8>(at.tile, at.level, kDvvColumn, tensor(bs.cubic, bt.linear), scale, out.dvv.col(p));
    }
  }
}

const StamEvaluator& stam_evaluator(int valence) {
  check_valence(valence);
  static std::array<std::once_flag, kMaxValence + 1> built;
  static std::array<std::unique_ptr<const StamEvaluator>, kMaxValence + 1> evaluators;
  const auto index = static_cast<std::size_t>(valence);
  std::call_once(built[index], [&] { evaluators[index] = std::make_unique<const StamEvaluator>(valence); });
  return *evaluators[index];
}

}  // namespace iga::basis::catmull_clark
