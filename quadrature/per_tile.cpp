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

Rule1D dyadic_line_rule(int p, int levels, bool toward_zero) {
  if (levels < 1 || levels > 50) throw InputError("tiled rule: levels must be 1..50, got " + std::to_string(levels));
  const Rule1D line = gauss_legendre(p);
  Rule1D out;
  out.points.resize((levels + 1) * p);
  out.weights.resize((levels + 1) * p);
  Eigen::Index k = 0;
  auto piece = [&](double a, double h) {
    for (Eigen::Index i = 0; i < p; ++i, ++k) {
      const double t = a + h * line.points(i);
      out.points(k) = toward_zero ? t : 1.0 - t;
      out.weights(k) = h * line.weights(i);
    }
  };
  for (int l = 1; l <= levels; ++l) piece(std::ldexp(1.0, -l), std::ldexp(1.0, -l));
  piece(0.0, std::ldexp(1.0, -levels));
  return out;
}

PerTile::PerTile(int points_per_direction, int levels)
    : gauss_(points_per_direction),
      levels_(levels),
      tiled_(tiled_rule(points_per_direction, levels)),
      tiled_triangle_(tiled_triangle_rule(points_per_direction, levels)) {
  // Side 1 of a half-box EF triangle lies in layer 1 and crosses tiles 0 and 1 at t = 1/2.
  const Rule1D line = gauss_legendre(points_per_direction);
  Rule1D halves;
  halves.points.resize(2 * line.size());
  halves.weights.resize(2 * line.size());
  halves.points << 0.5 * line.points, 0.5 + 0.5 * line.points.array();
  halves.weights << 0.5 * line.weights, 0.5 * line.weights;
  half_box_sides_ = {dyadic_line_rule(points_per_direction, levels, true), halves,
                     dyadic_line_rule(points_per_direction, levels, false)};
  // A Catmull–Clark quad with its EV at corner c0: side 0 (c0 -> c1) and side 3 (c3 -> c0) run along the tiles
  // into the EV; sides 1 and 2 cross the two tiles of layer 1 at t = 1/2.
  quad_sides_ = {half_box_sides_[0], halves, halves, half_box_sides_[2]};
}

const Rule1D& PerTile::side_rule(const basis::ElementKind& kind, int side) const {
  if (is_catmull_clark_irregular(kind) && side >= 0 && side < 4) return quad_sides_[static_cast<std::size_t>(side)];
  if (kind.shape == basis::Shape::Triangle && kind.family == basis::Family::Irregular &&
      kind.scheme == basis::Scheme::HalfBox && side >= 0 && side < 3) {
    return half_box_sides_[static_cast<std::size_t>(side)];
  }
  return edge_rule();
}

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

namespace iga::quadrature {

std::unique_ptr<RuleProvider> PerTile::error_rules() const {
  return std::make_unique<PerTile>(gauss_.points_per_direction() + 2, levels_);
}

}  // namespace iga::quadrature
