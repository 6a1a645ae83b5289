#pragma once
// The threads of the process: OpenMP (the element loops and the libraries' parallel regions) and OpenBLAS.
#include <functional>

namespace iga::fem {

/// Sets the number of threads of every pool in the process to n >= 1: OpenMP's for later parallel regions, and
/// OpenBLAS's own pool (openblas_set_num_threads) when the BLAS the process loaded is OpenBLAS. Parallel regions
/// that ask for a fixed number of threads themselves (Debian's CHOLMOD asks for 4) are held to n only inside
/// within_thread_limit().
void set_num_threads(int n);
/// The number of threads a parallel loop would use now.
int num_threads();
/// Runs f so that no OpenMP parallel region inside it, a library's included, gets more than num_threads()
/// threads, whatever its num_threads clause says: f runs in a host teams region with that thread_limit
/// (OpenMP 5.0). An exception from f is rethrown after the region.
void within_thread_limit(const std::function<void()>& f);

}  // namespace iga::fem
