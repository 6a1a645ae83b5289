#include "fem/parallel.hpp"

#include <mpi.h>
#include <petscsys.h>

#include <cstdlib>

#include "core/error.hpp"

namespace iga::fem {

namespace {
bool session_open = false;
bool session_owns_mpi = false;
}  // namespace

ParallelSession::ParallelSession(int& argc, char**& argv) : ParallelSession(argc, argv, std::nullopt) {}

ParallelSession::ParallelSession(int& argc, char**& argv, Communicator comm)
    : ParallelSession(argc, argv, std::optional<Communicator>(comm)) {}

ParallelSession::ParallelSession(int& argc, char**& argv, std::optional<Communicator> comm) {
  if (session_open) throw InputError("a parallel session is already open");
  // PT-Scotch (the ptscotch partition) on threads of its own needs MPI_THREAD_MULTIPLE and then hung at 4 ranks
  // on this machine; on one thread it is also the same partition for the same graph. A user's setting is kept.
  setenv("SCOTCH_PTHREAD_NUMBER", "1", 0);
  int mpi_up = 0;
  MPI_Initialized(&mpi_up);
  if (comm && !mpi_up) {
    throw InputError("a parallel session on a driver's communicator needs MPI initialised by the driver first");
  }
  if (!mpi_up) {
    MPI_Init(&argc, &argv);
    session_owns_mpi = true;
  }
  // Every object and reduction of iga and PETSc is on PETSC_COMM_WORLD: the driver's communicator, or the world.
  PETSC_COMM_WORLD = comm ? MPI_Comm_f2c(static_cast<MPI_Fint>(comm->fortran_handle)) : MPI_COMM_WORLD;
  // PETSc's own report of a leftover option at PetscFinalize is replaced by iga's check (fem/petsc_system.cpp).
  PetscOptionsSetValue(nullptr, "-options_left", "0");
  if (PetscInitialize(&argc, &argv, nullptr, nullptr) != 0) {
    if (session_owns_mpi) MPI_Finalize();
    throw InputError("PETSc could not be initialised (a malformed PETSC_OPTIONS or command-line option?)");
  }
  PetscPushErrorHandler(PetscReturnErrorHandler, nullptr);
  session_open = true;
}

ParallelSession::~ParallelSession() {
  PetscPopErrorHandler();
  PetscFinalize();
  if (session_owns_mpi) MPI_Finalize();
  session_open = false;
  session_owns_mpi = false;
}

bool parallel_session_open() { return session_open; }

int rank() {
  if (!session_open) return 0;
  int r = 0;
  MPI_Comm_rank(PETSC_COMM_WORLD, &r);
  return r;
}

int ranks() {
  if (!session_open) return 1;
  int n = 1;
  MPI_Comm_size(PETSC_COMM_WORLD, &n);
  return n;
}

double max_over_ranks(double value) {
  if (!session_open) return value;
  double out = value;
  MPI_Allreduce(&value, &out, 1, MPI_DOUBLE, MPI_MAX, PETSC_COMM_WORLD);
  return out;
}

Index sum_over_ranks(Index value) {
  if (!session_open) return value;
  long long in = value, out = 0;
  MPI_Allreduce(&in, &out, 1, MPI_LONG_LONG, MPI_SUM, PETSC_COMM_WORLD);
  return static_cast<Index>(out);
}

void barrier() {
  if (session_open) MPI_Barrier(PETSC_COMM_WORLD);
}

double sum_over_ranks(double value) {
  if (!session_open) return value;
  double out = 0;
  MPI_Allreduce(&value, &out, 1, MPI_DOUBLE, MPI_SUM, PETSC_COMM_WORLD);
  return out;
}

std::vector<Index> gather_over_ranks(Index value) {
  if (!session_open) return {value};
  const long long in = value;
  std::vector<long long> all(static_cast<std::size_t>(ranks()));
  MPI_Allgather(&in, 1, MPI_LONG_LONG, all.data(), 1, MPI_LONG_LONG, PETSC_COMM_WORLD);
  return {all.begin(), all.end()};
}

}  // namespace iga::fem
