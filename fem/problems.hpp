#pragma once
// Built-in manufactured problems on planar domains: -Δu + c u = f with u known in closed form.
#include <memory>
#include <string>
#include <vector>

#include "fem/function.hpp"

namespace iga::fem {

struct ManufacturedProblem {
  std::string name;
  std::string description;
  std::shared_ptr<Function> exact;   ///< u, with its closed-form gradient
  std::shared_ptr<Function> source;  ///< f = -Δu + c u
  /// u and f as muparser expressions in x, y (the syntax of fem::Expression, --exact and --source), for reports:
  /// they evaluate to exact and source (tests/fem/test_problems.cpp checks that), with c written out.
  std::string exact_expression, source_expression;
};

/// Names: "sine" (sin(πx) sin(πy)), "harmonic" (e^x sin y), "linear" (1 + 2x - 3y, the patch test),
/// "poly" (x²y + y³ - xy), "corner" (r^(2/3) sin(2φ/3) about the reflex corner (1,1) of the L-shape of
/// basis::bspline::make_l_shape and data/meshes/l_shape.obj, harmonic; its gradient, singular at the corner, is
/// returned as 0 there). InputError for an unknown name, listing the known ones.
ManufacturedProblem manufactured_problem(const std::string& name, double reaction = 0.0);
std::vector<std::string> manufactured_problem_names();

}  // namespace iga::fem
