#include "basis/space.hpp"

#include "core/error.hpp"

namespace iga::basis {

Eigen::Vector2d side_point(int side, double t) {
  switch (side) {
    case 0: return {t, 0.0};
    case 1: return {1.0, t};
    case 2: return {1.0 - t, 1.0};
    case 3: return {0.0, 1.0 - t};
    default: throw InputError("side_point: side " + std::to_string(side) + " is not 0..3");
  }
}

Eigen::Vector2d side_tangent(int side) {
  switch (side) {
    case 0: return {1.0, 0.0};
    case 1: return {0.0, 1.0};
    case 2: return {-1.0, 0.0};
    case 3: return {0.0, -1.0};
    default: throw InputError("side_tangent: side " + std::to_string(side) + " is not 0..3");
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
  return s;
}

}  // namespace iga::basis
