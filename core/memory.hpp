#pragma once
// What memory this process may still allocate, for the checks that refuse work which cannot fit before it starts
// (fem/memory.hpp: a solve; basis/catmull_clark/levels: a whole refined net).
#include <string>

namespace iga {

/// Bytes this process may still allocate: the smaller of the memory the system reports available
/// (MemAvailable in /proc/meminfo) and the address-space and data-segment limits (ulimit -v / -d) less what
/// the process already uses. Infinity when nothing is known.
double available_memory();

/// "1.2 GiB": bytes for messages.
std::string gib_text(double bytes);

}  // namespace iga
