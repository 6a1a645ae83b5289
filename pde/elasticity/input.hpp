#pragma once
// Plane elasticity as a program's command line gives it (iga-elasticity): the material, a built-in problem or
// expressions, and conditions on boundary parts by name, read against the refined geometry into ElasticityData.
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "basis/geometry.hpp"
#include "pde/elasticity/elasticity.hpp"

namespace iga::pde {

struct ElasticityInput {
  double young = 1e5, poisson = 0.3;
  std::string model = "strain";  ///< "strain" or "stress"
  /// --problem: "kirsch" (Kirsch's plate with a hole of radius 1 about the origin under tension --tension along x:
  /// the exact displacement; by default u_x = 0 on v1, u_y = 0 on v0 and the exact traction on u1, the parts of the
  /// built-in plate-with-hole geometry), or empty: the expressions below.
  std::string problem;
  double tension = 10.0;
  std::string body_force;  ///< "BX; BY" (x, y)
  std::string exact;       ///< "UX; UY": the error norms, and the data conditions leave out
  /// "C; PARTS[; VALUE]": u_C = VALUE (default: the exact solution's component, else 0) on the parts; C is x or y.
  std::vector<std::string> displacement;
  /// "PARTS[; TX; TY]": t = (TX, TY)(x, y, nx, ny) on the parts (default: σ(u)n of the exact solution).
  std::vector<std::string> traction;
};

/// "kirsch".
std::vector<std::string> elasticity_problem_names();

/// The data for make_elasticity. InputError naming the option for an item that is not of its form, a component
/// that is not x or y, a part that does not exist, an expression that does not parse, data taken from an exact
/// solution that was not given, or a built-in problem given with --body-force or --exact. `description` gets the
/// report's problem object: name, material, body force, exact, and the conditions as given with their parts by name.
ElasticityData elasticity_data(const ElasticityInput& input, const basis::Geometry& geometry, nlohmann::json& description);

}  // namespace iga::pde
