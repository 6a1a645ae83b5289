// Solves the patch test (u = 1 + 2x - 3y) on the installed library; exits 0 when it is reproduced.
#include <cstdio>

#include "basis/bspline/patches.hpp"
#include "fem/poisson.hpp"
#include "fem/problems.hpp"
#include "quadrature/rule_provider.hpp"
#include "refine/uniform.hpp"

int main() {
  using namespace iga;
  const basis::Geometry g = refine::refine_uniform(basis::bspline::make_quarter_annulus(2), 2).geometry;
  const fem::ManufacturedProblem mp = fem::manufactured_problem("linear");
  fem::PoissonProblem p;
  p.source = mp.source;
  p.exact = mp.exact;
  p.dirichlet = mp.exact;
  // The annulus is a NURBS patch: the patch test is exact up to the rule's error on the rational stiffness integrand,
  // below 1e-15 with 10 points per direction.
  const fem::PoissonResult r = fem::solve_poisson(g, quadrature::Gauss(10), p);
  std::printf("consumer: %lld dofs, L2 error %.3e\n", static_cast<long long>(r.dofs), r.errors->l2);
  return r.errors->l2 < 1e-10 ? 0 : 1;
}
