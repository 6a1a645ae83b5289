// Every PDE on every backend, distributed (ctest: under mpirun at 2, 3 and 4 ranks, and alone): the PETSc solution
// equals CHOLMOD's to 1e-10 (relative, largest coefficient) with both parallel partitions. The biharmonic equation
// (clamped) on B-splines, Catmull–Clark, polyhedral and half-box splines, with one case of 36 elements (a rank of 9 at
// 4 ranks); elasticity (held all round, a body force) on the same four; the Kirchhoff–Love shell (held all round, an
// area load) on a B-spline cylinder patch and on the Catmull–Clark and polyhedral hemisphere band.
#include "support/backend_cases.hpp"
#include "support/paths.hpp"
#include "support/biharmonic_solutions.hpp"
#include "support/parallel_main.hpp"
#include <gtest/gtest.h>

#include <numeric>

#include "basis/bspline/patches.hpp"
#include "basis/registry.hpp"
#include "fem/parallel.hpp"
#include "fem/problem.hpp"
#include "mesh/obj_reader.hpp"
#include "mesh/three_valent.hpp"
#include "pde/biharmonic/biharmonic.hpp"
#include "pde/elasticity/elasticity.hpp"
#include "pde/shell/shell.hpp"
#include "quadrature/rule_provider.hpp"
#include "refine/uniform.hpp"

using namespace iga;

namespace {

using Case = test::BackendCase;
using test::geometry_of;

std::vector<int> all_parts(const basis::Geometry& g) {
  std::vector<int> parts(g.space().boundary_part_names().size());
  std::iota(parts.begin(), parts.end(), 0);
  return parts;
}

// The largest relative difference between the PETSc solutions (each partition) and CHOLMOD's.
void expect_equal_distributed(const std::string& what, const basis::Geometry& g,
                              const std::shared_ptr<const fem::Problem>& problem, int degree) {
  const auto rules = quadrature::make_rule_provider(basis::backend_of(g.space()).default_quadrature(degree), degree + 1);
  const fem::ProblemResult serial = fem::solve_problem(g, *rules, problem);
  for (const std::string partition : {"curve", "ptscotch"}) {
    fem::SolverOptions petsc;
    petsc.kind = fem::SolverKind::Petsc;
    petsc.tolerance = 1e-14;
    petsc.partition = partition;
    const fem::ProblemResult r = fem::solve_problem(g, *rules, problem, petsc);
    const double difference = (r.u - serial.u).lpNorm<Eigen::Infinity>() / serial.u.lpNorm<Eigen::Infinity>();
    EXPECT_LE(difference, 1e-10) << what << " by " << partition << " at " << fem::ranks() << " ranks";
    EXPECT_EQ(r.ranks, fem::ranks()) << what;
    Index elements = 0;
    for (Index e : r.elements_per_rank) elements += e;
    EXPECT_EQ(elements, g.space().num_elements()) << what;
  }
}

const std::vector<Case> kPlanar = {
    {"bspline", "", 3},                   // the NURBS quarter annulus
    {"cc", "square_evs.obj", 1},          // extraordinary vertices
    {"cc", "square_evs.obj", 0},          // 36 elements: 9 per rank at 4 ranks
    {"polyhedral", "square_evs.obj", 1},  // receding boundary: coupled constraints
    {"halfbox", "tri_square.obj", 0},     // triangles
};

}  // namespace

TEST(PdeRanks, BiharmonicOnEveryBackendEqualsCholmod) {
  for (const Case& c : kPlanar) {
    const basis::Geometry g = geometry_of(c);
    const pde::BiharmonicData data = pde::biharmonic_data_from_exact(test::bump(), test::bump_source());
    expect_equal_distributed("biharmonic, " + c.backend + " refine " + std::to_string(c.refine), g,
                             pde::make_biharmonic(data), 4);
  }
}

TEST(PdeRanks, ElasticityOnEveryBackendEqualsCholmod) {
  for (const Case& c : kPlanar) {
    const basis::Geometry g = geometry_of(c);
    pde::ElasticityData data;
    data.body_force = {fem::constant_function(1.0), fem::constant_function(-0.5)};
    data.displacement = {{0, all_parts(g), nullptr}, {1, all_parts(g), nullptr}};
    expect_equal_distributed("elasticity, " + c.backend + " refine " + std::to_string(c.refine), g,
                             pde::make_elasticity(data), 4);
  }
}

TEST(PdeRanks, ShellOnBsplineCatmullClarkAndPolyhedralEqualsCholmod) {
  std::vector<std::pair<std::string, basis::Geometry>> surfaces;
  surfaces.emplace_back("bspline cylinder patch",
                        refine::refine_uniform(basis::bspline::make_cylinder_patch(3, 25.0, 50.0, -0.7, 0.7), 2).geometry);
  surfaces.emplace_back("cc band", geometry_of({"cc", "band_32x8_evs.obj", 0}));
  surfaces.emplace_back("polyhedral band", geometry_of({"polyhedral", "band_32x8_evs.obj", 0}));
  for (const auto& [name, g] : surfaces) {
    pde::ShellData data;
    data.material = {1e6, 0.3, 0.1};
    data.area_load = {nullptr, nullptr, fem::constant_function(-1.0)};
    for (int component = 0; component < 3; ++component) data.supports.push_back({component, all_parts(g), nullptr});
    expect_equal_distributed("shell, " + name, g, pde::make_shell(data), 4);
  }
}

int main(int argc, char** argv) { return iga::test::run_tests_on_every_rank(argc, argv); }
