#include "bem/kernel_quadrature.hpp"

#include <algorithm>
#include <cmath>

#include "bem/laplace_kernel.hpp"
#include "quadrature/gauss_legendre.hpp"
#include "quadrature/log_gauss.hpp"

namespace iga::bem {

namespace {

const quadrature::Rule1D& cached_gauss(int n) {
  thread_local std::vector<quadrature::Rule1D> rules(64);
  quadrature::Rule1D& r = rules[static_cast<std::size_t>(n)];
  if (r.size() == 0) r = quadrature::gauss_legendre(n);
  return r;
}

const quadrature::Rule1D& cached_log_gauss(int n) {
  thread_local std::vector<quadrature::Rule1D> rules(41);
  quadrature::Rule1D& r = rules[static_cast<std::size_t>(n)];
  if (r.size() == 0) r = quadrature::log_gauss_rule(n);
  return r;
}

// Gauss on [a, b] with kernels evaluated directly.
void regular_nodes(const basis::CurveGeometry& curve, Index e, double a, double b, const Eigen::Vector2d& p,
                   int order, KernelNodes& out) {
  const quadrature::Rule1D& g = cached_gauss(order);
  thread_local basis::CurvePoints pts;
  const Eigen::VectorXd t = (a + (b - a) * g.points.array()).matrix();
  curve.evaluate(e, t, pts);
  const SingleLayerKernel v;
  const DoubleLayerKernel dv;
  for (Index k = 0; k < t.size(); ++k) {
    const double w = (b - a) * g.weights(k) * pts.speed(k);
    out.t.push_back(t(k));
    out.single.push_back(w * v(p, pts.x.col(k)));
    out.dbl.push_back(w * dv(p, pts.x.col(k), pts.normal.col(k)));
  }
}

// One side t = t0 + sign L s of P = x(t0), s ∈ [0, 1].
void singular_side(const basis::CurveGeometry& curve, Index e, double t0, double end, const Eigen::Vector2d& p,
                   int order, KernelNodes& out) {
  const double len = std::abs(end - t0), sign = end > t0 ? 1.0 : -1.0;
  const quadrature::Rule1D& g = cached_gauss(order);
  const quadrature::Rule1D& lg = cached_log_gauss(order);
  thread_local basis::CurvePoints pts;
  const DoubleLayerKernel dv;
  // Gauss: the smooth part −ln(|x − P| / s) / (2π) and the double layer.
  Eigen::VectorXd t = (t0 + sign * len * g.points.array()).matrix();
  curve.evaluate(e, t, pts);
  for (Index k = 0; k < t.size(); ++k) {
    const double w = len * g.weights(k) * pts.speed(k);
    const double r = (pts.x.col(k) - p).norm();
    out.t.push_back(t(k));
    out.single.push_back(-w * kInvTwoPi * std::log(r / g.points(k)));
    out.dbl.push_back(w * dv(p, pts.x.col(k), pts.normal.col(k)));
  }
  // log-Gauss: −(1/2π) ∫_0^1 f ln s ds = (1/2π) Σ w f.
  t = (t0 + sign * len * lg.points.array()).matrix();
  curve.evaluate(e, t, pts);
  for (Index k = 0; k < t.size(); ++k) {
    out.t.push_back(t(k));
    out.single.push_back(len * lg.weights(k) * pts.speed(k) * kInvTwoPi);
    out.dbl.push_back(0.0);
  }
}

void adaptive_nodes(const basis::CurveGeometry& curve, Index e, double a, double b, const Eigen::Vector2d& p,
                    int depth, const KernelQuadratureOptions& o, KernelNodes& out) {
  thread_local basis::CurvePoints pts;
  const Eigen::Vector3d t(a, 0.5 * (a + b), b);
  curve.evaluate(e, t, pts);
  const double length = std::max((pts.x.col(2) - pts.x.col(0)).norm(), pts.speed(1) * (b - a));
  if (admissible(pts.x.col(0), pts.x.col(1), pts.x.col(2), length, p, o.admissibility)) {
    regular_nodes(curve, e, a, b, p, o.regular_order, out);
    return;
  }
  if (depth >= o.max_depth) {
    out.hit_point = true;
    regular_nodes(curve, e, a, b, p, o.regular_order, out);
    return;
  }
  adaptive_nodes(curve, e, a, 0.5 * (a + b), p, depth + 1, o, out);
  adaptive_nodes(curve, e, 0.5 * (a + b), b, p, depth + 1, o, out);
}

}  // namespace

bool admissible(const Eigen::Vector2d& xa, const Eigen::Vector2d& xm, const Eigen::Vector2d& xb, double length,
                const Eigen::Vector2d& p, double admissibility) {
  const double d = std::min({(p - xa).norm(), (p - xm).norm(), (p - xb).norm()});
  return d >= admissibility * length;
}

void append_kernel_nodes(const basis::CurveGeometry& curve, Index element, double a, double b,
                         const Eigen::Vector2d& p, double t0, KernelNodes& out, const KernelQuadratureOptions& o) {
  const double tol = 1e-13 * curve.diameter();
  if (std::isnan(t0)) {
    if ((curve.point(element, a) - p).norm() <= tol) t0 = a;
    else if ((curve.point(element, b) - p).norm() <= tol) t0 = b;
    out.at_end_point = !std::isnan(t0);
  }
  const double slack = 1e-14;
  if (!std::isnan(t0) && t0 >= a - slack && t0 <= b + slack) {
    t0 = std::clamp(t0, a, b);
    if (t0 > a) singular_side(curve, element, t0, a, p, o.singular_order, out);
    if (t0 < b) singular_side(curve, element, t0, b, p, o.singular_order, out);
    return;
  }
  adaptive_nodes(curve, element, a, b, p, 0, o, out);
}

}  // namespace iga::bem
