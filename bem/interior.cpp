#include "bem/interior.hpp"

#include <iomanip>
#include <limits>
#include <sstream>
#include <string>

#include "bem/boundary_integrals.hpp"
#include "core/error.hpp"
#include "fem/parallel_for.hpp"

namespace iga::bem {

Eigen::VectorXd evaluate_interior(const BoundaryDiscretization& d, const Solution& solution,
                                  const Eigen::Matrix2Xd& points) {
  if (solution.u.size() != d.num_dofs() || solution.q.size() != d.num_dofs()) {
    throw Error("bem interior evaluation: the solution has " + std::to_string(solution.u.size()) +
                     " coefficients for " + std::to_string(d.num_dofs()) + " dofs");
  }
  const BoundaryIntegrator integrator(d);
  const Eigen::VectorXd q_internal = solution.q / d.scale();
  const Index m = points.cols();
  Eigen::VectorXd out(m);
  // A point on the boundary is refused by the lowest such index; an exception inside any body is rethrown after the
  // loop (fem::parallel_for), not std::terminate.
  fem::parallel_for(m, [&](Index k) {
    Eigen::VectorXd h, g;
    if (!integrator.integrate(points.col(k) * d.scale(), -1, std::numeric_limits<double>::quiet_NaN(), h, g)) {
      std::ostringstream msg;
      msg << std::setprecision(6) << "the point (" << points(0, k) << ", " << points(1, k)
          << ") lies on the boundary, where the boundary integral representation does not hold";
      throw InputError(msg.str());
    }
    out(k) = g.dot(q_internal) - h.dot(solution.u);
  }, 8);
  return out;
}

}  // namespace iga::bem
