#include "fem/compatibility.hpp"

#include <cmath>
#include <sstream>

#include "core/error.hpp"

namespace iga::fem {

namespace {
std::string number(double v) {
  std::ostringstream s;
  s.precision(6);
  s << v;
  std::string t = s.str();  // 1e-08 as 1e-8
  for (const char* e : {"e-0", "e+0"}) {
    const std::size_t at = t.find(e);
    if (at != std::string::npos) t.erase(at + 2, 1);
  }
  return t;
}
}  // namespace

double Compatibility::quadrature_error() const { return std::abs(assembly.defect() - finer.defect()); }

double Compatibility::relative() const { return scale() > 0.0 ? std::abs(defect()) / scale() : 0.0; }

Compatibility::Verdict Compatibility::verdict() const {
  const double d = std::abs(defect());
  if (d <= kCompatibilityRoundoff * scale()) return Verdict::kExact;
  if (d <= kQuadratureMargin * quadrature_error()) return Verdict::kQuadrature;
  if (d <= kCompatibilityTolerance * scale()) return Verdict::kWarned;
  return Verdict::kRefused;
}

std::string Compatibility::word() const {
  switch (verdict()) {
    case Verdict::kExact: return "exact";
    case Verdict::kQuadrature: return "within the quadrature error";
    case Verdict::kWarned: return "small defect removed (warned)";
    case Verdict::kRefused: break;
  }
  return "refused";
}

std::string Compatibility::warning() const {
  const std::string sum = has_source ? "∫f + ∫g" : "∫g";
  const std::string abs = has_source ? "∫|f| + ∫|g|" : "∫|g|";
  return "the Neumann data are compatible only to " + number(relative()) + " of " + abs + " (" + sum + " = " +
         number(defect()) + "); solved with the defect removed";
}

std::string Compatibility::refusal(const std::string& remedy) const {
  std::string what = "the Neumann problem has no solution: ";
  if (has_source) {
    what += "∫f + ∫g = " + number(defect()) + " (∫f = " + number(finer.source) + ", ∫g = " + number(finer.neumann) +
            "), not zero within " + number(kCompatibilityTolerance) + " of ∫|f| + ∫|g| = " + number(scale());
  } else {
    what += "∫g = " + number(defect()) + " over the boundary, not zero within " + number(kCompatibilityTolerance) +
            " of ∫|g| = " + number(scale());
  }
  return what + "; " + remedy;
}

void check_compatibility(const Compatibility& c, const std::string& remedy) {
  if (c.verdict() == Compatibility::Verdict::kRefused) throw InputError(c.refusal(remedy));
}

}  // namespace iga::fem
