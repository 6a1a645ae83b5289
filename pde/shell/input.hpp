#pragma once
// The shell as a program's command line (or --config file) gives it (iga-shell): the material, a problem of the
// shell obstacle course or loads and supports by boundary part and point, read against the refined geometry into
// ShellData, plus the points whose displacement the report gives.
#include <nlohmann/json.hpp>
#include <limits>
#include <string>
#include <vector>

#include "basis/geometry.hpp"
#include "pde/shell/shell.hpp"

namespace iga::pde {

struct ShellInput {
  /// E, ν, t: NaN = not given (a built-in problem's own, else required; ν defaults to 0.3).
  double young = std::numeric_limits<double>::quiet_NaN(), poisson = std::numeric_limits<double>::quiet_NaN(),
         thickness = std::numeric_limits<double>::quiet_NaN();
  /// --problem: scordelis-lo-roof, pinched-cylinder or pinched-hemisphere (the set-ups of the README's shell obstacle
  /// course, on the built-in geometries of the same names), or empty: the items below. Items given with a problem
  /// are added to its own (an --area-load replaces its own), and its reference values are then not reported: they hold
  /// for the problem as set (its material, loads and supports; any discretisation of its surface).
  std::string problem;
  std::string area_load;                    ///< "FX; FY; FZ" per unit area (expressions in x, y, z)
  std::string pressure;                     ///< along the unit normal (an expression)
  std::vector<std::string> line_load;       ///< "PARTS; QX; QY; QZ" per unit length
  std::vector<std::string> support;         ///< "C; PARTS[; value|slope|value+slope]", C x, y or z
  std::vector<std::string> symmetry;        ///< "AXIS; PARTS": the plane normal to AXIS (value of u_AXIS, slopes of the others)
  std::vector<std::string> clamped;         ///< "PARTS": values and slopes of all three components
  std::vector<std::string> point_load;      ///< "X, Y, Z; FX, FY, FZ"
  std::vector<std::string> point_support;   ///< "X, Y, Z; C"
  std::vector<std::string> point;           ///< "NAME; X, Y, Z": the displacement there in the report
};

/// A point whose displacement the report gives; with a reference value of one component (a built-in problem's).
struct ShellPoint {
  std::string name;
  Eigen::Vector3d at = Eigen::Vector3d::Zero();
  int component = -1;  ///< of the reference; -1: none
  double reference = 0.0;
  std::string source;  ///< where the reference comes from
};

struct ShellSetUp {
  ShellData data;
  std::vector<ShellPoint> points;
};

/// "scordelis-lo-roof", "pinched-cylinder", "pinched-hemisphere".
std::vector<std::string> shell_problem_names();
/// The built-in geometry a problem is posed on (its own name).
std::string shell_problem_geometry(const std::string& problem);

/// The data for make_shell. InputError naming the option for an item not of its form, a component that is not x, y or
/// z, a part that does not exist, an expression that does not parse, a missing material constant. `description` gets
/// the report's problem object: name, material, loads, supports and points as given.
ShellSetUp shell_setup(const ShellInput& input, const basis::Geometry& geometry, nlohmann::json& description);

}  // namespace iga::pde
