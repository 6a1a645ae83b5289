#pragma once
// The number of threads the element loops use (OpenMP).

namespace iga::fem {

/// Sets the number of threads for later assembly (n >= 1).
void set_num_threads(int n);
/// The number of threads a parallel loop would use now.
int num_threads();

}  // namespace iga::fem
