#include "quadrature/spline_gauss/macro_rule.hpp"

#include <cmath>

#include "core/error.hpp"
#include "quadrature/gauss_legendre.hpp"
#include "quadrature/per_tile.hpp"
#include "quadrature/spline_gauss/generator.hpp"
#include "quadrature/tensor_rule.hpp"

namespace iga::quadrature::spline_gauss {

namespace {
void check_r(int r) {
  if (r < 1 || r > 12) throw InputError("macro quadrature: r must be 1..12, got " + std::to_string(r));
}

Rule1D side_rule(const std::vector<double>& breaks, SpaceDegrees s) {
  const std::vector<int> cont(breaks.size() - 2, s.continuity);
  return gaussian_rule(s.degree, breaks, cont);
}
}  // namespace

SpaceDegrees rule_space(Space space) {
  switch (space) {
    case Space::Subdivision: return {3, 2};
    case Space::Area: return {5, 1};
    case Space::Volume: return {9, 1};
    case Space::Poisson: return {6, 1};
  }
  throw InputError("macro quadrature: unknown space");
}

std::string to_string(Space space) {
  switch (space) {
    case Space::Subdivision: return "subdivision";
    case Space::Area: return "area";
    case Space::Volume: return "volume";
    case Space::Poisson: return "poisson";
  }
  return "?";
}

std::vector<double> short_side_breaks(int r) {
  check_r(r);
  std::vector<double> b;
  for (int l = r; l >= 0; --l) b.push_back(std::ldexp(1.0, -l));  // 2^-r, ..., 1/2, 1
  return b;
}

std::vector<double> long_side_breaks(int r) {
  check_r(r);
  std::vector<double> b = {-std::ldexp(1.0, -r), 0.0};
  for (int l = r; l >= 0; --l) b.push_back(std::ldexp(1.0, -l));
  return b;
}

Rule macro_patch_rule(int r, SpaceDegrees space, Rule1D* short_rule, Rule1D* long_rule) {
  const Rule1D su = side_rule(short_side_breaks(r), space);
  const Rule1D sv = side_rule(long_side_breaks(r), space);
  if (short_rule) *short_rule = su;
  if (long_rule) *long_rule = sv;
  // tensor_rule works on [0,1] rules but only multiplies points and weights: use it directly.
  return tensor_rule(su, sv);
}

int covered_levels(int r, int levels) {
  check_r(r);
  if (levels < 1 || levels > 50) throw InputError("macro quadrature: levels must be 1..50, got " + std::to_string(levels));
  return r * ((levels + r - 1) / r);
}

Rule macro_rule(int r, int levels, SpaceDegrees space) {
  const int covered = covered_levels(r, levels);
  const int patches = covered / r;
  const Rule patch = macro_patch_rule(r, space);
  // Fold: v > 0 stays, v < 0 rotates to (-v, u), v == 0 splits.
  std::vector<Eigen::Vector3d> folded;  // (u, v, w)
  for (Eigen::Index k = 0; k < patch.size(); ++k) {
    const double u = patch.points(0, k), v = patch.points(1, k), w = patch.weights(k);
    if (v > 0) folded.emplace_back(u, v, w);
    else if (v < 0) folded.emplace_back(-v, u, w);
    else {
      folded.emplace_back(u, 0.0, 0.5 * w);
      folded.emplace_back(0.0, u, 0.5 * w);
    }
  }
  const int nc = (space.degree + 2) / 2;
  const Rule1D g = gauss_legendre(nc);
  const Rule corner = tensor_rule(g, g);
  const auto nf = static_cast<Eigen::Index>(folded.size());
  Rule out;
  out.points.resize(2, nf * patches + corner.size());
  out.weights.resize(nf * patches + corner.size());
  Eigen::Index i = 0;
  for (int k = 0; k < patches; ++k) {
    const double s = std::ldexp(1.0, -r * k);
    for (const auto& f : folded) {
      out.points(0, i) = s * f(0);
      out.points(1, i) = s * f(1);
      out.weights(i) = s * s * f(2);
      ++i;
    }
  }
  const double h = std::ldexp(1.0, -covered);
  for (Eigen::Index k = 0; k < corner.size(); ++k, ++i) {
    out.points.col(i) = h * corner.points.col(k);
    out.weights(i) = h * h * corner.weights(k);
  }
  return out;
}

Rule macro_rule(int r, int levels, Space space) { return macro_rule(r, levels, rule_space(space)); }

MacroPatch::MacroPatch(int r, int levels, Space space)
    : gauss_(4), r_(r), levels_(levels), space_(space), macro_(macro_rule(r, levels, space)),
      tiled_(tiled_rule(4, covered_levels(r, levels))), sides_(4, covered_levels(r, levels)) {}

const Rule& MacroPatch::rule(const basis::ElementKind& kind) const {
  if (is_catmull_clark_irregular(kind)) return kind.boundary ? tiled_ : macro_;
  return polynomial_rule(gauss_, kind, name());
}

std::string MacroPatch::name() const {
  std::string out = "macro:";
  out += std::to_string(r_);
  if (levels_ != 8) {
    out += ':';
    out += std::to_string(levels_);
  }
  return out;
}

std::unique_ptr<RuleProvider> make_macro_patch(int r, int levels) { return std::make_unique<MacroPatch>(r, levels); }

}  // namespace iga::quadrature::spline_gauss

namespace iga::quadrature::spline_gauss {

std::unique_ptr<RuleProvider> MacroPatch::error_rules() const {
  return std::make_unique<PerTile>(6, covered_levels(r_, levels_));
}

}  // namespace iga::quadrature::spline_gauss
