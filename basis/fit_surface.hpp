#pragma once
// A geometry's control points fitted so that its surface lies on an exact shape (a cylinder, a sphere between two
// latitudes): how the shell obstacle course gets Catmull–Clark nets with extraordinary vertices of the exact
// cylinders and spheres its NURBS patches describe (any backend whose functions sum to one).
#include <Eigen/Core>
#include <array>
#include <string>

#include "basis/geometry.hpp"

namespace iga::basis {

/// A cylinder about the y axis, x = (R sin a, b, R cos a), or a sphere about the origin, x = R (cos b cos a,
/// cos b sin a, sin b) (a the longitude, b the latitude); a ∈ [a0, a1], b ∈ [b0, b1], angles in radians. A range of
/// a spanning 2π is periodic (the whole tube, the whole band): it has no boundary in a.
struct ExactSurface {
  enum class Kind { kCylinder, kSphere };
  Kind kind = Kind::kCylinder;
  double radius = 1.0;
  std::array<double, 2> a{0.0, 1.0}, b{0.0, 1.0};

  Eigen::Vector3d at(double pa, double pb) const;
  bool periodic() const;
  /// The parameters of the shape's point nearest to x, clamped into the ranges.
  Eigen::Vector2d parameters(const Eigen::Vector3d& x) const;
  /// That point; on_boundary: the nearest point of the shape's boundary curves instead (a = a0, a1 unless periodic;
  /// b = b0, b1), the one nearest along the surface.
  Eigen::Vector3d project(const Eigen::Vector3d& x, bool on_boundary = false) const;
  /// "cylinder R = 300, a in [-180, 180] degrees, y in [0, 600]" and the like, for messages.
  std::string description() const;
};

/// "cylinder; R; A0; A1; Y0; Y1" (a in degrees) or "sphere; R; LON0; LON1; LAT0; LAT1" (degrees): the --fit-to option.
/// InputError naming `what` and the text for anything else (a radius that is not > 0, a range that is empty or wider
/// than 360°, a latitude outside [−90, 90]).
ExactSurface parse_exact_surface(const std::string& text, const std::string& what);

struct SurfaceFit {
  Geometry geometry;
  double distance = 0.0;  ///< the largest distance of the fitted surface's samples from the shape
};

/// The control points of g fitted so that its surface lies on the shape: least squares over 5 × 5 samples per element
/// and 11 per boundary side towards their projections (boundary samples onto the shape's boundary curves), repeated
/// `rounds` times (the projections move with the surface). g's surface must lie near the shape already (a net made
/// on it) and its functions sum to one. InputError when g is planar or the least-squares system is singular.
SurfaceFit fit_to_surface(const Geometry& g, const ExactSurface& shape, int rounds = 12);

}  // namespace iga::basis
