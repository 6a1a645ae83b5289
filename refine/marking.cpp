#include "refine/marking.hpp"

#include <algorithm>
#include <numeric>

#include "core/error.hpp"

namespace iga::refine {

Marking parse_marking(const std::string& name) {
  if (name == "doerfler") return Marking::Doerfler;
  if (name == "max") return Marking::Maximum;
  throw InputError("--mark: unknown marking '" + name + "' (doerfler or max)");
}

std::string to_string(Marking m) { return m == Marking::Doerfler ? "doerfler" : "max"; }

std::vector<Index> mark(const Eigen::VectorXd& eta, Marking strategy, double theta) {
  if (!(theta > 0.0 && theta <= 1.0)) throw InputError("marking: theta must be in (0, 1], got " + std::to_string(theta));
  if (!eta.allFinite()) throw InputError("marking: an error indicator is not finite");
  std::vector<Index> marked;
  const double max = eta.size() > 0 ? eta.maxCoeff() : 0.0;
  if (max <= 0.0) return marked;
  if (strategy == Marking::Maximum) {
    for (Index e = 0; e < eta.size(); ++e) {
      if (eta(e) >= theta * max) marked.push_back(e);
    }
    return marked;
  }
  std::vector<Index> order(static_cast<std::size_t>(eta.size()));
  std::iota(order.begin(), order.end(), Index{0});
  std::sort(order.begin(), order.end(), [&](Index a, Index b) { return eta(a) > eta(b) || (eta(a) == eta(b) && a < b); });
  const double goal = theta * eta.squaredNorm();
  double sum = 0.0;
  for (Index e : order) {
    if (sum >= goal) break;
    marked.push_back(e);
    sum += eta(e) * eta(e);
  }
  std::sort(marked.begin(), marked.end());
  return marked;
}

}  // namespace iga::refine
