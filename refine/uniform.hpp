#pragma once
// Uniform h-refinement of a geometry: a new space, the same map, and the prolongation between them.
#include <Eigen/Sparse>

#include "basis/geometry.hpp"

namespace iga::refine {

struct Refinement {
  basis::Geometry geometry;                  ///< the refined geometry (the same map)
  Eigen::SparseMatrix<double> prolongation;  ///< fine coefficients = prolongation × coarse coefficients
};

/// `steps` rounds of uniform refinement; each element splits into four and the map is unchanged.
/// Tensor-product B-splines: the midpoint of every non-empty knot interval is inserted in both directions
/// by the refine-and-smooth algorithm (refine_smooth.hpp; equal to Oslo/Boehm knot insertion to 1e-12). Catmull–Clark: the control net is subdivided (refine_net), the new space is that
/// of the refined net. UnsupportedError for other spaces (named). steps = 0 returns the geometry with the
/// identity.
Refinement refine_uniform(const basis::Geometry& geometry, int steps);

}  // namespace iga::refine
