// Catmull–Clark splines with the natural and the clamped boundary rule on a regular control net of the unit
// square (data/meshes/square_6x6.obj), for u = (cos πx − 1) sin 2πy, whose second normal derivative on x = 0 is
// not zero: every natural-rule function has u_nn = 0 on the boundary, so that rule converges at L2 rate 2.5; the
// clamped rule (one ring of ghost control points: open knot vectors in the normal direction) at the bicubic 4.
// Dirichlet data everywhere, imposed strongly on the regular net or, with --nitsche, weakly (what nets with
// boundary extraordinary vertices need with the clamped rule). Exit 1 unless the clamped rate is at least 3.8
// and the natural one at most 3.
#include <CLI/CLI.hpp>
#include <cmath>
#include <iostream>

#include "basis/catmull_clark/space.hpp"
#include "fem/expression.hpp"
#include "fem/poisson.hpp"
#include "mesh/obj_reader.hpp"
#include "quadrature/rule_provider.hpp"
#include "refine/uniform.hpp"

namespace {
// The L2 rate over refinement levels 1..3 with one boundary rule.
double l2_rate(const iga::mesh::PolyMesh& net, iga::basis::catmull_clark::BoundaryRule rule, bool nitsche) {
  using namespace iga;
  fem::PoissonProblem p;
  p.source = std::make_shared<fem::Expression>("pi^2*(5*cos(pi*x)-4)*sin(2*pi*y)", "source");
  p.exact = std::make_shared<fem::Expression>("(cos(pi*x)-1)*sin(2*pi*y)", "exact");
  p.dirichlet = p.exact;
  if (nitsche) p.dirichlet_method = fem::DirichletMethod::kNitsche;
  const basis::Geometry coarse = basis::catmull_clark::make_catmull_clark_geometry(net, "net", rule);
  double first = 0, last = 0;
  for (int level = 1; level <= 3; ++level) {
    const fem::PoissonResult r = fem::solve_poisson(refine::refine_uniform(coarse, level).geometry, quadrature::Gauss(4), p);
    std::cout << "  " << basis::catmull_clark::to_string(rule) << ", level " << level << ": " << r.dofs << " dofs, L2 error "
              << r.errors->l2 << "\n";
    (level == 1 ? first : last) = r.errors->l2;
  }
  return std::log2(first / last) / 2;  // h halves per level
}
}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Catmull–Clark natural against clamped boundary rule: convergence rates"};
  std::string file = "data/meshes/square_6x6.obj";
  bool nitsche = false;
  app.add_option("--mesh", file, "regular planar control net of the unit square (OBJ)");
  app.add_flag("--nitsche", nitsche, "impose the Dirichlet data weakly (Nitsche) instead of by L2 projection");
  CLI11_PARSE(app, argc, argv);
  const iga::mesh::PolyMesh net = iga::mesh::read_obj(file);
  const double natural = l2_rate(net, iga::basis::catmull_clark::BoundaryRule::kNatural, nitsche);
  const double clamped = l2_rate(net, iga::basis::catmull_clark::BoundaryRule::kClamped, nitsche);
  std::cout << "L2 rate: natural " << natural << ", clamped " << clamped << "\n";
  const bool ok = clamped >= 3.8 && natural <= 3.0;
  std::cout << (ok ? "OK" : "FAILED") << "\n";
  return ok ? 0 : 1;
}
