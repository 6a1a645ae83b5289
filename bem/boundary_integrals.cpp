#include "bem/boundary_integrals.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "bem/laplace_kernel.hpp"
#include "quadrature/gauss_legendre.hpp"

namespace iga::bem {

BoundaryIntegrator::BoundaryIntegrator(const BoundaryDiscretization& d, const KernelQuadratureOptions& options)
    : d_(d), options_(options), cache_(static_cast<std::size_t>(d.num_elements())) {
  const quadrature::Rule1D g = quadrature::gauss_legendre(options_.regular_order);
  const basis::CurveGeometry& curve = d.scaled_curve();
  for (Index e = 0; e < d.num_elements(); ++e) {
    const BemElement& el = d.element(e);
    ElementCache& c = cache_[static_cast<std::size_t>(e)];
    basis::CurvePoints pts;
    const Eigen::VectorXd t = (el.a + (el.b - el.a) * g.points.array()).matrix();
    curve.evaluate(el.curve_element, t, pts);
    c.x = pts.x;
    c.normal = pts.normal;
    c.ws = ((el.b - el.a) * g.weights.array() * pts.speed.array()).matrix();
    basis::CurveBasisValues v;
    d.space().evaluate(e, g.points, 0, v);
    c.basis = v.value;
    const Eigen::Vector3d ends(el.a, 0.5 * (el.a + el.b), el.b);
    curve.evaluate(el.curve_element, ends, pts);
    c.xa = pts.x.col(0);
    c.xm = pts.x.col(1);
    c.xb = pts.x.col(2);
    c.length = std::max((c.xb - c.xa).norm(), pts.speed(1) * (el.b - el.a));
  }
}

bool BoundaryIntegrator::integrate(const Eigen::Vector2d& p, Index on_curve_element, double curve_t,
                                   Eigen::VectorXd& h, Eigen::VectorXd& g) const {
  const Index n = d_.num_dofs();
  h.setZero(n);
  g.setZero(n);
  thread_local KernelNodes nodes;
  thread_local Eigen::VectorXd kv, kd, local_g, local_h;
  thread_local basis::CurveBasisValues values;
  thread_local Eigen::VectorXd tau;
  bool ok = true;
  for (Index e = 0; e < d_.num_elements(); ++e) {
    const ElementCache& c = cache_[static_cast<std::size_t>(e)];
    const BemElement& el = d_.element(e);
    const std::span<const Index> dofs = d_.space().dofs(e);
    // P on this very piece (its parameter inside [a, b]); other pieces of P's curve element are near or far
    // by distance like any other.
    const bool same = el.curve_element == on_curve_element && curve_t >= el.a - 1e-14 && curve_t <= el.b + 1e-14;
    if (!same && admissible(c.xa, c.xm, c.xb, c.length, p, options_.admissibility)) {
      // Far field: the kernels at the cached nodes, then (local dofs × nodes) times them.
      const Index q = c.ws.size();
      kv.resize(q);
      kd.resize(q);
      for (Index k = 0; k < q; ++k) {
        const Eigen::Vector2d r = c.x.col(k) - p;
        const double r2 = r.squaredNorm();
        kv(k) = -0.5 * kInvTwoPi * c.ws(k) * std::log(r2);  // v = −ln r / (2π) = −ln r² / (4π)
        kd(k) = -kInvTwoPi * c.ws(k) * r.dot(c.normal.col(k)) / r2;
      }
      local_g.noalias() = c.basis * kv;
      local_h.noalias() = c.basis * kd;
      for (std::size_t j = 0; j < dofs.size(); ++j) {
        g(dofs[j]) += local_g(static_cast<Index>(j));
        h(dofs[j]) += local_h(static_cast<Index>(j));
      }
      continue;
    }
    nodes.clear();
    append_kernel_nodes(d_.scaled_curve(), el.curve_element, el.a, el.b, p,
                        same ? curve_t : std::numeric_limits<double>::quiet_NaN(), nodes, options_);
    // Off the boundary by declaration, P must not be found on it (at an element's end point either).
    ok = ok && !nodes.hit_point && !(on_curve_element < 0 && nodes.at_end_point);
    tau.resize(static_cast<Index>(nodes.size()));
    for (std::size_t k = 0; k < nodes.size(); ++k) {
      tau(static_cast<Index>(k)) = std::clamp((nodes.t[k] - el.a) / (el.b - el.a), 0.0, 1.0);
    }
    d_.space().evaluate(e, tau, 0, values);
    for (std::size_t k = 0; k < nodes.size(); ++k) {
      for (std::size_t j = 0; j < dofs.size(); ++j) {
        g(dofs[j]) += nodes.single[k] * values.value(static_cast<Index>(j), static_cast<Index>(k));
        h(dofs[j]) += nodes.dbl[k] * values.value(static_cast<Index>(j), static_cast<Index>(k));
      }
    }
  }
  return ok;
}

}  // namespace iga::bem
