#include "core/memory.hpp"

#include <sys/resource.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iomanip>
#include <limits>
#include <sstream>
#include <string>

namespace iga {

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

}  // namespace

std::string gib_text(double bytes) {
  std::ostringstream s;
  s << std::setprecision(bytes < 1e10 ? 2 : 3) << bytes / (1024.0 * 1024.0 * 1024.0) << " GiB";
  return s.str();
}

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

}  // namespace iga
