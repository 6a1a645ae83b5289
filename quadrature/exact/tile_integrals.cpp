#include "quadrature/exact/tile_integrals.hpp"

#include <array>

#include "core/error.hpp"
#include "quadrature/gauss_legendre.hpp"

namespace iga::quadrature::exact {

namespace {

// Order-th derivative (0..2) of the uniform cubic B-splines N_0..N_3 on [0,1] at t.
std::array<double, 4> bspline1d(double t, int order) {
  const double r = 1.0 - t;
  switch (order) {
    case 0: return {r * r * r / 6, (3 * t * t * t - 6 * t * t + 4) / 6, (-3 * t * t * t + 3 * t * t + 3 * t + 1) / 6,
                    t * t * t / 6};
    case 1: return {-r * r / 2, (3 * t * t - 4 * t) / 2, (-3 * t * t + 2 * t + 1) / 2, t * t / 2};
    case 2: return {r, 3 * t - 2, -3 * t + 1, t};
    default: throw InputError("bspline1d: order must be 0, 1 or 2");
  }
}

// Derivative orders (along u, along v) of a factor; second-derivative codes 10 + d (d: 0 uu, 1 uv, 2 vv).
std::array<int, 2> orders(int f) {
  switch (f) {
    case -1: return {0, 0};
    case 0: return {1, 0};
    case 1: return {0, 1};
    case 10: return {2, 0};
    case 11: return {1, 1};
    case 12: return {0, 2};
    default: throw InputError("tile integrals: factor must be -1 (value), 0 (d/du) or 1 (d/dv)");
  }
}

// 1D tables: values of the order-o derivatives at the Gauss points.
struct Table1D {
  Rule1D rule = gauss_legendre(6);
  Eigen::Matrix<double, 4, Eigen::Dynamic> at(int order) const {
    Eigen::Matrix<double, 4, Eigen::Dynamic> m(4, rule.size());
    for (Eigen::Index q = 0; q < rule.size(); ++q) {
      const auto b = bspline1d(rule.points(q), order);
      for (int a = 0; a < 4; ++a) m(a, q) = b[static_cast<std::size_t>(a)];
    }
    return m;
  }
};

const Table1D& table() {
  static const Table1D t;
  return t;
}

// ∫ of products of 1D factors of the given orders: k = 1, 2, 3 factors; indexed a + 4 b + 16 c.
Eigen::VectorXd integrals1d(const std::vector<int>& ord) {
  const Table1D& t = table();
  std::vector<Eigen::Matrix<double, 4, Eigen::Dynamic>> m;
  for (int o : ord) m.push_back(t.at(o));
  int size = 1;
  for (std::size_t i = 0; i < ord.size(); ++i) size *= 4;
  Eigen::VectorXd out = Eigen::VectorXd::Zero(size);
  for (int idx = 0; idx < size; ++idx) {
    for (Eigen::Index q = 0; q < t.rule.size(); ++q) {
      double p = t.rule.weights(q);
      int rest = idx;
      for (std::size_t i = 0; i < ord.size(); ++i) {
        p *= m[i](rest % 4, q);
        rest /= 4;
      }
      out(idx) += p;
    }
  }
  return out;
}

}  // namespace

Eigen::VectorXd tile_integral(Factor f) {
  const auto o = orders(f);
  const Eigen::VectorXd iu = integrals1d({o[0]}), iv = integrals1d({o[1]});
  Eigen::VectorXd out(16);
  for (int a = 0; a < 4; ++a)
    for (int b = 0; b < 4; ++b) out(a + 4 * b) = iu(a) * iv(b);
  return out;
}

namespace {

Eigen::MatrixXd gram_codes(int f, int g) {
  const auto of = orders(f), og = orders(g);
  const Eigen::VectorXd iu = integrals1d({of[0], og[0]}), iv = integrals1d({of[1], og[1]});
  Eigen::MatrixXd out(16, 16);
  for (int a1 = 0; a1 < 4; ++a1)
    for (int b1 = 0; b1 < 4; ++b1)
      for (int a2 = 0; a2 < 4; ++a2)
        for (int b2 = 0; b2 < 4; ++b2) out(a1 + 4 * b1, a2 + 4 * b2) = iu(a1 + 4 * a2) * iv(b1 + 4 * b2);
  return out;
}

}  // namespace

Eigen::MatrixXd tile_gram(Factor f, Factor g) {
  if (f < -1 || f > 1 || g < -1 || g > 1) throw InputError("tile_gram: factors must be -1, 0 or 1");
  return gram_codes(f, g);
}

Eigen::MatrixXd tile_gram2(int d, int e) {
  if (d < 0 || d > 2 || e < 0 || e > 2) throw InputError("tile_gram2: second derivatives are 0 (uu), 1 (uv), 2 (vv)");
  return gram_codes(10 + d, 10 + e);
}

Tensor3 tile_triple(Factor f, Factor g, Factor h) {
  if (f < -1 || f > 1 || g < -1 || g > 1 || h < -1 || h > 1) throw InputError("tile_triple: factors must be -1, 0 or 1");
  const auto of = orders(f), og = orders(g), oh = orders(h);
  const Eigen::VectorXd iu = integrals1d({of[0], og[0], oh[0]}), iv = integrals1d({of[1], og[1], oh[1]});
  Tensor3 out(16, Eigen::MatrixXd(16, 16));
  for (int i = 0; i < 16; ++i)
    for (int j = 0; j < 16; ++j)
      for (int k = 0; k < 16; ++k)
        out[static_cast<std::size_t>(i)](j, k) =
            iu(i % 4 + 4 * (j % 4) + 16 * (k % 4)) * iv(i / 4 + 4 * (j / 4) + 16 * (k / 4));
  return out;
}

}  // namespace iga::quadrature::exact
