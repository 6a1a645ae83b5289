#include "basis/half_box/regular_patch.hpp"

#include "core/error.hpp"

namespace iga::basis::half_box {

namespace {

// BB coefficients of the pieces of H111 on U(0,0), in sixths. Derived by directional convolution (2.23) of
// the indicator of the up triangle along (1,0), (0,1), (1,-1) and fitting the cubic on each piece (exact
// rationals with denominator 6; thesis Figure 2.24 shows the same stencils). Rows: BB order, columns: the 13.
constexpr int kSixths[kBezierSize][kRegularPatchSize] = {
    {1, 1, 0, 1, 1, 1, 1, 0, 0, 0, 0, 0, 0},  // 300: mean of F0
    {2, 2, 0, 1, 0, 0, 1, 0, 0, 0, 0, 0, 0},  // 210
    {2, 1, 0, 2, 1, 0, 0, 0, 0, 0, 0, 0, 0},  // 201
    {2, 2, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 0},  // 120
    {3, 1, 1, 1, 0, 0, 0, 0, 0, 0, 0, 0, 0},  // 111
    {2, 0, 1, 2, 0, 0, 0, 0, 0, 0, 0, 0, 1},  // 102
    {1, 1, 1, 0, 0, 0, 0, 1, 1, 1, 0, 0, 0},  // 030: mean of F1
    {2, 1, 2, 0, 0, 0, 0, 0, 0, 1, 0, 0, 0},  // 021
    {2, 0, 2, 1, 0, 0, 0, 0, 0, 0, 1, 0, 0},  // 012
    {1, 0, 1, 1, 0, 0, 0, 0, 0, 0, 1, 1, 1},  // 003: mean of F2
};

// Multi-indices (i, j, k) of λ0^i λ1^j λ2^k in BB order.
constexpr int kIndex[kBezierSize][3] = {{3, 0, 0}, {2, 1, 0}, {2, 0, 1}, {1, 2, 0}, {1, 1, 1},
                                        {1, 0, 2}, {0, 3, 0}, {0, 2, 1}, {0, 1, 2}, {0, 0, 3}};

// x^e for e >= 0 (0 for e < 0).
double power(double x, int e) {
  double r = 1.0;
  if (e < 0) return 0.0;
  for (int i = 0; i < e; ++i) r *= x;
  return r;
}

double factorial(int e) { return e <= 1 ? 1.0 : (e == 2 ? 2.0 : 6.0); }

}  // namespace

const Eigen::Matrix<double, kBezierSize, kRegularPatchSize>& bezier_matrix() {
  static const Eigen::Matrix<double, kBezierSize, kRegularPatchSize> m = [] {
    Eigen::Matrix<double, kBezierSize, kRegularPatchSize> r;
    for (int i = 0; i < kBezierSize; ++i)
      for (int j = 0; j < kRegularPatchSize; ++j) r(i, j) = kSixths[i][j] / 6.0;
    return r;
  }();
  return m;
}

void bernstein_cubic(double u, double v, int derivatives, BernsteinValues& out) {
  // B_ijk = 6/(i! j! k!) λ0^i λ1^j λ2^k with λ0 = 1 − u − v, λ1 = u, λ2 = v; d/du = −∂0 + ∂1, d/dv = −∂0 + ∂2.
  const double l[3] = {1.0 - u - v, u, v};
  for (int b = 0; b < kBezierSize; ++b) {
    const int* e = kIndex[b];
    const double c = 6.0 / (factorial(e[0]) * factorial(e[1]) * factorial(e[2]));
    // p(a0, a1, a2) = c · Π λ_m^(e_m − a_m) · e_m!/(e_m − a_m)!: the partial derivative ∂0^a0 ∂1^a1 ∂2^a2.
    auto partial = [&](int a0, int a1, int a2) {
      const int a[3] = {a0, a1, a2};
      double r = c;
      for (int m = 0; m < 3; ++m) {
        if (a[m] > e[m]) return 0.0;
        r *= power(l[m], e[m] - a[m]) * factorial(e[m]) / factorial(e[m] - a[m]);
      }
      return r;
    };
    out.value(b) = partial(0, 0, 0);
    if (derivatives >= 1) {
      const double p0 = partial(1, 0, 0);
      out.du(b) = partial(0, 1, 0) - p0;
      out.dv(b) = partial(0, 0, 1) - p0;
    }
    if (derivatives >= 2) {
      const double p00 = partial(2, 0, 0);
      out.duu(b) = partial(0, 2, 0) - 2.0 * partial(1, 1, 0) + p00;
      out.dvv(b) = partial(0, 0, 2) - 2.0 * partial(1, 0, 1) + p00;
      out.duv(b) = partial(0, 1, 1) - partial(1, 1, 0) - partial(1, 0, 1) + p00;
    }
  }
}

void evaluate_regular(const Eigen::Matrix2Xd& uv, int derivatives, BasisValues& out) {
  if (derivatives < 0 || derivatives > 2)
    throw InputError("half-box evaluate_regular: derivatives must be 0, 1 or 2, got " + std::to_string(derivatives));
  const Eigen::Index q = uv.cols();
  out.resize(kRegularPatchSize, q, derivatives);
  const auto mt = bezier_matrix().transpose();
  BernsteinValues b;
  for (Eigen::Index p = 0; p < q; ++p) {
    bernstein_cubic(uv(0, p), uv(1, p), derivatives, b);
    out.value.col(p).noalias() = mt * b.value;
    if (derivatives >= 1) {
      out.du.col(p).noalias() = mt * b.du;
      out.dv.col(p).noalias() = mt * b.dv;
    }
    if (derivatives >= 2) {
      out.duu.col(p).noalias() = mt * b.duu;
      out.duv.col(p).noalias() = mt * b.duv;
      out.dvv.col(p).noalias() = mt * b.dvv;
    }
  }
}

}  // namespace iga::basis::half_box
