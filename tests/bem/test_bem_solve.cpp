// bem: collocation BEM solves — patch tests, convergence on a smooth loop, a square and a square with a hole,
// LU against GMRES, the condition estimate, interior values.
#include <gtest/gtest.h>

#include <Eigen/LU>
#include <cstdio>

#include "bem/boundary_discretization.hpp"
#include "bem/errors.hpp"
#include "bem/interior.hpp"
#include "bem/solve.hpp"
#include "bem_geometries.hpp"
#include "core/error.hpp"
#include "support/rates.hpp"

using iga::Index;
namespace bem = iga::bem;
namespace tb = iga::test::bem;

namespace {

bem::Problem problem_for(std::shared_ptr<iga::fem::Function> u) {
  return {u, iga::fem::normal_flux(u), u};
}

struct Result {
  double flux_error, u_error, interior_error;
  Index dofs;
};

Result solve_case(const iga::basis::CurveGeometry& curve, const std::vector<int>& cond, int p, int refine,
        const std::shared_ptr<iga::fem::Function>& u, const Eigen::Matrix2Xd& interior = Eigen::Matrix2Xd(2, 0)) {
  bem::DiscretizationOptions o;
  o.degree = p;
  o.refine = refine;
  const bem::BoundaryDiscretization d(curve, cond, o);
  const bem::Solution s = bem::solve(d, problem_for(u));
  Result r{bem::flux_l2_error(d, s, *u) / bem::flux_l2_norm(d, *u), bem::u_l2_error(d, s, *u) / bem::u_l2_norm(d, *u),
        0.0, d.num_dofs()};
  if (interior.cols() > 0) {
    const Eigen::VectorXd uh = bem::evaluate_interior(d, s, interior);
    Eigen::Matrix3Xd x = Eigen::Matrix3Xd::Zero(3, interior.cols());
    x.topRows<2>() = interior;
    Eigen::VectorXd ue;
    u->values(x, ue);
    r.interior_error = (uh - ue).cwiseAbs().maxCoeff();
  }
  return r;
}

}  // namespace

TEST(BemSolve, Explore) {
  const auto loop = tb::smooth_loop();
  Eigen::Matrix2Xd pts(2, 3);
  pts << 0.1, 0.3, -0.4, 0.0, 0.2, 0.1;
  for (int p : {2, 3}) {
    for (int k = 1; k <= 4; ++k) {
      for (int r = 0; r <= 4; ++r) {
        const Result x = solve_case(loop, std::vector<int>(static_cast<std::size_t>(loop.num_elements()), 0), p, r,
                          tb::re_power(k), pts);
        std::printf("loop D p %d k %d r %d dofs %ld flux %.3e u %.3e int %.3e\n", p, k, r, static_cast<long>(x.dofs),
                    x.flux_error, x.u_error, x.interior_error);
      }
    }
  }
}
