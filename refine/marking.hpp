#pragma once
// Marking strategies for adaptive refinement (thesis §4.1.6): which elements an estimate → mark → refine loop
// refines.
#include <Eigen/Core>
#include <string>
#include <vector>

#include "core/types.hpp"

namespace iga::refine {

enum class Marking {
  Doerfler,  ///< bulk criterion: the fewest elements with Σ_M η_K² >= θ Σ η_K² (largest indicators first)
  Maximum,   ///< every element with η_K >= θ max η
};

/// "doerfler" or "max"; InputError otherwise.
Marking parse_marking(const std::string& name);
std::string to_string(Marking m);

/// The marked elements, ascending. θ in (0, 1] (InputError otherwise, and for a non-finite indicator). Ties
/// are broken by element index, so the set is reproducible. An all-zero estimate marks nothing.
std::vector<Index> mark(const Eigen::VectorXd& indicators, Marking strategy, double theta);

}  // namespace iga::refine
