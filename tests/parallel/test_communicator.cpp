// A driver that hands iga its own communicator (fem/parallel_mpi.hpp): under mpirun at 3 and 4 ranks the world is
// split into the even and the odd ranks, each half opens a ParallelSession on its communicator and solves its own
// problem (the halves different sizes, 2 and 1 ranks at 3) with --solver petsc: each half's ranks are its own, and its
// solution equals CHOLMOD's to 1e-10. The driver initialises and finalises MPI; rank 0 of the world prints.
#include <gtest/gtest.h>

#include "basis/registry.hpp"
#include "fem/parallel_mpi.hpp"
#include "fem/poisson.hpp"
#include "fem/problems.hpp"
#include "support/mixed_problem.hpp"
#include "quadrature/rule_provider.hpp"

using namespace iga;

namespace {
int world_rank = 0, world_size = 1, half = 0, half_size = 1;
}

TEST(Communicator, EachHalfSolvesItsOwnProblemOnItsOwnRanks) {
  EXPECT_EQ(fem::ranks(), half_size);
  EXPECT_EQ(fem::rank(), world_rank / 2);
  EXPECT_EQ(fem::sum_over_ranks(Index{1}), half_size);
  basis::BackendFacts facts;
  basis::BackendOptions options;
  options.degree = 3;
  const int refine = half == 0 ? 3 : 2;  // different problems in the two halves at once
  const basis::Geometry g = basis::make_refined_geometry(basis::backend("bspline"), nullptr, options, refine, facts).geometry;
  const auto rules = quadrature::make_rule_provider(basis::backend_of(g.space()).default_quadrature(3), 3);
  const fem::PoissonProblem p = test::sine_with_neumann_near_y0();
  const fem::PoissonResult serial = fem::solve_poisson(g, *rules, p);
  fem::SolverOptions petsc;
  petsc.kind = fem::SolverKind::Petsc;
  petsc.tolerance = 1e-14;
  const fem::PoissonResult r = fem::solve_poisson(g, *rules, p, petsc);
  EXPECT_EQ(r.ranks, half_size);
  EXPECT_LE((r.u - serial.u).lpNorm<Eigen::Infinity>(), 1e-10 * serial.u.lpNorm<Eigen::Infinity>()) << "half " << half;
  Index elements = 0;
  for (Index e : r.elements_per_rank) elements += e;
  EXPECT_EQ(elements, g.space().num_elements()) << "half " << half;
}

int main(int argc, char** argv) {
  ::testing::InitGoogleTest(&argc, argv);
  MPI_Init(&argc, &argv);
  MPI_Comm_rank(MPI_COMM_WORLD, &world_rank);
  MPI_Comm_size(MPI_COMM_WORLD, &world_size);
  half = world_rank % 2;
  MPI_Comm mine = MPI_COMM_NULL;
  MPI_Comm_split(MPI_COMM_WORLD, half, world_rank, &mine);
  MPI_Comm_size(mine, &half_size);
  int failed = 0;
  {
    int args = 1;
    fem::ParallelSession session(args, argv, fem::communicator(mine));
    if (world_rank > 0) {
      ::testing::TestEventListeners& listeners = ::testing::UnitTest::GetInstance()->listeners();
      delete listeners.Release(listeners.default_result_printer());
    }
    failed = RUN_ALL_TESTS();
  }
  int any = 0;
  MPI_Allreduce(&failed, &any, 1, MPI_INT, MPI_MAX, MPI_COMM_WORLD);
  MPI_Comm_free(&mine);
  MPI_Finalize();
  return any > 0 ? 1 : 0;
}
