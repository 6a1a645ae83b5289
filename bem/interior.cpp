#include "bem/interior.hpp"

#include <limits>
#include <string>

#include "bem/boundary_integrals.hpp"
#include "core/error.hpp"

namespace iga::bem {

Eigen::VectorXd evaluate_interior(const BoundaryDiscretization& d, const Solution& solution,
                                  const Eigen::Matrix2Xd& points) {
  if (solution.u.size() != d.num_dofs() || solution.q.size() != d.num_dofs()) {
    throw InputError("evaluate_interior: the solution has " + std::to_string(solution.u.size()) +
                     " coefficients for " + std::to_string(d.num_dofs()) + " dofs");
  }
  const BoundaryIntegrator integrator(d);
  const Eigen::VectorXd q_internal = solution.q / d.scale();
  const Index m = points.cols();
  Eigen::VectorXd out(m);
  Index bad = -1;
#pragma omp parallel for schedule(dynamic, 8)
  for (Index k = 0; k < m; ++k) {
    Eigen::VectorXd h, g;
    const bool ok = integrator.integrate(points.col(k) * d.scale(), -1, std::numeric_limits<double>::quiet_NaN(), h, g);
    out(k) = g.dot(q_internal) - h.dot(solution.u);
    if (!ok) {
#pragma omp critical(iga_bem_interior)
      if (bad < 0 || k < bad) bad = k;
    }
  }
  if (bad >= 0) {
    throw InputError("evaluate_interior: point " + std::to_string(bad) + " (" + std::to_string(points(0, bad)) +
                     ", " + std::to_string(points(1, bad)) + ") lies on the boundary");
  }
  return out;
}

}  // namespace iga::bem
