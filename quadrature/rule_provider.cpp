#include "quadrature/rule_provider.hpp"

#include <charconv>

#include "core/error.hpp"
#include "quadrature/gauss_legendre.hpp"
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

std::unique_ptr<RuleProvider> make_rule_provider(const std::string& spec, int default_points) {
  const auto colon = spec.find(':');
  const std::string method = spec.substr(0, colon);
  if (method == "gauss") {
    int p = default_points;
    if (colon != std::string::npos) {
      const std::string arg = spec.substr(colon + 1);
      const auto res = std::from_chars(arg.data(), arg.data() + arg.size(), p);
      if (res.ec != std::errc() || res.ptr != arg.data() + arg.size()) {
        throw InputError("quadrature '" + spec + "': expected gauss:P with P a whole number of points per direction");
      }
    }
    return std::make_unique<Gauss>(p);
  }
  throw InputError("quadrature '" + spec + "': unknown method '" + method + "' (known: gauss:P)");
}

}  // namespace iga::quadrature
