#pragma once
// The Poisson problem the distributed-solver tests share: u = sin πx sin πy with its normal flux (Neumann) on the
// boundary edges near y = 0 (every domain there has its lower side at y = 0, a receding boundary a little above it)
// and Dirichlet data on the others.
#include <Eigen/Core>

#include "fem/poisson.hpp"
#include "fem/problems.hpp"

namespace iga::test {

inline fem::PoissonProblem sine_with_neumann_near_y0() {
  const fem::ManufacturedProblem m = fem::manufactured_problem("sine");
  fem::PoissonProblem p;
  p.source = m.source;
  p.dirichlet = m.exact;
  p.exact = m.exact;
  p.neumann = fem::normal_flux(m.exact);
  p.neumann_where = fem::make_function([](const Eigen::Vector3d& x) { return x(1) < 0.05 ? 1.0 : -1.0; });
  return p;
}

}  // namespace iga::test
