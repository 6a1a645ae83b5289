#pragma once
// PETSc and MPI for the distributed solver ("petsc", fem/linear_system.hpp). A program or driver that may use it
// opens one ParallelSession first (PetscInitialize on PETSC_COMM_WORLD, every process of mpirun; or on a
// communicator the driver hands in). No MPI type appears here, so code that includes iga's headers needs no MPI
// include path; a driver that has an MPI_Comm of its own makes a Communicator with fem/parallel_mpi.hpp.
#include <optional>
#include <string>
#include <vector>

#include "core/types.hpp"

namespace iga::fem {

/// A driver's MPI communicator, as MPI's Fortran handle of it (MPI_Comm_c2f: an integer in every MPI), so that
/// this header needs no MPI type. Made by fem::communicator(MPI_Comm) of fem/parallel_mpi.hpp.
struct Communicator {
  int fortran_handle = 0;
};

class ParallelSession {
 public:
  /// Initialises MPI (unless the caller already did) and PETSc, which reads its options from argv (after `--`
  /// where CLI11 would refuse them) and from the PETSC_OPTIONS environment. PETSc's errors then return codes that
  /// iga turns into one-line exceptions instead of printing tracebacks. InputError when a session is already open.
  ParallelSession(int& argc, char**& argv);
  /// The same on the processes of a driver's communicator, which MPI must already have been initialised for (by
  /// the driver, which finalises it too): iga's ranks, reductions, partitions and PETSc objects are then that
  /// communicator's (PETSc's PETSC_COMM_WORLD is set to it). InputError when MPI is not initialised.
  ParallelSession(int& argc, char**& argv, Communicator comm);
  ~ParallelSession();  ///< PetscFinalize (and MPI_Finalize when this session initialised MPI)
  ParallelSession(const ParallelSession&) = delete;
  ParallelSession& operator=(const ParallelSession&) = delete;

 private:
  ParallelSession(int& argc, char**& argv, std::optional<Communicator> comm);
};

/// Whether a ParallelSession is open.
bool parallel_session_open();
/// This process's rank and the number of ranks of the session's communicator (0 and 1 without a session).
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
