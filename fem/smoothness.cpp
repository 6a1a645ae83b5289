#include "fem/smoothness.hpp"

#include <sstream>
#include <vector>

#include "core/error.hpp"

namespace iga::fem {

namespace {

std::string side_midpoint(const basis::Geometry& geometry, Index e, int side) {
  Eigen::Matrix2Xd mid(2, 1);
  mid.col(0) = basis::side_point(geometry.space().kind(e).shape, side, 0.5);
  basis::GeometryValues gv;
  geometry.evaluate(e, mid, gv);
  std::ostringstream s;
  s << "(" << gv.x(0, 0) << ", " << gv.x(1, 0);
  if (geometry.dim() == 3) s << ", " << gv.x(2, 0);
  s << ")";
  return s.str();
}

}  // namespace

std::string check_c1(const basis::Geometry& geometry, const std::string& problem, const std::string& equation) {
  const basis::Space& space = geometry.space();
  for (Index e = 0; e < space.num_elements(); ++e) {
    const std::optional<int> degree = space.polynomial_degree(e);
    if (degree && *degree < 2) {
      throw InputError(problem + ": element " + std::to_string(e) + " has degree " + std::to_string(*degree) +
                       ": its functions are not in H² (" + equation + " needs a C1 space of degree >= 2)");
    }
  }
  std::vector<basis::InteriorEdge> edges;
  try {
    edges = space.interior_edges();
  } catch (const UnsupportedError&) {
    return "not checked edge by edge (the " + space.name() + " space lists no interior edges; C1 by construction)";
  }
  for (const basis::InteriorEdge& edge : edges) {
    if (edge.continuity < 1) {
      throw InputError(problem + ": the space is only C0 across the side shared by elements " +
                       std::to_string(edge.element[0]) + " and " + std::to_string(edge.element[1]) +
                       " (midpoint " + side_midpoint(geometry, edge.element[0], edge.side[0]) + "): " + equation +
                       " needs a C1 space (degree >= 2, no repeated interior knot)");
    }
  }
  return "C1 across all " + std::to_string(edges.size()) + " interior edges";
}

}  // namespace iga::fem
