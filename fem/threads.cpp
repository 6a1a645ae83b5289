#include "fem/threads.hpp"

#include <omp.h>

#include "core/error.hpp"

namespace iga::fem {

void set_num_threads(int n) {
  if (n < 1) throw InputError("number of threads must be >= 1, got " + std::to_string(n));
  omp_set_num_threads(n);
}

int num_threads() { return omp_get_max_threads(); }

}  // namespace iga::fem
