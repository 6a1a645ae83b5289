#include "quadrature/per_tile.hpp"

#include <array>
#include <cmath>
#include <functional>

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

// Corners (a, b, c) of an affine image of the reference square or triangle: the three tiles of layer l and the
// corner piece left below the last layer.
using Corners = std::array<Eigen::Vector2d, 3>;

// The rule `base` (on the reference square or triangle) on the three tiles tiles(2^-l) of every layer
// l = 1..levels and on the corner piece corner(2^-levels).
Rule layered_rule(const Rule& base, int levels, const std::function<std::array<Corners, 3>(double)>& tiles,
                  const std::function<Corners(double)>& corner) {
  if (levels < 1 || levels > 50) throw InputError("tiled rule: levels must be 1..50, got " + std::to_string(levels));
  Rule out;
  const Eigen::Index n = base.size() * (3 * levels + 1);
  out.points.resize(2, n);
  out.weights.resize(n);
  Eigen::Index k = 0;
  for (int l = 1; l <= levels; ++l) {
    for (const Corners& t : tiles(std::ldexp(1.0, -l))) append_mapped(base, t[0], t[1], t[2], out, k);
  }
  const Corners c = corner(std::ldexp(1.0, -levels));
  append_mapped(base, c[0], c[1], c[2], out, k);
  return out;
}
}  // namespace

Rule tiled_triangle_rule(int p, int levels) {
  const Rule1D line = gauss_legendre(p);
  // Ω_{1,l}, Ω_{2,l} (the middle, down-oriented triangle), Ω_{3,l}; then the corner triangle u + v <= 2^-L.
  return layered_rule(
      collapsed_triangle_rule(line, line), levels,
      [](double a) {
        return std::array<Corners, 3>{Corners{{{a, 0.0}, {2 * a, 0.0}, {a, a}}}, Corners{{{a, 0.0}, {a, a}, {0.0, a}}},
                                      Corners{{{0.0, a}, {a, a}, {0.0, 2 * a}}}};
      },
      [](double h) { return Corners{{{0.0, 0.0}, {h, 0.0}, {0.0, h}}}; });
}

Rule tiled_rule(int p, int levels) {
  const Rule1D line = gauss_legendre(p);
  // Ω_{1,l} = [h, 2h] × [0, h], Ω_{2,l} = [h, 2h]², Ω_{3,l} = [0, h] × [h, 2h]; then the corner square [0, 2^-L]².
  auto square = [](double u0, double v0, double h) { return Corners{{{u0, v0}, {u0 + h, v0}, {u0, v0 + h}}}; };
  return layered_rule(
      tensor_rule(line, line), levels,
      [&](double h) { return std::array<Corners, 3>{square(h, 0.0, h), square(h, h, h), square(0.0, h, h)}; },
      [&](double h) { return square(0.0, 0.0, h); });
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
