#pragma once
// The BEM solution at the sample points of the FEM geometry it was taken from (the same domain in both
// methods): on the boundary sides from the boundary solution u_h, inside by the representation formula (4.50).
#include <Eigen/Core>
#include <functional>
#include <vector>

#include "basis/curve/trace_space.hpp"
#include "basis/geometry.hpp"
#include "bem/boundary_discretization.hpp"
#include "bem/solve.hpp"

namespace iga::bem {

/// Values at every element's reference points ref_points(shape) (2 × q) of `geometry`, whose boundary is
/// `trace` (trace_geometry(geometry)) discretised by d. A point on a boundary side of its element (reference
/// coordinate within 1e-14 of the side) gets u_h of the boundary solution there; all others are evaluated
/// together by evaluate_interior, except those at the position of a boundary-side point (1e-12 of the diameter),
/// which take its value (elements that touch the boundary at a corner only). `on_boundary` (optional) receives per element which points were on the boundary.
std::vector<Eigen::VectorXd> sample_on_geometry(const basis::Geometry& geometry, const basis::TraceSpace& trace,
                                                const BoundaryDiscretization& d, const Solution& solution,
                                                const std::function<Eigen::Matrix2Xd(basis::Shape)>& ref_points,
                                                std::vector<std::vector<char>>* on_boundary = nullptr);

/// The side parameter t of reference point p on side `side` of a shape (inverse of basis::side_point), or −1 when
/// p is not on that side (farther than tol).
double side_parameter(basis::Shape shape, int side, const Eigen::Vector2d& p, double tol = 1e-14);

}  // namespace iga::bem
