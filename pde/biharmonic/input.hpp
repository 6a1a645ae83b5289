#pragma once
// The biharmonic problem as a program's command line gives it (iga-biharmonic): a built-in problem or
// expressions, and the boundary parts by name, read against the refined geometry into BiharmonicData.
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "basis/geometry.hpp"
#include "pde/biharmonic/biharmonic.hpp"

namespace iga::pde {

struct BiharmonicInput {
  std::string problem;           ///< --problem: a built-in one (biharmonic_problem_names()); empty: the expressions
  std::string source;            ///< --source f(x, y) in Δ²u = f
  std::string exact;             ///< --exact u(x, y): the boundary data unless given, and the error norms
  std::string value, slope, moment;  ///< --value g, --slope h(x, y, nx, ny), --moment m: override --exact's
  std::string simply_supported;  ///< --simply-supported: parts by name or index, or all; the others clamped
  double nitsche_penalty = 0.0;  ///< --nitsche-penalty (0: the local estimate)
};

/// "sine": u = sin(πx) sin(πy), f = 4π⁴ u, every boundary datum from u (derivatives in closed form); "plate": a
/// Kirchhoff plate under a uniform load, f = q/D = 1, u = 0 and ∂u/∂n = 0 (clamped) or Δu = 0 (simply
/// supported), no exact solution.
std::vector<std::string> biharmonic_problem_names();

/// The data for make_biharmonic. Without --problem, --source and --exact: "sine". InputError naming the option for
/// a built-in problem given with expressions, boundary data without a source, an expression that does not parse,
/// or a part that does not exist. `description` gets the report's problem object: name (null without a built-in
/// one), source, exact, value, slope, moment (the texts in effect, "" for 0) and the simply supported and clamped
/// parts by name.
BiharmonicData biharmonic_data(const BiharmonicInput& input, const basis::Geometry& geometry, nlohmann::json& description);

}  // namespace iga::pde
