#include "basis/polyhedral/bezier.hpp"

#include <algorithm>
#include <string>

#include "basis/bspline/bernstein.hpp"
#include "core/error.hpp"

namespace iga::basis::polyhedral {

PatchMask regular_mask() {
  // Grid position (i, j) of each gathered vertex [v, e_0, f_0, e_1, f_1, e_2, f_2, e_3, f_3].
  const int gi[9] = {1, 2, 2, 1, 0, 0, 0, 1, 2};
  const int gj[9] = {1, 1, 2, 2, 2, 1, 0, 0, 0};
  // Per direction: BB coefficient k from B-spline control points c_0..c_2 (uniform quadratic, middle piece).
  Eigen::Matrix3d m;
  m << 0.5, 0.5, 0.0,  //
      0.0, 1.0, 0.0,   //
      0.0, 0.5, 0.5;
  PatchMask mask;
  mask.degree_u = 2;
  mask.degree_v = 2;
  mask.coefficients = Eigen::MatrixXd::Zero(9, 9);
  for (int j = 0; j < 3; ++j) {
    for (int i = 0; i < 3; ++i) {
      for (int c = 0; c < 9; ++c) mask.coefficients(3 * j + i, c) = m(i, gi[c]) * m(j, gj[c]);
    }
  }
  return mask;
}

Eigen::MatrixXd elevation_matrix(int p, int q) {
  if (p < 0 || q < p) throw InputError("elevation_matrix: cannot raise degree " + std::to_string(p) + " to " + std::to_string(q));
  Eigen::MatrixXd e = Eigen::MatrixXd::Identity(p + 1, p + 1);
  for (int d = p; d < q; ++d) {
    Eigen::MatrixXd step = Eigen::MatrixXd::Zero(d + 2, d + 1);
    for (int i = 0; i <= d + 1; ++i) {
      const double a = static_cast<double>(i) / (d + 1);
      if (i >= 1) step(i, i - 1) = a;
      if (i <= d) step(i, i) = 1.0 - a;
    }
    e = step * e;
  }
  return e;
}

namespace {

Eigen::MatrixXd elevate_rows(const Eigen::MatrixXd& c, int du, int dv, int tu, int tv) {
  if (c.rows() != (du + 1) * (dv + 1)) {
    throw InputError("elevate: " + std::to_string(c.rows()) + " coefficients do not fit degree (" + std::to_string(du) +
                     ", " + std::to_string(dv) + ")");
  }
  const Eigen::MatrixXd eu = elevation_matrix(du, tu);
  const Eigen::MatrixXd ev = elevation_matrix(dv, tv);
  Eigen::MatrixXd out = Eigen::MatrixXd::Zero((tu + 1) * (tv + 1), c.cols());
  // Row j·(du+1)+i → j'·(tu+1)+i' with weight ev(j', j) eu(i', i) (kron(ev, eu)).
  for (int j2 = 0; j2 <= tv; ++j2) {
    for (int i2 = 0; i2 <= tu; ++i2) {
      for (int j = 0; j <= dv; ++j) {
        for (int i = 0; i <= du; ++i) {
          const double w = ev(j2, j) * eu(i2, i);
          if (w != 0.0) out.row(j2 * (tu + 1) + i2) += w * c.row(j * (du + 1) + i);
        }
      }
    }
  }
  return out;
}

}  // namespace

BezierPatch elevate(const BezierPatch& patch, int target_u, int target_v) {
  return {target_u, target_v, elevate_rows(patch.coefficients, patch.degree_u, patch.degree_v, target_u, target_v)};
}

PatchMask elevate(const PatchMask& mask, int target_u, int target_v) {
  PatchMask out;
  out.degree_u = target_u;
  out.degree_v = target_v;
  out.coefficients = elevate_rows(mask.coefficients, mask.degree_u, mask.degree_v, target_u, target_v);
  return out;
}

Eigen::MatrixXd bernstein_tensor(int degree_u, int degree_v, const Eigen::Matrix2Xd& pts, int order_u, int order_v) {
  if (order_u < 0 || order_u > 2 || order_v < 0 || order_v > 2) throw InputError("bernstein_tensor: derivative orders are 0..2");
  Eigen::MatrixXd bu[3], bv[3];
  const Eigen::RowVectorXd u = pts.row(0), v = pts.row(1);
  bspline::bernstein(degree_u, u, order_u, bu[0], &bu[1], &bu[2]);
  bspline::bernstein(degree_v, v, order_v, bv[0], &bv[1], &bv[2]);
  const Eigen::MatrixXd& a = bu[order_u];
  const Eigen::MatrixXd& b = bv[order_v];
  Eigen::MatrixXd out((degree_u + 1) * (degree_v + 1), pts.cols());
  for (int j = 0; j <= degree_v; ++j) {
    for (int i = 0; i <= degree_u; ++i) out.row(j * (degree_u + 1) + i) = a.row(i).cwiseProduct(b.row(j));
  }
  return out;
}

PatchValues evaluate(const BezierPatch& patch, const Eigen::Matrix2Xd& pts, int derivatives) {
  if (patch.coefficients.rows() != (patch.degree_u + 1) * (patch.degree_v + 1)) {
    throw InputError("evaluate: the patch's coefficient count does not fit its degree");
  }
  auto eval = [&](int ou, int ov) -> Eigen::MatrixXd {
    return bernstein_tensor(patch.degree_u, patch.degree_v, pts, ou, ov).transpose() * patch.coefficients;
  };
  PatchValues r;
  r.x = eval(0, 0);
  if (derivatives >= 1) {
    r.xu = eval(1, 0);
    r.xv = eval(0, 1);
  }
  if (derivatives >= 2) {
    r.xuu = eval(2, 0);
    r.xuv = eval(1, 1);
    r.xvv = eval(0, 2);
  }
  return r;
}

}  // namespace iga::basis::polyhedral
