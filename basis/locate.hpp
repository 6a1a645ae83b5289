#pragma once
// Where a physical point lies on a geometry: the element and reference point whose image is nearest to it, for
// point loads, point supports and named points of a report, on any backend.
#include <Eigen/Core>
#include <string>

#include "basis/geometry.hpp"

namespace iga::basis {

struct LocatedPoint {
  Index element = 0;
  Eigen::Vector2d uv = Eigen::Vector2d::Zero();  ///< reference point in the element (unit square or triangle)
  Eigen::Vector3d x = Eigen::Vector3d::Zero();   ///< its image
  double distance = 0.0;                         ///< |x − the point asked for|
};

/// The nearest point of the geometry to `point` (planar geometries: z = 0): every element sampled on a 9 × 9 grid
/// of its reference domain, then Gauss–Newton on the closest candidates, kept inside the reference domain. Points
/// where the map degenerates (an extraordinary vertex's corner) are reached by the sampling, which includes the
/// corners.
LocatedPoint nearest_point(const Geometry& geometry, const Eigen::Vector3d& point);

/// nearest_point, or InputError "<what>: (x, y, z) is not on the surface: the nearest point of the geometry is
/// (..) at distance d, more than the a allowed" when the distance exceeds a = max(`tolerance` × the control net's
/// extent, `allowance`). The allowance is for a geometry that approximates the intended surface (a net fitted to an
/// exact shape: BackendFacts::fit_distance), whose points are given on the intended one.
LocatedPoint locate_point(const Geometry& geometry, const Eigen::Vector3d& point, const std::string& what,
                          double tolerance = 1e-6, double allowance = 0.0);

}  // namespace iga::basis
