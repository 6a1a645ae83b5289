#include "basis/half_box/irregular_patch.hpp"

#include <cmath>
#include <string>

#include "basis/half_box/patch_net.hpp"
#include "basis/half_box/regular_patch.hpp"
#include "basis/half_box/subdivision_structure.hpp"
#include "core/error.hpp"

namespace iga::basis::half_box {

namespace {

void check_point(double u, double v) {
  constexpr double kTol = 1e-12;
  if (!(u >= -kTol && v >= -kTol && u + v <= 1.0 + kTol))
    throw InputError("half-box patch: point (" + std::to_string(u) + ", " + std::to_string(v) +
                     ") is outside the reference triangle");
}

// Column p of `out` at the EF corner: limit and tangent stencils.
void corner_column(const SubdivisionStructure& s, Eigen::Index p, int derivatives, BasisValues& out) {
  out.value.col(p) = s.limit_stencil.transpose();
  if (derivatives >= 1) {
    out.du.col(p) = s.tangent_stencils.row(0).transpose();
    out.dv.col(p) = s.tangent_stencils.row(1).transpose();
  }
}

}  // namespace

void evaluate_irregular(int valence, const Eigen::Matrix2Xd& uv, int derivatives, BasisValues& out) {
  if (derivatives < 0 || derivatives > 2)
    throw InputError("half-box evaluate_irregular: derivatives must be 0, 1 or 2, got " + std::to_string(derivatives));
  const SubdivisionStructure& s = subdivision_structure(valence);
  const Eigen::Index q = uv.cols();
  out.resize(patch_size(valence), q, derivatives);
  BernsteinValues b;
  Eigen::Matrix<double, kBezierSize, 1> bs, bt;
  Eigen::Matrix<double, kRegularPatchSize, 1> hss, hst, htt;
  for (Eigen::Index p = 0; p < q; ++p) {
    const double u = std::max(uv(0, p), 0.0), v = std::max(uv(1, p), 0.0);
    check_point(uv(0, p), uv(1, p));
    const double sum = u + v;
    int e = 0;
    std::frexp(sum, &e);
    const int layer = std::max(1, 1 - e);
    if (sum == 0.0 || layer > kCachedLayers) {
      if (derivatives >= 2)
        throw NumericalError("half-box EF patch: second derivatives do not exist at the extraordinary corner (0,0)"
                             " (point within 2^-64 of it)");
      corner_column(s, p, derivatives, out);
      continue;
    }
    // (3.40): scale to layer 1, pick the tile, map it to the reference triangle of its regular patch; the tile
    // operator acts on the Bernstein values directly (bezier_operator = tile_operator^T · bezier_matrix()^T).
    const double ul = std::ldexp(u, layer - 1), vl = std::ldexp(v, layer - 1);
    const int k = tile_of(ul, vl);
    const TileMap& t = s.tiles[static_cast<std::size_t>(k)];
    const Eigen::Vector2d x = t.jacobian * Eigen::Vector2d(ul, vl) + t.offset;
    bernstein_cubic(x(0), x(1), derivatives, b);
    out.value.col(p).noalias() = s.bezier_operator(k, layer, false) * b.value;
    if (derivatives == 0) continue;
    const auto& op = s.bezier_operator(k, layer, true);
    const Eigen::Matrix2d& j = t.jacobian;
    const double f = std::ldexp(1.0, layer - 1);
    bs.noalias() = f * (j(0, 0) * b.du + j(1, 0) * b.dv);
    bt.noalias() = f * (j(0, 1) * b.du + j(1, 1) * b.dv);
    out.du.col(p).noalias() = op * bs;
    out.dv.col(p).noalias() = op * bt;
    if (derivatives >= 2) {
      // Second derivatives keep the two-stage product: their summands grow like 4^(l−1) against a result of
      // order 2^(l−1), so regrouping would change them by more than 1e-15 at deep layers (both are rounding).
      const auto mt = bezier_matrix().transpose();
      hss.noalias() = mt * b.duu;
      hst.noalias() = mt * b.duv;
      htt.noalias() = mt * b.dvv;
      const double f2 = f * f;
      // Hessian in (u, v) = J^T H J.
      auto second = [&](int a, int c) -> Eigen::Matrix<double, kRegularPatchSize, 1> {
        return f2 * (j(0, a) * j(0, c) * hss + (j(0, a) * j(1, c) + j(1, a) * j(0, c)) * hst + j(1, a) * j(1, c) * htt);
      };
      const Eigen::MatrixXd& op2 = s.tile_operator(k, layer, true);
      out.duu.col(p).noalias() = op2.transpose() * second(0, 0);
      out.duv.col(p).noalias() = op2.transpose() * second(0, 1);
      out.dvv.col(p).noalias() = op2.transpose() * second(1, 1);
    }
  }
}

void evaluate_patch(int valence, const Eigen::Matrix2Xd& uv, int derivatives, BasisValues& out) {
  if (valence == 6)
    evaluate_regular(uv, derivatives, out);
  else
    evaluate_irregular(valence, uv, derivatives, out);
}

}  // namespace iga::basis::half_box
