#include "io/bezier_hanging.hpp"

#include <algorithm>
#include <cmath>

#include "core/error.hpp"

namespace iga::io {

namespace {

bool whole_side(double t0, double t1) { return std::abs(std::abs(t1 - t0) - 1.0) < 1e-12; }

/// Rows of `points` (control points of a degree-(rows − 1) Bézier curve) evaluated at t by de Casteljau.
Eigen::RowVectorXd de_casteljau(Eigen::MatrixXd points, double t) {
  for (Eigen::Index r = points.rows() - 1; r > 0; --r) {
    for (Eigen::Index i = 0; i < r; ++i) points.row(i) = (1.0 - t) * points.row(i) + t * points.row(i + 1);
  }
  return points.row(0);
}

/// The degree-d Bézier control points (rows) of the curve f on [0, 1] from its values at d + 1 equispaced
/// parameters (exact when f is a polynomial of degree <= d, as a restricted, degree-raised Bézier curve is).
Eigen::MatrixXd bezier_from_values(const Eigen::MatrixXd& values) {
  const auto d = static_cast<int>(values.rows()) - 1;
  Eigen::MatrixXd b(d + 1, d + 1);
  for (int k = 0; k <= d; ++k) {
    const double t = static_cast<double>(k) / d;
    for (int i = 0; i <= d; ++i) {
      double binomial = 1.0;
      for (int m = 1; m <= i; ++m) binomial = binomial * (d - i + m) / m;
      b(k, i) = binomial * std::pow(t, i) * std::pow(1.0 - t, d - i);
    }
  }
  return b.partialPivLu().solve(values);
}

}  // namespace

std::vector<HangingSide> hanging_sides(const basis::Space& space, std::vector<int>& degree) {
  bool any = false;
  for (Index e = 0; e < space.num_elements() && !any; ++e) any = !space.polynomial_degree(e).has_value();
  if (!any) return {};
  std::vector<basis::InteriorEdge> edges;
  try {
    edges = space.interior_edges();
  } catch (const UnsupportedError&) {
    return {};
  }
  std::vector<HangingSide> out;
  for (const basis::InteriorEdge& ie : edges) {
    for (int c = 0; c < 2; ++c) {
      const int f = 1 - c;
      if (whole_side(ie.t0[c], ie.t1[c]) || !whole_side(ie.t0[f], ie.t1[f])) continue;
      if (space.polynomial_degree(ie.element[c]).has_value()) continue;
      HangingSide h{ie.element[c], ie.element[f], ie.side[c], ie.side[f], 0.0, 1.0};
      // τ on the fine side ↔ s = (τ − t0f) / (t1f − t0f) ↔ t0c + s (t1c − t0c) on the coarse side.
      const auto coarse_at = [&](double tau) {
        return ie.t0[c] + (tau - ie.t0[f]) / (ie.t1[f] - ie.t0[f]) * (ie.t1[c] - ie.t0[c]);
      };
      h.a = coarse_at(0.0);
      h.b = coarse_at(1.0);
      auto& fine_degree = degree[static_cast<std::size_t>(h.fine)];
      fine_degree = std::max(fine_degree, degree[static_cast<std::size_t>(h.coarse)]);
      out.push_back(h);
    }
  }
  // A coarse cell's side takes its final form before finer cells copy it (it may follow an even coarser cell).
  std::stable_sort(out.begin(), out.end(), [&](const HangingSide& x, const HangingSide& y) {
    return space.level(x.coarse) < space.level(y.coarse);
  });
  return out;
}

void follow_coarse_side(const HangingSide& h, const std::vector<const BezierLayout*>& layout,
                        std::vector<CellControl>& control) {
  const BezierLayout& cl = *layout[static_cast<std::size_t>(h.coarse)];
  const BezierLayout& fl = *layout[static_cast<std::size_t>(h.fine)];
  const CellControl& coarse = control[static_cast<std::size_t>(h.coarse)];
  CellControl& fine = control[static_cast<std::size_t>(h.fine)];
  const std::vector<int> cs = cl.side_points(h.coarse_side), fs = fl.side_points(h.fine_side);
  const bool with_u = coarse.u.size() > 0, with_exact = coarse.exact.size() > 0;
  const Eigen::Index nf = coarse.fields.cols();
  // Columns: x (3), u, exact, the fields.
  Eigen::MatrixXd curve(static_cast<Eigen::Index>(cs.size()), 5 + nf);
  curve.setZero();
  for (std::size_t k = 0; k < cs.size(); ++k) {
    const auto r = static_cast<Eigen::Index>(k);
    curve.block(r, 0, 1, 3) = coarse.x.row(cs[k]);
    if (with_u) curve(r, 3) = coarse.u(cs[k]);
    if (with_exact) curve(r, 4) = coarse.exact(cs[k]);
    if (nf > 0) curve.block(r, 5, 1, nf) = coarse.fields.row(cs[k]);
  }
  const auto n = static_cast<Eigen::Index>(fs.size());
  Eigen::MatrixXd values(n, 5 + nf);
  for (Eigen::Index k = 0; k < n; ++k) {
    const double tau = static_cast<double>(k) / static_cast<double>(n - 1);
    values.row(k) = de_casteljau(curve, h.a + tau * (h.b - h.a));
  }
  const Eigen::MatrixXd points = bezier_from_values(values);
  for (Eigen::Index k = 0; k < n; ++k) {
    const int p = fs[static_cast<std::size_t>(k)];
    fine.x.row(p) = points.block(k, 0, 1, 3);
    if (with_u) fine.u(p) = points(k, 3);
    if (with_exact) fine.exact(p) = points(k, 4);
    if (nf > 0) fine.fields.row(p) = points.block(k, 5, 1, nf);
  }
}

}  // namespace iga::io
