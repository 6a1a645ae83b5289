#pragma once
// Uniform h-refinement of a geometry: a new space, the same map, and the prolongation between them, through
// the backend registry (basis/registry.hpp).
#include <Eigen/Sparse>

#include "basis/geometry.hpp"
#include "basis/registry.hpp"

namespace iga::refine {

using Refinement = basis::Refinement;

/// `steps` rounds of uniform refinement through the geometry's backend; each element splits into four and
/// the map is unchanged. Tensor-product B-splines: the midpoint of every non-empty knot interval is inserted
/// in both directions (Oslo; equal to the refine-and-smooth algorithm of refine_smooth.hpp to 1e-12, which
/// refine_smooth_tensor applies to chosen intervals). Catmull–Clark: the control net is subdivided. Polyhedral:
/// the net is refined and the space rebuilt (not nested: Refinement::nested is false, no prolongation).
/// UnsupportedError for a backend without refinement (named). steps = 0 returns the geometry with the identity.
Refinement refine_uniform(const basis::Geometry& geometry, int steps);

}  // namespace iga::refine
