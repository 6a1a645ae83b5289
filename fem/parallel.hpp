#pragma once
// PETSc and MPI for the distributed solver ("petsc", fem/linear_system.hpp). A program or driver that may use it
// opens one ParallelSession first (PetscInitialize on PETSC_COMM_WORLD; without mpirun that is one rank). No MPI
// type appears here, so code that includes iga's headers needs no MPI include path.
#include <string>
#include <vector>

#include "core/types.hpp"

namespace iga::fem {

class ParallelSession {
 public:
  /// Initialises MPI (unless the caller already did) and PETSc, which reads its options from argv (after `--`
  /// where CLI11 would refuse them) and from the PETSC_OPTIONS environment. PETSc's errors then return codes that
  /// iga turns into one-line exceptions instead of printing tracebacks. InputError when a session is already open.
  ParallelSession(int& argc, char**& argv);
  ~ParallelSession();  ///< PetscFinalize (and MPI_Finalize when this session initialised MPI)
  ParallelSession(const ParallelSession&) = delete;
  ParallelSession& operator=(const ParallelSession&) = delete;
};

/// Whether a ParallelSession is open.
bool parallel_session_open();
/// This process's rank and the number of ranks in PETSC_COMM_WORLD (0 and 1 without a session).
int rank();
int ranks();
/// The maximum and sum over all ranks (the value itself without a session).
double max_over_ranks(double value);
Index sum_over_ranks(Index value);
double sum_over_ranks(double value);
/// Waits until every rank has come here (nothing without a session).
void barrier();
/// Every rank's value, on every rank (rank order).
std::vector<Index> gather_over_ranks(Index value);

}  // namespace iga::fem
