// The distributed solver (fem/linear_system.hpp, "petsc") against the serial one, at whatever number of ranks
// this program is started with (ctest: 1 without mpirun, 2, 3 and 4 under mpirun): the partitions (curve, PT-Scotch, METIS), the
// assembled matrix entry by entry, the solution against CHOLMOD's for every backend with Dirichlet and Neumann
// parts and the coupled constraints of receding boundaries, convergence rates, and failures as one exception on
// every rank. Every rank runs every test; rank 0 prints.
#include "support/backend_cases.hpp"
#include "support/paths.hpp"
#include "support/mixed_problem.hpp"
#include "support/parallel_main.hpp"
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdint>

#include "basis/registry.hpp"
#include "core/error.hpp"
#include "fem/dirichlet.hpp"
#include "fem/linear_system.hpp"
#include "fem/parallel.hpp"
#include "fem/partition.hpp"
#include "fem/poisson.hpp"
#include "fem/problems.hpp"
#include "mesh/obj_reader.hpp"
#include "mesh/three_valent.hpp"
#include "quadrature/rule_provider.hpp"
#include "support/rates.hpp"

using namespace iga;

namespace {

using Case = test::BackendCase;
using test::geometry_of;

std::unique_ptr<quadrature::RuleProvider> rules_of(const Case& c, const basis::Geometry& g) {
  const basis::Backend& b = basis::backend_of(g.space());
  return quadrature::make_rule_provider(b.default_quadrature(c.backend == "bspline" ? 3 : 3), 3);
}

fem::PoissonProblem problem_with_neumann() { return test::sine_with_neumann_near_y0(); }

fem::SolverOptions petsc(const std::string& options = "") {
  fem::SolverOptions o;
  o.kind = fem::SolverKind::Petsc;
  o.tolerance = 1e-14;  // relative residual: the solution then agrees with the direct solver's to about 1e-11
  o.petsc_options = options;
  return o;
}

double relative_difference(const Eigen::VectorXd& a, const Eigen::VectorXd& b) {
  return (a - b).lpNorm<Eigen::Infinity>() / b.lpNorm<Eigen::Infinity>();
}

const std::vector<Case> kCases = {
    {"bspline", "", 3},                   // the NURBS quarter annulus, 8 × 8 elements
    {"cc", "square_evs.obj", 1},          // Catmull–Clark with extraordinary vertices
    {"polyhedral", "square_evs.obj", 1},  // receding boundary: coupled Dirichlet constraints
    {"halfbox", "tri_square.obj", 1},     // triangles, receding boundary
};

}  // namespace

TEST(Partition, EveryElementOwnedOnceDofsByTheirLowestOwnerAndNumberedByRank) {
  const basis::Geometry g = geometry_of({"bspline", "", 3});
  const basis::Space& s = g.space();
  for (int parts : {1, 2, 3, 5}) {
    const fem::Partition p = fem::partition_elements(s, parts);
    ASSERT_EQ(p.element_owner.size(), static_cast<std::size_t>(s.num_elements()));
    Index owned = 0;
    for (int r = 0; r < parts; ++r) {
      EXPECT_GT(p.owned_elements(r), 0) << parts << " parts, rank " << r;
      owned += p.owned_elements(r);
    }
    EXPECT_EQ(owned, s.num_elements());  // every owner is one of the ranks, and each element counted once
    std::vector<int> lowest(static_cast<std::size_t>(s.num_dofs()), parts);
    for (Index e = 0; e < s.num_elements(); ++e) {
      for (Index d : s.dofs(e)) lowest[static_cast<std::size_t>(d)] = std::min(lowest[static_cast<std::size_t>(d)], p.element_owner[static_cast<std::size_t>(e)]);
    }
    std::vector<char> used(static_cast<std::size_t>(s.num_dofs()), 0);
    for (Index d = 0; d < s.num_dofs(); ++d) {
      EXPECT_EQ(p.dof_owner[static_cast<std::size_t>(d)], lowest[static_cast<std::size_t>(d)]);
      const Index n = p.number[static_cast<std::size_t>(d)];
      const int r = p.dof_owner[static_cast<std::size_t>(d)];
      EXPECT_GE(n, p.offsets[static_cast<std::size_t>(r)]);
      EXPECT_LT(n, p.offsets[static_cast<std::size_t>(r) + 1]);
      ASSERT_FALSE(used[static_cast<std::size_t>(n)]) << "number " << n << " given twice";
      used[static_cast<std::size_t>(n)] = 1;
    }
    EXPECT_EQ(p.offsets.back(), s.num_dofs());
  }
  EXPECT_THROW(fem::partition_elements(s, static_cast<int>(s.num_elements()) + 1), InputError);
}

// The Hilbert index (Skilling's transform): on a 2^b grid in 2D and 3D every cell has one index, and cells of
// consecutive indices share a side, the property that makes runs of the curve compact parts.
TEST(Partition, HilbertKeysOfConsecutiveCellsShareASide) {
  for (int n : {2, 3}) {
    const int bits = n == 2 ? 4 : 3, side = 1 << bits, cells = n == 2 ? side * side : side * side * side;
    std::vector<std::array<int, 3>> at(static_cast<std::size_t>(cells), {-1, -1, -1});
    for (int c = 0; c < cells; ++c) {
      const std::array<std::uint32_t, 3> x{static_cast<std::uint32_t>(c % side), static_cast<std::uint32_t>(c / side % side),
                                           static_cast<std::uint32_t>(n == 3 ? c / side / side : 0)};
      const std::uint64_t key = fem::hilbert_key(x, n, bits);
      ASSERT_LT(key, static_cast<std::uint64_t>(cells));
      ASSERT_EQ(at[key][0], -1) << "index " << key << " given twice";
      at[key] = {static_cast<int>(x[0]), static_cast<int>(x[1]), static_cast<int>(x[2])};
    }
    for (int k = 1; k < cells; ++k) {
      int distance = 0;
      for (int i = 0; i < 3; ++i) distance += std::abs(at[static_cast<std::size_t>(k)][i] - at[static_cast<std::size_t>(k) - 1][i]);
      EXPECT_EQ(distance, 1) << n << "D, indices " << k - 1 << " and " << k;
    }
  }
}

// Every method parts the elements of every backend the same way on every rank and on a second call; the dofs are
// owned by their lowest element owner; the reported cut is the dofs whose elements lie on more than one rank; the
// curve's parts differ by at most one element. The smallest case gives a rank few elements (9 over 3 ranks).
TEST(Partition, EveryMethodPartsEveryBackendTheSameOnEveryRank) {
  std::vector<Case> cases = kCases;
  cases.push_back({"cc", "square_evs.obj", 0});
  for (const Case& c : cases) {
    const basis::Geometry g = geometry_of(c);
    const basis::Space& s = g.space();
    for (fem::PartitionMethod m : {fem::PartitionMethod::Curve, fem::PartitionMethod::Scotch, fem::PartitionMethod::Metis}) {
      const std::string what = c.backend + " refine " + std::to_string(c.refine) + " by " + fem::partition_name(m) +
                               " at " + std::to_string(fem::ranks()) + " ranks";
      const fem::Partition p = fem::partition_elements(g, m);
      ASSERT_EQ(p.element_owner.size(), static_cast<std::size_t>(s.num_elements())) << what;
      EXPECT_EQ(p.method, fem::ranks() > 1 ? fem::partition_name(m) : std::string("none")) << what;
      Index hash = 0, owned = 0;
      for (Index e = 0; e < s.num_elements(); ++e) {
        const int o = p.element_owner[static_cast<std::size_t>(e)];
        ASSERT_TRUE(o >= 0 && o < fem::ranks()) << what;
        hash = (hash * 31 + o + 1) % 1000000007;
      }
      for (Index h : fem::gather_over_ranks(hash)) EXPECT_EQ(h, hash) << what << ": the ranks disagree";
      EXPECT_EQ(fem::partition_elements(g, m).element_owner, p.element_owner) << what << ": not reproducible";
      std::vector<int> lowest(static_cast<std::size_t>(s.num_dofs()), fem::ranks()), highest(lowest.size(), -1);
      for (Index e = 0; e < s.num_elements(); ++e) {
        for (Index d : s.dofs(e)) {
          lowest[static_cast<std::size_t>(d)] = std::min(lowest[static_cast<std::size_t>(d)], p.element_owner[static_cast<std::size_t>(e)]);
          highest[static_cast<std::size_t>(d)] = std::max(highest[static_cast<std::size_t>(d)], p.element_owner[static_cast<std::size_t>(e)]);
        }
      }
      Index cut = 0;
      for (std::size_t d = 0; d < lowest.size(); ++d) {
        EXPECT_EQ(p.dof_owner[d], lowest[d]) << what;
        cut += highest[d] != lowest[d];
      }
      EXPECT_EQ(p.interface_dofs, cut) << what;
      EXPECT_EQ(p.offsets.back(), s.num_dofs()) << what;
      for (int r = 0; r < fem::ranks(); ++r) owned += p.owned_elements(r);
      EXPECT_EQ(owned, s.num_elements()) << what;
      if (m == fem::PartitionMethod::Curve) {
        for (int r = 0; r < fem::ranks(); ++r) EXPECT_LE(std::abs(p.owned_elements(r) * fem::ranks() - s.num_elements()), fem::ranks()) << what;
      }
    }
  }
}

// The distributed solution does not depend on the partition: each method's equals CHOLMOD's to 1e-10.
TEST(PetscSystem, SolutionEqualsCholmodForEveryPartition) {
  for (const Case& c : kCases) {
    const basis::Geometry g = geometry_of(c);
    const auto rules = rules_of(c, g);
    const fem::PoissonProblem p = problem_with_neumann();
    const fem::PoissonResult serial = fem::solve_poisson(g, *rules, p);
    for (const std::string method : {"curve", "ptscotch", "metis"}) {
      fem::SolverOptions o = petsc();
      o.partition = method;
      const fem::PoissonResult r = fem::solve_poisson(g, *rules, p, o);
      EXPECT_LE(relative_difference(r.u, serial.u), 1e-10) << c.backend << " by " << method << " at " << fem::ranks() << " ranks";
      EXPECT_EQ(r.partition.method, fem::ranks() > 1 ? method : std::string()) << c.backend;
    }
  }
}

// The matrix and load the ranks assemble, gathered, equal the serial CSC assembly entry by entry.
TEST(PetscSystem, AssembledMatrixEqualsTheSerialOneEntryByEntry) {
  for (const Case& c : kCases) {
    const basis::Geometry g = geometry_of(c);
    const auto rules = rules_of(c, g);
    const fem::Assembler assembler(g, *rules);
    const fem::StiffnessForm k;
    const fem::SourceForm f(fem::manufactured_problem("sine").source);
    const std::vector<const fem::BilinearForm*> bf{&k};
    const std::vector<const fem::LinearForm*> lf{&f};
    Eigen::SparseMatrix<double> a;
    Eigen::VectorXd b;
    assembler.assemble(bf, lf, a, b);
    const std::unique_ptr<fem::LinearSystem> sys = fem::make_linear_system(assembler, petsc());
    assembler.assemble(bf, lf, sys->sink());
    const Eigen::SparseMatrix<double> ap = sys->global_matrix();
    const Eigen::VectorXd bp = sys->global_load();
    const double scale = Eigen::Map<const Eigen::VectorXd>(a.valuePtr(), a.nonZeros()).lpNorm<Eigen::Infinity>();
    const Eigen::SparseMatrix<double> diff = ap - a;
    double worst = 0;
    for (Index j = 0; j < diff.outerSize(); ++j) {
      for (Eigen::SparseMatrix<double>::InnerIterator it(diff, j); it; ++it) worst = std::max(worst, std::abs(it.value()));
    }
    EXPECT_LE(worst, 1e-14 * scale) << c.backend << " at " << fem::ranks() << " ranks";
    EXPECT_LE((bp - b).lpNorm<Eigen::Infinity>(), 1e-14 * b.lpNorm<Eigen::Infinity>()) << c.backend;
  }
}

// The PETSc solution (CG + GAMG, and MUMPS's direct solve) equals CHOLMOD's to 1e-10, relative, with Dirichlet and
// Neumann parts; polyhedral and half-box go through the coupled constraints of their receding boundaries.
TEST(PetscSystem, SolutionEqualsCholmodForEveryBackend) {
  for (const Case& c : kCases) {
    const basis::Geometry g = geometry_of(c);
    const auto rules = rules_of(c, g);
    const fem::PoissonProblem p = problem_with_neumann();
    const fem::PoissonResult serial = fem::solve_poisson(g, *rules, p);
    EXPECT_GT(serial.neumann_edges, 0) << c.backend;  // both kinds of boundary condition are exercised
    EXPECT_GT(serial.dirichlet_edges, 0) << c.backend;
    for (const std::string& options : {std::string(), std::string("-ksp_type preonly -pc_type lu -pc_factor_mat_solver_type mumps")}) {
      const fem::PoissonResult r = fem::solve_poisson(g, *rules, p, petsc(options));
      EXPECT_LE(relative_difference(r.u, serial.u), 1e-10) << c.backend << " " << options << " at " << fem::ranks() << " ranks";
      EXPECT_EQ(r.ranks, fem::ranks());
      EXPECT_EQ(r.free_dofs, serial.free_dofs) << c.backend;
      EXPECT_NEAR(r.errors->l2, serial.errors->l2, 1e-9 * serial.errors->l2) << c.backend;
      Index dofs = 0;
      for (Index d : r.dofs_per_rank) dofs += d;
      EXPECT_EQ(dofs, serial.dofs);
    }
  }
}

// The receding boundaries really are coupled (so the test above covers MatPtAP, not only the selection).
TEST(PetscSystem, RecedingBoundariesHaveCoupledConstraints) {
  for (const Case& c : kCases) {
    if (c.backend != "polyhedral" && c.backend != "halfbox") continue;
    const basis::Geometry g = geometry_of(c);
    const auto rules = rules_of(c, g);
    const fem::Assembler assembler(g, *rules);
    const fem::PoissonProblem p = problem_with_neumann();
    const fem::BoundarySplit split = fem::split_boundary(g, p);
    EXPECT_GT(fem::project_dirichlet(assembler, split.dirichlet, p.dirichlet).coupling.nonZeros(), 0) << c.backend;
  }
}

// A mean-zero problem (pure Neumann) and Nitsche's method go through the same system.
TEST(PetscSystem, MeanZeroAndNitscheEqualCholmod) {
  const Case c{"bspline", "", 3};
  const basis::Geometry g = geometry_of(c);
  const auto rules = rules_of(c, g);
  fem::PoissonProblem p = problem_with_neumann();
  p.dirichlet_method = fem::DirichletMethod::kNitsche;
  EXPECT_LE(relative_difference(fem::solve_poisson(g, *rules, p, petsc()).u, fem::solve_poisson(g, *rules, p).u), 1e-10);
  fem::PoissonProblem n = problem_with_neumann();
  n.neumann_where = fem::make_function([](const Eigen::Vector3d&) { return 1.0; });
  n.mean_zero = true;
  const fem::PoissonResult serial = fem::solve_poisson(g, *rules, n);
  const fem::PoissonResult r = fem::solve_poisson(g, *rules, n, petsc());
  EXPECT_TRUE(r.mean_zero);
  EXPECT_NEAR(r.compatibility_defect, serial.compatibility_defect, 1e-12);
  EXPECT_LE(relative_difference(r.u, serial.u), 1e-10);
}

// Convergence rates (B-spline p = 2, L2 and H1) over three levels equal the serial ones.
TEST(PetscSystem, ConvergenceRatesEqualTheSerialOnes) {
  std::vector<double> l2s, l2p, h1s, h1p;
  for (int level = 2; level <= 4; ++level) {
    basis::BackendFacts facts;
    basis::BackendOptions options;
    options.degree = 2;
    const basis::Geometry g =
        basis::make_refined_geometry(basis::backend("bspline"), nullptr, options, level, facts).geometry;
    const auto rules = quadrature::make_rule_provider("gauss:3", 2);
    const fem::PoissonProblem p = problem_with_neumann();
    const fem::PoissonResult s = fem::solve_poisson(g, *rules, p);
    const fem::PoissonResult r = fem::solve_poisson(g, *rules, p, petsc());
    l2s.push_back(s.errors->l2);
    h1s.push_back(s.errors->h1);
    l2p.push_back(r.errors->l2);
    h1p.push_back(r.errors->h1);
  }
  const double l2 = test::fitted_rate(l2s), h1 = test::fitted_rate(h1s);
  EXPECT_GT(l2, 2.8);
  EXPECT_GT(h1, 1.8);
  EXPECT_NEAR(test::fitted_rate(l2p), l2, 1e-6);
  EXPECT_NEAR(test::fitted_rate(h1p), h1, 1e-6);
}

// A bad option or a KSP that does not converge is one exception with one line, on every rank (no hang).
// Data that fails on some elements only (a source with no value beyond radius 1.9: the outer ring of elements of the
// quarter annulus 1 <= r <= 2, whose radial parameter is r - 1, 8 elements across): the ranks owning them fail in
// the element loop, and every rank throws the lowest failing one's message, named "rank R of N", with its type
// where the rank failed itself; none waits for another (the test would hang).
TEST(PetscSystem, AFailureOnOneRanksElementsStopsEveryRankNamingIt) {
  const Case c{"bspline", "", 3};
  const basis::Geometry g = geometry_of(c);
  const auto rules = rules_of(c, g);
  fem::PoissonProblem p = problem_with_neumann();
  p.source = fem::make_function([](const Eigen::Vector3d& x) -> double {
    if (x.head<2>().norm() > 1.9) throw NumericalError("source: no value at radius " + std::to_string(x.head<2>().norm()));
    return 1.0;
  });
  const fem::Partition part = fem::partition_elements(g, fem::PartitionMethod::Curve);
  int lowest = fem::ranks();  // the lowest rank owning an element of the outer ring (centre radius 1.9375)
  basis::GeometryValues centre;
  for (Index e = 0; e < g.space().num_elements(); ++e) {
    g.evaluate(e, Eigen::Matrix2Xd(Eigen::Vector2d(0.5, 0.5)), centre);
    if (centre.x.col(0).head<2>().norm() > 1.9) lowest = std::min(lowest, part.element_owner[static_cast<std::size_t>(e)]);
  }
  ASSERT_LT(lowest, fem::ranks());
  std::string what = "no error";
  try {
    fem::solve_poisson(g, *rules, p, petsc());
  } catch (const NumericalError& e) {
    what = e.what();
    EXPECT_GE(fem::rank(), lowest) << "a rank that did not fail keeps no type: " << what;
  } catch (const Error& e) {
    what = e.what();
  }
  EXPECT_NE(what.find("source: no value at radius "), std::string::npos) << what;
  if (fem::ranks() > 1) {
    EXPECT_EQ(what.rfind("rank " + std::to_string(lowest) + " of " + std::to_string(fem::ranks()) + ": ", 0), 0u) << what;
  }
  EXPECT_EQ(what.find('\n'), std::string::npos) << what;
}

TEST(PetscSystem, BadOptionsAndFailedSolvesAreOneLineErrors) {
  const Case c{"bspline", "", 2};
  const basis::Geometry g = geometry_of(c);
  const auto rules = rules_of(c, g);
  const fem::PoissonProblem p = problem_with_neumann();
  auto message = [&](const fem::SolverOptions& o) -> std::string {
    try {
      fem::solve_poisson(g, *rules, p, o);
    } catch (const Error& e) {
      return e.what();
    }
    return "no error";
  };
  const std::string unknown = message(petsc("-pc_type no_such_preconditioner"));
  EXPECT_NE(unknown.find("no_such_preconditioner"), std::string::npos) << unknown;
  const std::string unused = message(petsc("-ksp_tyep cg"));
  EXPECT_NE(unused.find("-ksp_tyep was not used"), std::string::npos) << unused;
  fem::SolverOptions few = petsc("-pc_type jacobi");
  few.max_iterations = 2;
  const std::string diverged = message(few);
  EXPECT_NE(diverged.find("DIVERGED_ITS after 2 iterations"), std::string::npos) << diverged;
  for (const std::string& m : {unknown, unused, diverged}) EXPECT_EQ(m.find('\n'), std::string::npos) << m;
  // Options do not leak from one solve into the next: the default solve still works.
  EXPECT_LE(relative_difference(fem::solve_poisson(g, *rules, p, petsc()).u, fem::solve_poisson(g, *rules, p).u), 1e-10);
}

int main(int argc, char** argv) { return test::run_tests_on_every_rank(argc, argv); }
