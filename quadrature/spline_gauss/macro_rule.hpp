#pragma once
// Strip (r = 1) and macro-element (r >= 2) quadrature for irregular Catmull–Clark elements (thesis §4.2.2).
//
// Element coordinates as in per_tile.hpp: the extraordinary vertex at (0,0), level l holds the tiles
// Ω_{1,l} = [2^-l, 2^(1-l)] × [0, 2^-l], Ω_{2,l} = [2^-l, 2^(1-l)]², Ω_{3,l} = [0, 2^-l] × [2^-l, 2^(1-l)].
//
// The macro patch of r levels owned by an element is the rectangle
//   u ∈ [2^-r, 1]  (the short side: r intervals, breaks 2^-l, l = 1..r-1),
//   v ∈ [-2^-r, 1] (the long side: r + 2 intervals, breaks 2^-l, l = 1..r, and 0),
// i.e. the tiles of levels 1..r of the element with u >= 2^-r plus (v < 0) a strip of width 2^-r of the
// neighbouring element across the edge v = 0 (its tiles Ω_3, partly: "virtual knot insertion" of the level-r
// knot lines back to level 1). r = 1 is the strip of three tiles. On the patch the target space is the tensor
// space (p, c) × (p, c): degree p, C^c at the inner breaks, and the patch rule is the tensor product of the
// Gaussian rules (generator.hpp) of the two sides. With the same patch owned by every element around the
// vertex (Stam's parameterisation: the edge v = 0 of one element is the edge u = 0 of the next, where
// (u, v) -> (-v, u)), n patches cover levels 1..r of all n elements, and the points of the neighbour's patch
// that fall into this element are the patch points with v < 0 rotated into (-v, u) ∈ [0, 2^-r] × [2^-r, 1].
// Hence per element: exactly the points of one patch, folded.
//
// Exactness: a patch rule is exact for every function of the patch space. The folded per-element rule is
// exact for the SUM over the elements around the vertex of a global integrand whose restriction to each patch
// lies in the patch space (as for assembled area, volume or stiffness entries), not for every per-element
// integrand on its own. Only symmetric spaces (same (p, c) in u and v) can be folded.
#include <memory>
#include <string>
#include <vector>

#include "quadrature/per_tile.hpp"
#include "quadrature/rule_provider.hpp"

namespace iga::quadrature::spline_gauss {

/// Target spaces of the thesis (lines 8474, 8515, 8605; superspaces at 8614-8616, 8655-8657).
enum class Space {
  Subdivision,  ///< subdivision splines (values "phi"): (3,2) × (3,2)
  Area,         ///< planar area det J: (5,1) × (5,1)
  Volume,       ///< enclosed volume z det J: (8,1) × (8,1), integrated via the superspace (9,1) × (9,1)
  Poisson,      ///< stiffness ∇φ·∇φ: (4,1) × (6,2) and (6,2) × (4,1), via the superspace (6,1) × (6,1)
};

/// The degree and continuity (same in u and v) of the space a rule is built for.
struct SpaceDegrees {
  int degree = 3;
  int continuity = 2;
};

/// The space the rule is generated for (after taking the thesis's superspace).
SpaceDegrees rule_space(Space space);
std::string to_string(Space space);

/// Break points of the short (u) and long (v) side of the r-level macro patch (see above).
std::vector<double> short_side_breaks(int r);
std::vector<double> long_side_breaks(int r);

/// The unfolded tensor rule on the patch [2^-r, 1] × [-2^-r, 1]: point (u_i, v_j) at index i + n_u j.
/// `short_rule` / `long_rule` (optional) receive the two 1D rules.
Rule macro_patch_rule(int r, SpaceDegrees space, Rule1D* short_rule = nullptr, Rule1D* long_rule = nullptr);

/// The per-element rule for an Irregular element: ceil(levels / r) folded macro patches, patch k scaled by
/// 2^(-r k) (covering levels r k + 1 .. r (k + 1); `levels` is rounded UP to a whole number of patches), plus an
/// n_c × n_c Gauss rule on the remaining corner square [0, 2^(-r K)]², n_c = ceil((p + 1) / 2) — the per-tile
/// choice of points. K · n_short · n_long + n_c² points; weights sum to 1. A point of a patch exactly on
/// v = 0 is split between the element (half weight) and its rotated copy.
Rule macro_rule(int r, int levels, SpaceDegrees space);
Rule macro_rule(int r, int levels, Space space);

/// Number of levels macro_rule covers: r · ceil(levels / r).
int covered_levels(int r, int levels);

/// MacroPatch(r, levels, space): the macro rule on Irregular quads at interior extraordinary vertices, the
/// per-tile rule (4 × 4 Gauss per tile, the same levels) at boundary extraordinary vertices — the folded macro
/// rule is exact only for sums over a closed ring of elements —, 4 × 4 Gauss on other quads, the collapsed
/// 4 × 4 rule on triangles, 4 points on sides. Name "macro:R" (levels 8) or "macro:R:L".
class MacroPatch final : public RuleProvider {
 public:
  explicit MacroPatch(int r, int levels = 8, Space space = Space::Poisson);
  const Rule& rule(const basis::ElementKind& kind) const override;
  const Rule1D& edge_rule() const override { return gauss_.edge_rule(); }
  /// Sides of irregular elements follow their tiles (PerTile's side rules over the covered levels).
  const Rule1D& side_rule(const basis::ElementKind& kind, int side) const override { return sides_.side_rule(kind, side); }
  std::string name() const override;
  /// PerTile(6, the covered levels): 4 × 4 Gauss is the base of every rule here.
  std::unique_ptr<RuleProvider> error_rules() const override;
  int r() const { return r_; }
  int levels() const { return levels_; }
  Space space() const { return space_; }

 private:
  Gauss gauss_;
  int r_, levels_;
  Space space_;
  Rule macro_, tiled_;
  PerTile sides_;
};

std::unique_ptr<RuleProvider> make_macro_patch(int r, int levels);

}  // namespace iga::quadrature::spline_gauss
