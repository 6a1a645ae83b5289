#include "quadrature/rule_provider.hpp"

#include <charconv>
#include <vector>

#include "core/error.hpp"
#include "quadrature/gauss_legendre.hpp"
#include "quadrature/per_tile.hpp"
#include "quadrature/moment_fit/table.hpp"
#include "quadrature/moment_fit/table_directory.hpp"
#include "quadrature/spline_gauss/macro_rule.hpp"
#include "quadrature/tensor_rule.hpp"

namespace iga::quadrature {

Gauss::Gauss(int points_per_direction) : p_(points_per_direction) {
  if (p_ < 1 || p_ > 64) throw InputError("gauss quadrature: points per direction must be 1..64, got " + std::to_string(p_));
  line_ = gauss_legendre(p_);
  quad_ = tensor_rule(line_, line_);
  triangle_ = collapsed_triangle_rule(line_, line_);
}

const Rule& Gauss::rule(const basis::ElementKind& kind) const {
  return kind.shape == basis::Shape::Quad ? quad_ : triangle_;
}

const Rule& polynomial_rule(const Gauss& gauss, const basis::ElementKind& kind, const std::string& provider) {
  if (kind.family == basis::Family::Irregular) {
    throw UnsupportedError("quadrature '" + provider + "' has no rule for " + basis::to_string(kind) +
                           " elements (use gauss:P or tiles:P:L)");
  }
  return gauss.rule(kind);
}

namespace {
// Whole number from a piece of a specification; InputError naming the specification otherwise.
int parse_count(const std::string& text, const std::string& spec, const std::string& expected) {
  int value = 0;
  const auto res = std::from_chars(text.data(), text.data() + text.size(), value);
  if (text.empty() || res.ec != std::errc() || res.ptr != text.data() + text.size()) {
    throw InputError("quadrature '" + spec + "': expected " + expected);
  }
  return value;
}
}  // namespace

std::unique_ptr<RuleProvider> make_rule_provider(const std::string& spec, int default_points) {
  std::vector<std::string> parts;
  std::size_t start = 0;
  while (true) {
    const auto colon = spec.find(':', start);
    parts.push_back(spec.substr(start, colon - start));
    if (colon == std::string::npos) break;
    start = colon + 1;
  }
  const std::string& method = parts[0];
  if (method == "gauss" && parts.size() <= 2) {
    const int p = parts.size() == 2 ? parse_count(parts[1], spec, "gauss:P with P points per direction") : default_points;
    return std::make_unique<Gauss>(p);
  }
  if (method == "tiles" && parts.size() == 3) {
    const std::string expected = "tiles:P:L with P points per direction and L levels";
    return std::make_unique<PerTile>(parse_count(parts[1], spec, expected), parse_count(parts[2], spec, expected));
  }
  if (method == "macro" && (parts.size() == 2 || parts.size() == 3)) {
    const std::string expected = "macro:R or macro:R:L with R rings per macro patch (1, 2, 3) and L levels";
    const int r = parse_count(parts[1], spec, expected);
    const int levels = parts.size() == 3 ? parse_count(parts[2], spec, expected) : 8;
    return spline_gauss::make_macro_patch(r, levels);
  }
  if (method == "fitted") {
    // Tables made by tools/fit_quadrature.cpp: fitted[:SPACE][:DIR]; SPACE phi (default), mass or stiffness;
    // DIR, else moment_fit::default_table_directory ($IGA_QUADRATURE_DIR, next to the library, the build tree's).
    // DIR may itself contain ':'.
    moment_fit::Space space = moment_fit::Space::Phi;
    std::string rest = parts.size() >= 2 ? spec.substr(spec.find(':') + 1) : std::string();
    if (parts.size() >= 2 && (parts[1] == "phi" || parts[1] == "mass" || parts[1] == "stiffness")) {
      space = moment_fit::parse_space(parts[1]);
      rest = parts.size() >= 3 ? rest.substr(rest.find(':') + 1) : std::string();
      if (parts.size() >= 3 && rest.empty()) throw InputError("quadrature '" + spec + "': empty directory after the space");
    } else if (parts.size() >= 2 && rest.empty()) {
      throw InputError("quadrature '" + spec + "': expected fitted[:SPACE][:DIR] with SPACE phi, mass or stiffness");
    }
    return moment_fit::make_fitted(rest.empty() ? moment_fit::default_table_directory(space) : rest, space);
  }
  throw InputError("quadrature '" + spec + "': unknown (known: gauss:P, tiles:P:L, macro:R[:L], fitted[:SPACE][:DIR])");
}

}  // namespace iga::quadrature
