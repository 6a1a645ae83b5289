#include "fem/memory.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "core/error.hpp"

namespace iga::fem {

double poisson_memory(double elements, int local_dofs) {
  const double n = std::max(elements, 1.0);
  const double matrix = n * 3.0 * local_dofs * 12.0 * 3.0;  // pattern, matrix, reduced copy: value + index
  const double factor = n * std::log2(n + 2.0) * 8.0 * 4.0;  // nnz(L) ≳ 4 n log2 n doubles (see the calibration)
  const double per_element = n * 400.0;                       // geometry, dofs, colours, solution and output
  return matrix + factor + per_element;
}

double vtu_memory(double elements, int samples) {
  const double points = std::max(elements, 1.0) * samples * samples;
  return points * 100.0;  // coordinates, u, grad u, exact, error (~10 doubles), connectivity, encoding buffer
}

void check_memory(double bytes, double limit, const std::string& what, const std::string& advice) {
  const double available = limit > 0 ? limit : available_memory();
  if (!(bytes > available)) return;
  throw InputError(what + " would need about " + gib_text(bytes) + " of memory, more than the " + gib_text(available) +
                   (limit > 0 ? " of --max-memory" : " available") + " (" + advice + ")");
}

}  // namespace iga::fem
