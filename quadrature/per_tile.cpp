#include "quadrature/per_tile.hpp"

#include <cmath>

#include "core/error.hpp"
#include "quadrature/gauss_legendre.hpp"
#include "quadrature/tensor_rule.hpp"

namespace iga::quadrature {

namespace {
// Appends `rule` (on the unit square or the unit triangle) mapped by the affine map (s, t) ↦ a + s (b − a) +
// t (c − a), weights scaled by its Jacobian.
void append_mapped(const Rule& rule, const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& c,
                   Rule& out, Eigen::Index& k) {
  const double jac = std::abs((b - a).x() * (c - a).y() - (b - a).y() * (c - a).x());
  for (Eigen::Index i = 0; i < rule.size(); ++i, ++k) {
    out.points.col(k) = a + rule.points(0, i) * (b - a) + rule.points(1, i) * (c - a);
    out.weights(k) = jac * rule.weights(i);
  }
}

// The square rule on [u0, u0 + h] × [v0, v0 + h].
void append_square(const Rule& square, double u0, double v0, double h, Rule& out, Eigen::Index& k) {
  append_mapped(square, {u0, v0}, {u0 + h, v0}, {u0, v0 + h}, out, k);
}
}  // namespace

Rule tiled_triangle_rule(int p, int levels) {
  if (levels < 1 || levels > 50) throw InputError("tiled rule: levels must be 1..50, got " + std::to_string(levels));
  const Rule1D line = gauss_legendre(p);
  const Rule triangle = collapsed_triangle_rule(line, line);
  Rule out;
  const Eigen::Index n = triangle.size() * (3 * levels + 1);
  out.points.resize(2, n);
  out.weights.resize(n);
  Eigen::Index k = 0;
  for (int l = 1; l <= levels; ++l) {
    const double a = std::ldexp(1.0, -l);
    append_mapped(triangle, {a, 0.0}, {2 * a, 0.0}, {a, a}, out, k);  // Ω_{1,l}
    append_mapped(triangle, {a, 0.0}, {a, a}, {0.0, a}, out, k);      // Ω_{2,l}
    append_mapped(triangle, {0.0, a}, {a, a}, {0.0, 2 * a}, out, k);  // Ω_{3,l}
  }
  const double h = std::ldexp(1.0, -levels);
  append_mapped(triangle, {0.0, 0.0}, {h, 0.0}, {0.0, h}, out, k);  // the remaining corner triangle
  return out;
}

Rule tiled_rule(int p, int levels) {
  if (levels < 1 || levels > 50) throw InputError("tiled rule: levels must be 1..50, got " + std::to_string(levels));
  const Rule1D line = gauss_legendre(p);
  const Rule square = tensor_rule(line, line);
  Rule out;
  const Eigen::Index n = square.size() * (3 * levels + 1);
  out.points.resize(2, n);
  out.weights.resize(n);
  Eigen::Index k = 0;
  for (int l = 1; l <= levels; ++l) {
    const double h = std::ldexp(1.0, -l);  // 2^-l
    append_square(square, h, 0.0, h, out, k);  // Ω_{1,l}
    append_square(square, h, h, h, out, k);    // Ω_{2,l}
    append_square(square, 0.0, h, h, out, k);  // Ω_{3,l}
  }
  append_square(square, 0.0, 0.0, std::ldexp(1.0, -levels), out, k);  // the remaining corner square
  return out;
}

PerTile::PerTile(int points_per_direction, int levels)
    : gauss_(points_per_direction),
      levels_(levels),
      tiled_(tiled_rule(points_per_direction, levels)),
      tiled_triangle_(tiled_triangle_rule(points_per_direction, levels)) {}

const Rule& PerTile::rule(const basis::ElementKind& kind) const {
  if (is_catmull_clark_irregular(kind)) return tiled_;
  if (kind.shape == basis::Shape::Triangle && kind.family == basis::Family::Irregular &&
      kind.scheme == basis::Scheme::HalfBox) {
    return tiled_triangle_;
  }
  return polynomial_rule(gauss_, kind, name());
}

std::string PerTile::name() const {
  return "tiles:" + std::to_string(gauss_.points_per_direction()) + ":" + std::to_string(levels_);
}

}  // namespace iga::quadrature
