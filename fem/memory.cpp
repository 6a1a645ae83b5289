#include "fem/memory.hpp"

#include <sys/resource.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iomanip>
#include <limits>
#include <sstream>
#include <string>

#include "core/error.hpp"

namespace iga::fem {

namespace {
// A value in kB from a "Key:   123 kB" line of a /proc file, or -1.
double proc_kb(const char* file, const std::string& key) {
  std::ifstream in(file);
  std::string line;
  while (std::getline(in, line)) {
    if (line.compare(0, key.size(), key) == 0 && line.size() > key.size() && line[key.size()] == ':') {
      return std::strtod(line.c_str() + key.size() + 1, nullptr);
    }
  }
  return -1.0;
}

double limit_of(int resource) {
  rlimit l{};
  if (getrlimit(resource, &l) != 0 || l.rlim_cur == RLIM_INFINITY) return std::numeric_limits<double>::infinity();
  return static_cast<double>(l.rlim_cur);
}

std::string gib(double bytes) {
  std::ostringstream s;
  s << std::setprecision(bytes < 1e10 ? 2 : 3) << bytes / (1024.0 * 1024.0 * 1024.0) << " GiB";
  return s.str();
}
}  // namespace

double available_memory() {
  double available = std::numeric_limits<double>::infinity();
  const double system_kb = proc_kb("/proc/meminfo", "MemAvailable");
  if (system_kb > 0) available = system_kb * 1024.0;
  const double used_virtual = std::max(0.0, proc_kb("/proc/self/status", "VmSize")) * 1024.0;
  const double used_data = std::max(0.0, proc_kb("/proc/self/status", "VmData")) * 1024.0;
  available = std::min(available, limit_of(RLIMIT_AS) - used_virtual);
  available = std::min(available, limit_of(RLIMIT_DATA) - used_data);
  return std::max(0.0, available);
}

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
  throw InputError(what + " would need about " + gib(bytes) + " of memory, more than the " + gib(available) +
                   (limit > 0 ? " of --max-memory" : " available") + " (" + advice + ")");
}

}  // namespace iga::fem
