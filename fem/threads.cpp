#include "fem/threads.hpp"

#include <dlfcn.h>
#include <omp.h>

#include <exception>
#include <string>

#include "core/error.hpp"

namespace iga::fem {

void set_num_threads(int n) {
  if (n < 1) throw InputError("number of threads must be >= 1, got " + std::to_string(n));
  omp_set_num_threads(n);
  // OpenBLAS keeps a pthread pool of its own, sized from OPENBLAS_NUM_THREADS or the cores when it is loaded.
  // It is looked up rather than linked: the BLAS behind libblas.so.3 is chosen by Debian's alternatives.
  using SetThreads = void (*)(int);
  if (void* symbol = dlsym(RTLD_DEFAULT, "openblas_set_num_threads")) reinterpret_cast<SetThreads>(symbol)(n);
}

int num_threads() { return omp_get_max_threads(); }

void within_thread_limit(const std::function<void()>& f) {
  const int limit = num_threads();
  std::exception_ptr failure;
#pragma omp teams num_teams(1) thread_limit(limit)
  {
    try {
      f();
    } catch (...) {
      failure = std::current_exception();
    }
  }
  if (failure) std::rethrow_exception(failure);
}

}  // namespace iga::fem
