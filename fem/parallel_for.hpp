#pragma once
// A parallel loop whose failures are deterministic: the shared way iga's OpenMP loops (the assembler's element
// loops, the BEM's collocation and interior loops) turn an exception inside a parallel region, which OpenMP would
// end with std::terminate, into the one exception of the lowest failing index, rethrown after the region.
#include <atomic>
#include <exception>
#include <mutex>

#include "core/types.hpp"

namespace iga::fem {

/// Runs body(i) for i in [0, n) with OpenMP: schedule(static), or schedule(dynamic, chunk) for chunk > 0 (loops of
/// uneven iterations). When bodies throw, the exception of the lowest index is rethrown after the loop, whatever the
/// thread count and timing (an index is skipped only above a known failure, so every lower one runs): the same input
/// gives the same message.
template <class Body>
void parallel_for(Index n, Body&& body, int chunk = 0) {
  std::exception_ptr error;
  std::atomic<Index> failed_at{n};
  std::mutex m;
  auto run = [&](Index i) {
    if (i > failed_at.load(std::memory_order_relaxed)) return;
    try {
      body(i);
    } catch (...) {
      std::lock_guard<std::mutex> lock(m);
      if (i < failed_at.load()) {
        error = std::current_exception();
        failed_at = i;
      }
    }
  };
  if (chunk > 0) {
#pragma omp parallel for schedule(dynamic, chunk)
    for (Index i = 0; i < n; ++i) run(i);
  } else {
#pragma omp parallel for schedule(static)
    for (Index i = 0; i < n; ++i) run(i);
  }
  if (error) std::rethrow_exception(error);
}

}  // namespace iga::fem
