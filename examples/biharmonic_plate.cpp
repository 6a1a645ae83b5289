// Kirchhoff plates with iga: D Δ²w = q on the unit square under a uniform load, simply supported (w = Δw = 0 on the
// edges, Navier) and clamped (w = ∂w/∂n = 0), bicubic B-splines on 16 × 16 and 32 × 32 elements; the centre
// deflections against the classical values w = 0.00406235 q a⁴/D and 0.00126532 q a⁴/D. Exit 1 when either misses
// by more than 1e-4 (relative).
//   ./biharmonic_plate            CHOLMOD
//   mpirun -np 2 ./biharmonic_plate --petsc    also on PETSc (CG + GAMG over the ranks), compared with CHOLMOD
// Copy this file to start your own fourth-order driver: a geometry, the data, make_biharmonic, solve_problem.
#include <cmath>
#include <cstring>
#include <iostream>
#include <optional>
#include <vector>

#include "basis/bspline/patches.hpp"
#include "fem/parallel.hpp"
#include "fem/problem.hpp"
#include "pde/biharmonic/biharmonic.hpp"
#include "quadrature/rule_provider.hpp"
#include "refine/uniform.hpp"

namespace {

// w at the centre (0.5, 0.5): the corner (1, 1) of the element below and left of it (elements u-fastest).
double centre_value(const iga::basis::Geometry& g, const Eigen::VectorXd& w, int n) {
  const iga::Index e = (n / 2 - 1) * n + (n / 2 - 1);
  Eigen::Matrix2Xd corner(2, 1);
  corner << 1.0, 1.0;
  iga::basis::BasisValues bv;
  g.space().evaluate(e, corner, 0, bv);
  const auto dofs = g.space().dofs(e);
  double value = 0;
  for (std::size_t a = 0; a < dofs.size(); ++a) value += bv.value(static_cast<iga::Index>(a), 0) * w(dofs[a]);
  return value;
}

}  // namespace

int main(int argc, char** argv) {
  using namespace iga;
  const bool petsc = argc > 1 && std::strcmp(argv[1], "--petsc") == 0;
  std::optional<fem::ParallelSession> session;
  if (petsc) session.emplace(argc, argv);
  const bool report = !petsc || fem::rank() == 0;
  bool ok = true;

  struct Plate {
    const char* name;
    std::vector<int> simply_supported;  // boundary parts ("v0", "u1", "v1", "u0"); the others clamped
    double classical;                   // w(centre) D / (q a⁴)
    int refine;                         // 2^refine elements per side
  };
  for (const Plate& plate : {Plate{"simply supported", {0, 1, 2, 3}, 0.00406235, 4}, Plate{"clamped", {}, 0.00126532, 5}}) {
    // 1. Geometry: the unit square as one bicubic patch, refined by knot insertion.
    const basis::Geometry g = refine::refine_uniform(basis::bspline::make_rectangle(3), plate.refine).geometry;
    // 2. The data: f = q / D = 1, w = 0 on the boundary; ∂w/∂n = 0 where clamped, Δw = 0 where simply supported.
    pde::BiharmonicData data;
    data.source = fem::constant_function(1.0);
    data.simply_supported = plate.simply_supported;
    // 3. Solve: 4 × 4 Gauss points, CHOLMOD.
    const quadrature::Gauss rules(4);
    const fem::ProblemResult r = fem::solve_problem(g, rules, pde::make_biharmonic(data));
    const int n = 1 << plate.refine;
    const double w = centre_value(g, r.u, n);
    const double miss = std::abs(w / plate.classical - 1);
    ok = ok && miss < 1e-4;
    if (report) {
      std::cout << plate.name << " plate, " << n << " x " << n << " bicubic elements, " << r.dofs << " dofs: w(centre) = "
                << w << " q a^4/D (classical " << plate.classical << ", relative difference " << miss << ")\n";
      for (const auto& [what, how] : r.choices) std::cout << "  " << what << ": " << how << "\n";
    }
    // 4. On PETSc, distributed: the same solution to 1e-10 (relative, largest coefficient).
    if (petsc) {
      fem::SolverOptions options;
      options.kind = fem::SolverKind::Petsc;
      const fem::ProblemResult p = fem::solve_problem(g, rules, pde::make_biharmonic(data), options);
      const double difference = (p.u - r.u).cwiseAbs().maxCoeff() / r.u.cwiseAbs().maxCoeff();
      ok = ok && difference < 1e-10;
      if (report) {
        std::cout << "  " << p.solver << " on " << p.ranks << " ranks, " << p.solver_iterations
                  << " iterations: differs from CHOLMOD by " << difference << "\n";
      }
    }
  }
  if (report) std::cout << (ok ? "OK" : "FAILED: a deflection (or PETSc's answer) is off") << "\n";
  return ok ? 0 : 1;
}
