#include "bem/assembly.hpp"

#include <chrono>
#include <limits>

#include "bem/boundary_integrals.hpp"
#include "bem/kernel_quadrature.hpp"
#include "core/error.hpp"
#include "fem/parallel_for.hpp"

namespace iga::bem {

BemMatrices assemble(const BoundaryDiscretization& d) {
  const auto start = std::chrono::steady_clock::now();
  const BoundaryIntegrator integrator(d);
  const Index n = d.num_dofs();
  const std::vector<CollocationPoint>& points = d.collocation_points();
  BemMatrices m;
  m.H.resize(n, n);
  m.G.resize(n, n);
  m.free_term.resize(n);
  // An exception inside (a kernel's evaluation, memory) is rethrown after the loop, not std::terminate.
  fem::parallel_for(n, [&](Index i) {
    const CollocationPoint& c = points[static_cast<std::size_t>(i)];
    const Eigen::Vector2d p = d.scaled_curve().point(c.curve_element, c.curve_t);
    Eigen::VectorXd h, g;
    if (!integrator.integrate(p, c.curve_element, c.curve_t, h, g)) {
      throw NumericalError("bem assembly: a collocation point lies on another part of the boundary");
    }
    const double ci = -h.sum();
    basis::CurveBasisValues values;
    d.space().evaluate(c.element, Eigen::VectorXd::Constant(1, c.t), 0, values);
    const std::span<const Index> dofs = d.space().dofs(c.element);
    for (std::size_t j = 0; j < dofs.size(); ++j) h(dofs[j]) += ci * values.value(static_cast<Index>(j), 0);
    m.H.row(i) = h.transpose();
    m.G.row(i) = g.transpose();
    m.free_term(i) = ci;
  }, 4);
  m.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return m;
}

double free_term(const basis::CurveGeometry& curve, Index element, double t) {
  const Eigen::Vector2d p = curve.point(element, t);
  KernelNodes nodes;
  double sum = 0.0;
  for (Index e = 0; e < curve.num_elements(); ++e) {
    nodes.clear();
    append_kernel_nodes(curve, e, 0.0, 1.0, p, e == element ? t : std::numeric_limits<double>::quiet_NaN(), nodes);
    for (double w : nodes.dbl) sum += w;
  }
  return -sum;
}

}  // namespace iga::bem
