#pragma once
// For a driver that uses MPI itself (and links it: find_package(MPI), MPI::MPI_CXX): a fem::Communicator from its
// MPI_Comm, to open iga's ParallelSession on some of its processes. iga's other headers include no MPI header.
#include <mpi.h>

#include "fem/parallel.hpp"

namespace iga::fem {

inline Communicator communicator(MPI_Comm comm) { return Communicator{static_cast<int>(MPI_Comm_c2f(comm))}; }

}  // namespace iga::fem
