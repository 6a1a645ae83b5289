#include "basis/catmull_clark/regular_patch.hpp"

#include <array>
#include <stdexcept>

namespace iga::basis::catmull_clark {

namespace {

// Uniform cubic B-spline pieces on [0,1] and their first two derivatives.
inline void cubic(double t, double n[4], double d1[4], double d2[4]) {
  const double s = 1.0 - t, t2 = t * t, t3 = t2 * t;
  n[0] = s * s * s / 6.0;
  n[1] = (3.0 * t3 - 6.0 * t2 + 4.0) / 6.0;
  n[2] = (-3.0 * t3 + 3.0 * t2 + 3.0 * t + 1.0) / 6.0;
  n[3] = t3 / 6.0;
  d1[0] = -0.5 * s * s;
  d1[1] = 1.5 * t2 - 2.0 * t;
  d1[2] = -1.5 * t2 + t + 0.5;
  d1[3] = 0.5 * t2;
  d2[0] = s;
  d2[1] = 3.0 * t - 2.0;
  d2[2] = -3.0 * t + 1.0;
  d2[3] = t;
}

// The three grid points a corner owns, in the frame of corner 0: (-1,0), (-1,-1), (0,-1); rotated by
// (x, y) -> (1 - y, x) for each further corner.
std::array<int, 2> rotate(int x, int y, int times) {
  for (int k = 0; k < times; ++k) {
    const int nx = 1 - y, ny = x;
    x = nx;
    y = ny;
  }
  return {x, y};
}

}  // namespace

void bicubic_values(const Eigen::Matrix2Xd& pts, int derivatives, double scale, BasisValues& out) {
  const Eigen::Index q = pts.cols();
  out.value.resize(16, q);
  if (derivatives >= 1) {
    out.du.resize(16, q);
    out.dv.resize(16, q);
  }
  if (derivatives >= 2) {
    out.duu.resize(16, q);
    out.duv.resize(16, q);
    out.dvv.resize(16, q);
  }
  const double s2 = scale * scale;
  for (Eigen::Index p = 0; p < q; ++p) {
    double nu[4], du[4], ddu[4], nv[4], dv[4], ddv[4];
    cubic(pts(0, p), nu, du, ddu);
    cubic(pts(1, p), nv, dv, ddv);
    for (int b = 0; b < 4; ++b) {
      for (int a = 0; a < 4; ++a) {
        const int r = a + 4 * b;
        out.value(r, p) = nu[a] * nv[b];
        if (derivatives >= 1) {
          out.du(r, p) = scale * du[a] * nv[b];
          out.dv(r, p) = scale * nu[a] * dv[b];
        }
        if (derivatives >= 2) {
          out.duu(r, p) = s2 * ddu[a] * nv[b];
          out.duv(r, p) = s2 * du[a] * dv[b];
          out.dvv(r, p) = s2 * nu[a] * ddv[b];
        }
      }
    }
  }
}

bool is_regular_corner(const QuadMesh& m, int h) {
  const int g1 = m.ccw(h), g3 = m.cw(h);
  if (g1 >= 0 && g3 >= 0) {
    const int g2 = m.ccw(g1);
    return g2 >= 0 && g2 != g3 && g2 != h && m.ccw(g2) == g3 && m.ccw(g3) == h;
  }
  if (g1 >= 0) return m.ccw(g1) < 0;
  if (g3 >= 0) return m.cw(g3) < 0;
  return true;  // a corner: the face alone
}

std::array<int, 3> corner_outer_points(const QuadMesh& m, int h) {
  const int g1 = m.ccw(h), g3 = m.cw(h);
  const int g2 = g1 >= 0 ? m.ccw(g1) : -1;
  return {g1 >= 0 ? m.origin(QuadMesh::prev(g1)) : -1, g2 >= 0 ? m.origin(QuadMesh::next(QuadMesh::next(g2))) : -1,
          g3 >= 0 ? m.target(g3) : -1};
}

Eigen::MatrixXd grid_operator(const QuadMesh& m, int face, int rotation) {
  Eigen::MatrixXd w = Eigen::MatrixXd::Zero(16, m.num_vertices);
  std::array<bool, 16> present{};
  auto set = [&](int i, int j, int v) {
    w(grid_index(i, j), v) = 1.0;
    present[static_cast<std::size_t>(grid_index(i, j))] = true;
  };
  static constexpr int corner_xy[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  for (int i = 0; i < 4; ++i) {
    const int h = 4 * face + (i + rotation) % 4;
    if (!is_regular_corner(m, h)) throw std::logic_error("catmull_clark::grid_operator: irregular corner");
    set(corner_xy[i][0], corner_xy[i][1], m.origin(h));
    const std::array<int, 3> outer = corner_outer_points(m, h);
    static constexpr int frame[3][2] = {{-1, 0}, {-1, -1}, {0, -1}};
    for (int k = 0; k < 3; ++k) {
      if (outer[static_cast<std::size_t>(k)] < 0) continue;
      const auto g = rotate(frame[k][0], frame[k][1], i);
      set(g[0], g[1], outer[static_cast<std::size_t>(k)]);
    }
  }
  auto has = [&](int i, int j) { return present[static_cast<std::size_t>(grid_index(i, j))]; };
  auto extrapolate = [&](int i, int j, int i0, int j0, int i1, int j1) {
    w.row(grid_index(i, j)) = 2.0 * w.row(grid_index(i0, j0)) - w.row(grid_index(i1, j1));
    present[static_cast<std::size_t>(grid_index(i, j))] = true;
  };
  for (int j = -1; j <= 2; ++j) {  // rows: across the sides u = 0 and u = 1
    if (!has(-1, j) && has(0, j) && has(1, j)) extrapolate(-1, j, 0, j, 1, j);
    if (!has(2, j) && has(1, j) && has(0, j)) extrapolate(2, j, 1, j, 0, j);
  }
  for (int i = -1; i <= 2; ++i) {  // columns: across v = 0 and v = 1
    if (!has(i, -1) && has(i, 0) && has(i, 1)) extrapolate(i, -1, i, 0, i, 1);
    if (!has(i, 2) && has(i, 1) && has(i, 0)) extrapolate(i, 2, i, 1, i, 0);
  }
  for (bool p : present) {
    if (!p) throw std::logic_error("catmull_clark::grid_operator: grid point missing after extrapolation");
  }
  return w;
}

}  // namespace iga::basis::catmull_clark
