#pragma once
// Memory a run will need, predicted before the work that allocates it, so that a run which cannot fit is
// refused at once with one line (what it would need, what is available) instead of ending in std::bad_alloc
// or the kernel's OOM killer after seconds of work.
#include <string>

#include "core/memory.hpp"

namespace iga::fem {

/// core/memory.hpp's, here too.
using ::iga::available_memory;

/// A lower estimate of the peak memory of a Poisson solve with `elements` elements of at most `local_dofs`
/// functions each (about as many dofs as elements): the element contexts and the sparse matrix with its
/// reduced copy (nnz ≈ 3 local_dofs per row), the CHOLMOD factor (2D nested dissection: nnz(L) grows like
/// n log n), and the solution output. Calibrated on bicubic B-splines and Catmull–Clark below the true peak
/// (benchmarks/README.md), so a run it refuses could not have fitted.
double poisson_memory(double elements, int local_dofs);

/// Bytes of a .vtu with `elements` elements sampled at samples × samples points each (VTK's arrays and the
/// written file's encoding buffer), again a lower estimate.
double vtu_memory(double elements, int samples);

/// InputError "<what> would need about X GiB of memory, more than the Y GiB available (<how to shrink>)"
/// when bytes > limit (limit <= 0: available_memory()).
void check_memory(double bytes, double limit, const std::string& what, const std::string& advice);

}  // namespace iga::fem
