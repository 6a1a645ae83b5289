#include "refine/uniform.hpp"

namespace iga::refine {

Refinement refine_uniform(const basis::Geometry& geometry, int steps) {
  basis::BackendFacts facts;
  return basis::refine_uniform(geometry, steps, facts);
}

}  // namespace iga::refine
