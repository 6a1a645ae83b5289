#pragma once
// Extra cell data for the .vtu writers: named values, one per element.
#include <Eigen/Core>
#include <string>
#include <utility>
#include <vector>

namespace iga::io {

/// Named values, one per element (e.g. "indicator", an error estimator's η_K), written on every VTK cell of the
/// element.
using ElementData = std::vector<std::pair<std::string, Eigen::VectorXd>>;

}  // namespace iga::io
