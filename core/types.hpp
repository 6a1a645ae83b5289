#pragma once
// Basic types shared by every module of iga.
#include <cstdint>

namespace iga {

/// Index of a vertex, face, element or degree of freedom. Signed (Eigen's convention), 64 bit.
using Index = std::int64_t;

}  // namespace iga
