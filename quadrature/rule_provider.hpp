#pragma once
// Picks the quadrature rule of an element from its kind (DESIGN.md, "quadrature::RuleProvider").
#include <memory>
#include <string>

#include "basis/element_kind.hpp"
#include "quadrature/rule.hpp"

namespace iga::quadrature {

class RuleProvider {
 public:
  virtual ~RuleProvider() = default;
  /// The rule for elements of this kind. The reference stays valid for the provider's lifetime; calls are
  /// thread-safe. Throws UnsupportedError for kinds the provider does not handle.
  virtual const Rule& rule(const basis::ElementKind& kind) const = 0;
  /// The rule on [0,1] for element sides (boundary integrals).
  virtual const Rule1D& edge_rule() const = 0;
  /// The rule on [0,1] for side `side` of an element of this kind (side parameter of basis::side_point): by
  /// default edge_rule(); providers with tile rules split sides that run into an extraordinary corner.
  virtual const Rule1D& side_rule(const basis::ElementKind&, int) const { return edge_rule(); }
  /// The specification string, e.g. "gauss:4".
  virtual std::string name() const = 0;
  /// The rules for error norms: two more points per direction than the assembly's (p + 3 for the default
  /// p + 1, as deal.II does), so that an error norm is not integrated by the rule whose points the discrete
  /// solution was fitted at (gauss:3 reported the L2 error of biquadratic B-splines 16 % low). nullptr: the
  /// provider has no such rule and the norms use its own (said in the report).
  virtual std::unique_ptr<RuleProvider> error_rules() const { return nullptr; }
};

/// p × p Gauss–Legendre on every quad element (regular or not), the collapsed p × p rule on triangles,
/// p points on sides.
class Gauss final : public RuleProvider {
 public:
  explicit Gauss(int points_per_direction);
  const Rule& rule(const basis::ElementKind& kind) const override;
  const Rule1D& edge_rule() const override { return line_; }
  std::string name() const override { return "gauss:" + std::to_string(p_); }
  /// Gauss(p + 2).
  std::unique_ptr<RuleProvider> error_rules() const override { return std::make_unique<Gauss>(p_ + 2); }
  int points_per_direction() const { return p_; }

 private:
  int p_;
  Rule1D line_;
  Rule quad_, triangle_;
};

/// An irregular quad of the Catmull–Clark scheme (the kind the tiled, macro and fitted rules are made for).
inline bool is_catmull_clark_irregular(const basis::ElementKind& k) {
  return k.shape == basis::Shape::Quad && k.family == basis::Family::Irregular && k.scheme == basis::Scheme::CatmullClark;
}

/// What a provider with special rules for some irregular kinds uses for every other kind: `gauss`'s rule on
/// polynomial elements (Regular, Polar, TJunction), and UnsupportedError naming the provider and the kind for
/// an infinitely piecewise element it has no rule for (plain Gauss there would be a silent wrong answer).
const Rule& polynomial_rule(const Gauss& gauss, const basis::ElementKind& kind, const std::string& provider);

/// Makes a provider from a specification: "gauss:P", "tiles:P:L" (PerTile), "macro:R[:L]" (strip and macro
/// Gauss rules for spline spaces, spline_gauss::MacroPatch), "fitted[:SPACE][:DIR]" (moment-fitted tables,
/// moment_fit::Fitted; SPACE phi (the default), mass or stiffness selects the cc_<SPACE>_n<N> tables; DIR
/// defaults to $IGA_QUADRATURE_DIR, else the installed share/iga/quadrature next to the library, else the build
/// tree's data/quadrature: moment_fit::default_table_directory; "fitted:DIR" is phi tables in DIR).
/// `default_points` is used for a bare "gauss".
/// Throws InputError naming the specification when it is not understood.
std::unique_ptr<RuleProvider> make_rule_provider(const std::string& spec, int default_points);

}  // namespace iga::quadrature
