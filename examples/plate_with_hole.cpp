// The classic of isogeometric elasticity: an infinite plate with a circular hole under uniaxial tension T (Kirsch),
// on the exact NURBS quarter plate [0, 4]² minus the hole r < 1, plane strain, cubic NURBS refined 5 times
// (32 × 64 elements). Symmetry conditions u_y = 0 on y = 0 and u_x = 0 on x = 0, Kirsch's exact traction on the
// outer sides, the hole free. Checks the stress concentration σ_xx = 3T at (0, 1) and the energy error; writes
// displacement, stress and von Mises stress for ParaView (plate_with_hole.vtu: Warp By Vector on "displacement").
//   ./plate_with_hole            CHOLMOD
//   mpirun -np 2 ./plate_with_hole --petsc    also on PETSc over the ranks, compared with CHOLMOD
#include <cmath>
#include <cstring>
#include <iostream>
#include <optional>

#include "basis/bspline/patches.hpp"
#include "fem/parallel.hpp"
#include "fem/problem.hpp"
#include "io/vtu_writer.hpp"
#include "pde/elasticity/elasticity.hpp"
#include "pde/elasticity/kirsch.hpp"
#include "quadrature/rule_provider.hpp"
#include "refine/uniform.hpp"

int main(int argc, char** argv) {
  using namespace iga;
  const bool petsc = argc > 1 && std::strcmp(argv[1], "--petsc") == 0;
  std::optional<fem::ParallelSession> session;
  if (petsc) session.emplace(argc, argv);
  const bool report = !petsc || fem::rank() == 0;
  const int degree = 3, refine = 5;
  const double young = 1e5, nu = 0.3, tension = 10.0;

  // 1. Geometry: the exact quarter plate with the hole; boundary parts v0 (y = 0), u1 (outer sides), v1 (x = 0),
  //    u0 (the hole).
  const basis::Geometry g = refine::refine_uniform(basis::bspline::make_plate_with_hole(degree), refine).geometry;
  enum Part { kV0 = 0, kU1 = 1, kV1 = 2 };

  // 2. Material and data: Kirsch's exact solution gives the traction on the outer sides and the error figures.
  const pde::Lame lame = pde::lame(young, nu, pde::PlaneModel::kStrain);
  const pde::KirschSolution kirsch = pde::kirsch_solution(tension, 1.0, lame);
  pde::ElasticityData data;
  data.young = young;
  data.poisson = nu;
  data.model = pde::PlaneModel::kStrain;
  data.displacement = {{1, {kV0}, nullptr}, {0, {kV1}, nullptr}};  // symmetry: u_y = 0 on y = 0, u_x = 0 on x = 0
  data.traction = {{{kU1}, pde::traction_of(kirsch.displacement, lame)}};
  data.exact = kirsch.displacement;

  // 3. Solve: (p+1)² Gauss points, CHOLMOD.
  const quadrature::Gauss rules(degree + 1);
  const fem::ProblemResult r = fem::solve_problem(g, rules, pde::make_elasticity(data));

  // 4. The stress at the top of the hole: the corner u = 0, v = 1 of the first element of the last row.
  const Index nu_el = Index{1} << refine, hole_top = (2 * nu_el - 1) * nu_el;
  const double sigma = pde::stress_at(g, r.u, hole_top, {0.0, 1.0}, lame)(0);
  const double energy = r.error("energy").error / r.error("energy").exact;
  // Measured: σ_xx(0, 1) = 30.0085 (2.8e-4 from 3T) and a relative energy error of 1.2e-4 here.
  bool ok = std::abs(sigma / (3 * tension) - 1) < 1e-3 && energy < 2e-4;
  if (report) {
    std::cout << "dofs " << r.dofs << ", elements " << r.elements << "\n"
              << "sigma_xx(0, 1) = " << sigma << " (3T = " << 3 * tension << ")\n"
              << "relative L2 error " << r.error("L2").error / r.error("L2").exact << ", energy " << energy << "\n";
    // 5. ParaView: displacement (a vector), stress (a symmetric tensor) and von Mises' stress at 4 × 4 samples.
    io::VtuOptions out;
    out.samples = 4;
    const auto field = [&](int which) { return pde::elasticity_sampler(g.space(), r.u, lame, nu, which); };
    out.fields = {{"displacement", 3, field(0)}, {"stress", 6, field(1)}, {"von_mises", 1, field(2)}};
    io::write_vtu("plate_with_hole.vtu", g, out);
  }
  // 6. On PETSc, distributed: the same displacement to 1e-10 (relative, largest coefficient).
  if (petsc) {
    fem::SolverOptions options;
    options.kind = fem::SolverKind::Petsc;
    const fem::ProblemResult p = fem::solve_problem(g, rules, pde::make_elasticity(data), options);
    const double difference = (p.u - r.u).cwiseAbs().maxCoeff() / r.u.cwiseAbs().maxCoeff();
    ok = ok && difference < 1e-10;
    if (report) {
      std::cout << p.solver << " on " << p.ranks << " ranks, " << p.solver_iterations
                << " iterations: differs from CHOLMOD by " << difference << "\n";
    }
  }
  if (report) std::cout << (ok ? "OK" : "FAILED: the stress concentration, the energy error or PETSc's answer is off") << "\n";
  return ok ? 0 : 1;
}
