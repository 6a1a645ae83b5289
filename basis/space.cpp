#include "basis/space.hpp"

#include "core/error.hpp"

namespace iga::basis {

int num_sides(Shape shape) { return shape == Shape::Quad ? 4 : 3; }

namespace {
void check_side(Shape shape, int side) {
  if (side < 0 || side >= num_sides(shape)) {
    throw InputError("side " + std::to_string(side) + " of a " + (shape == Shape::Quad ? "quad" : "triangle") +
                     " element is not 0.." + std::to_string(num_sides(shape) - 1));
  }
}
}  // namespace

Eigen::Vector2d side_point(Shape shape, int side, double t) {
  check_side(shape, side);
  if (shape == Shape::Triangle) {
    switch (side) {
      case 0: return {t, 0.0};
      case 1: return {1.0 - t, t};
      default: return {0.0, 1.0 - t};
    }
  }
  switch (side) {
    case 0: return {t, 0.0};
    case 1: return {1.0, t};
    case 2: return {1.0 - t, 1.0};
    default: return {0.0, 1.0 - t};
  }
}

Eigen::Vector2d side_tangent(Shape shape, int side) {
  check_side(shape, side);
  if (shape == Shape::Triangle) {
    switch (side) {
      case 0: return {1.0, 0.0};
      case 1: return {-1.0, 1.0};
      default: return {0.0, -1.0};
    }
  }
  switch (side) {
    case 0: return {1.0, 0.0};
    case 1: return {0.0, 1.0};
    case 2: return {-1.0, 0.0};
    default: return {0.0, -1.0};
  }
}

std::string to_string(const ElementKind& k) {
  std::string s = k.shape == Shape::Quad ? "quad" : "triangle";
  switch (k.family) {
    case Family::Regular: s += "/regular"; break;
    case Family::Irregular: s += "/irregular:" + std::to_string(k.valence); break;
    case Family::Polar: s += "/polar:" + std::to_string(k.valence); break;
    case Family::TJunction: s += "/t-junction"; break;
  }
  if (k.scheme == Scheme::CatmullClark) s += " (catmull-clark)";
  if (k.scheme == Scheme::HalfBox) s += " (half-box)";
  if (k.family == Family::Irregular && k.boundary) s += " at the boundary";
  return s;
}

std::vector<InteriorEdge> Space::interior_edges() const {
  throw UnsupportedError("interior edges are not implemented for the '" + name() + "' basis");
}

void Space::from_reference(Index, const BasisValues& reference, int derivatives, BasisValues& out) const {
  BasisValues::for_each_block(reference, out, derivatives, [](const Eigen::MatrixXd& from, Eigen::MatrixXd& to) { to = from; });
}

}  // namespace iga::basis
