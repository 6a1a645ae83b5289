#pragma once
// Per-tile Gauss rules for elements at an extraordinary vertex (thesis §4.2.1, option 2).
#include <array>
#include <string>

#include "quadrature/rule_provider.hpp"

namespace iga::quadrature {

/// The tiles of an irregular element with its extraordinary vertex at (0,0) (Stam's parameterisation):
/// level l >= 1 holds Ω_{1,l} = [2^-l, 2^(1-l)] × [0, 2^-l], Ω_{2,l} = [2^-l, 2^(1-l)]²,
/// Ω_{3,l} = [0, 2^-l] × [2^-l, 2^(1-l)]; the functions are polynomial on each tile.
/// Returns the rule with a p × p Gauss rule on each of the three tiles of levels 1..levels and one p × p
/// Gauss rule on the remaining corner square [0, 2^-levels]² (where the functions are not polynomial; its
/// points are interior, never on the vertex, and its weights complete the element's area). 3·levels·p² + p²
/// points; weights sum to 1.
Rule tiled_rule(int p, int levels);

/// The tiles of an irregular triangle with its extraordinary face at corner (0,0) (half-box subdivision,
/// thesis §3.2.1, Figure 3.15): with a = 2^-l, layer l >= 1 is the strip a <= u + v <= 2a, made of the
/// triangles Ω_{1,l} = (a,0), (2a,0), (a,a); Ω_{2,l} = (a,0), (a,a), (0,a) (the middle, down-oriented one);
/// Ω_{3,l} = (0,a), (a,a), (0,2a). The functions are polynomial on each tile. Returns the collapsed p × p rule
/// (tensor_rule.hpp) mapped affinely onto each tile of levels 1..levels and onto the remaining corner triangle
/// u + v <= 2^-levels (not polynomial there; interior points only, weights completing the area 1/2).
/// (3·levels + 1)·p² points.
Rule tiled_triangle_rule(int p, int levels);

/// p-point Gauss on each piece [2^-l, 2^(1-l)], l = 1..levels, and on [0, 2^-levels] of [0, 1] (toward_zero),
/// or on the mirrored pieces of [1 − 2^(1-l), 1 − 2^-l] and [1 − 2^-levels, 1]: the tiles along a side that runs
/// into an extraordinary corner. (levels + 1)·p points.
Rule1D dyadic_line_rule(int p, int levels, bool toward_zero);

/// PerTile(p, levels): the tiled rule on irregular Catmull–Clark quads, the tiled triangle rule on irregular
/// half-box triangles, p × p Gauss on polynomial quads, the collapsed rule on polynomial triangles, p points
/// on sides; UnsupportedError naming any other irregular kind. Sides of irregular elements follow their tiles
/// (a side of a Catmull–Clark EV element on the boundary carries a non-polynomial trace with the clamped
/// boundary rule): half-box triangles side 0 (from the EF corner) and side 2 (into it), Catmull–Clark quads
/// side 0 (from the EV) and side 3 (into it) by dyadic_line_rule; the other sides by p points on each half.
/// Name "tiles:P:L".
class PerTile final : public RuleProvider {
 public:
  PerTile(int points_per_direction, int levels);
  const Rule& rule(const basis::ElementKind& kind) const override;
  const Rule1D& edge_rule() const override { return gauss_.edge_rule(); }
  const Rule1D& side_rule(const basis::ElementKind& kind, int side) const override;
  std::string name() const override;
  /// PerTile(p + 2, levels).
  std::unique_ptr<RuleProvider> error_rules() const override;
  int levels() const { return levels_; }

 private:
  Gauss gauss_;
  int levels_;
  Rule tiled_, tiled_triangle_;
  std::array<Rule1D, 3> half_box_sides_;
  std::array<Rule1D, 4> quad_sides_;
};

}  // namespace iga::quadrature
