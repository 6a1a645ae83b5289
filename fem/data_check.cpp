#include "fem/data_check.hpp"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "fem/expression.hpp"

namespace iga::fem {

namespace {

constexpr const char* kWhy = "singular data inside the domain have no finite load";

std::string point(const Eigen::Vector3d& x, int dim) {
  std::ostringstream s;
  s << std::setprecision(6) << "(" << x(0) << ", " << x(1);
  if (dim == 3) s << ", " << x(2);
  s << ")";
  return s.str();
}

// An element's sample points: corner, midpoint of side 0, corner, midpoint of side 1, ... (around the element,
// counter-clockwise), then the centre; on_boundary[k] when point k lies on a boundary side.
struct Samples {
  Eigen::Matrix2Xd reference;
  std::vector<char> on_boundary;
  int ring = 0;  // the points around the element; the centre is the last
  const char* what(int k) const { return k == ring ? "the centre" : (k % 2 == 0 ? "a corner" : "a side's midpoint"); }
};

Samples samples(basis::Shape shape, const std::vector<char>& boundary_side) {
  Samples s;
  const int sides = basis::num_sides(shape);
  s.ring = 2 * sides;
  s.reference.resize(2, s.ring + 1);
  s.on_boundary.assign(static_cast<std::size_t>(s.ring + 1), 0);
  for (int side = 0; side < sides; ++side) {
    s.reference.col(2 * side) = basis::side_point(shape, side, 0.0);
    s.reference.col(2 * side + 1) = basis::side_point(shape, side, 0.5);
    const bool here = boundary_side[static_cast<std::size_t>(side)] != 0;
    const bool before = boundary_side[static_cast<std::size_t>((side + sides - 1) % sides)] != 0;
    s.on_boundary[static_cast<std::size_t>(2 * side)] = here || before;
    s.on_boundary[static_cast<std::size_t>(2 * side + 1)] = here;
  }
  s.reference.col(s.ring) = shape == basis::Shape::Quad ? Eigen::Vector2d(0.5, 0.5) : Eigen::Vector2d(1.0 / 3, 1.0 / 3);
  return s;
}

// The singular factors on one element: a zero at a point inside, or a change of sign between neighbours.
void check_factors(const Expression& f, Index e, const Samples& s, const Eigen::Matrix3Xd& x, int dim) {
  Eigen::MatrixXd d;
  f.singular_factors(x, d);
  const Eigen::Index n = x.cols();
  for (Eigen::Index i = 0; i < d.rows(); ++i) {
    const std::string factor = f.singular_factor_names()[static_cast<std::size_t>(i)];
    const std::string head = f.what() + " " + f.quoted() + ": " + factor;
    double scale = 0.0;
    for (Eigen::Index k = 0; k < n; ++k) {
      if (std::isfinite(d(i, k))) scale = std::max(scale, std::abs(d(i, k)));
    }
    const double tiny = 1e-12 * scale;
    for (Eigen::Index k = 0; k < n; ++k) {
      if (s.on_boundary[static_cast<std::size_t>(k)] || !std::isfinite(d(i, k)) || std::abs(d(i, k)) > tiny) continue;
      throw InputError(head + " vanishes at " + point(x.col(k), dim) + " (element " + std::to_string(e) + ", " +
                       s.what(static_cast<int>(k)) + "): " + kWhy);
    }
    // Neighbours: along the ring, and each ring point with the centre.
    for (int k = 0; k < 2 * s.ring; ++k) {
      const Eigen::Index a = k < s.ring ? k : k - s.ring;
      const Eigen::Index b = k < s.ring ? (k + 1) % s.ring : s.ring;
      const double da = d(i, a), db = d(i, b);
      if (!(std::abs(da) > tiny && std::abs(db) > tiny && std::isfinite(da) && std::isfinite(db) && (da < 0) != (db < 0))) continue;
      const Eigen::Vector3d zero = x.col(a) + da / (da - db) * (x.col(b) - x.col(a));
      throw InputError(head + " changes sign inside element " + std::to_string(e) + ", between " + point(x.col(a), dim) +
                       " and " + point(x.col(b), dim) + " (zero near " + point(zero, dim) + "): " + kWhy);
    }
  }
}

}  // namespace

void check_domain_data(const basis::Geometry& geometry, const Function& function) {
  const auto* f = dynamic_cast<const Expression*>(&function);
  if (!f) return;
  const basis::Space& space = geometry.space();
  const int dim = geometry.dim();
  std::vector<std::vector<char>> boundary(static_cast<std::size_t>(space.num_elements()));
  for (const basis::BoundaryEdge& b : space.boundary_edges()) {
    auto& sides = boundary[static_cast<std::size_t>(b.element)];
    sides.resize(4, 0);
    sides[static_cast<std::size_t>(b.side)] = 1;
  }
  basis::BasisValues bv;
  basis::GeometryValues gv;
  Eigen::VectorXd v;
  for (Index e = 0; e < space.num_elements(); ++e) {
    auto& sides = boundary[static_cast<std::size_t>(e)];
    sides.resize(4, 0);
    const Samples s = samples(space.kind(e).shape, sides);
    space.evaluate(e, s.reference, 1, bv);
    geometry.evaluate(e, bv, gv, false);
    f->values_unchecked(gv.x, v);
    for (Eigen::Index k = 0; k < v.size(); ++k) {
      if (std::isfinite(v(k)) || s.on_boundary[static_cast<std::size_t>(k)]) continue;
      throw InputError(f->what() + " " + f->quoted() + " is not finite at " + point(gv.x.col(k), dim) + " (element " +
                       std::to_string(e) + ", " + s.what(static_cast<int>(k)) + "): " + kWhy);
    }
    check_factors(*f, e, s, gv.x, dim);
  }
}

}  // namespace iga::fem
