#pragma once
// Built-in manufactured problems on planar domains: -Δu + c u = f with u known in closed form.
#include <Eigen/Core>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "basis/geometry.hpp"
#include "fem/function.hpp"

namespace iga::fem {

/// The planar domain a built-in problem belongs to (its exact solution is one only there): its bounding box and
/// points that must lie on its boundary (a singular corner).
struct ProblemDomain {
  std::string description;  ///< in the user's words, e.g. "the L-shape [0,2]^2 minus (1,2]^2 (--geometry l-shape)"
  Eigen::Vector2d lo, hi;   ///< the bounding box
  std::vector<Eigen::Vector2d> boundary_points;
};

struct ManufacturedProblem {
  std::string name;
  std::string description;
  std::shared_ptr<Function> exact;   ///< u, with its closed-form gradient
  std::shared_ptr<Function> source;  ///< f = -Δu + c u
  /// u and f as muparser expressions in x, y (the syntax of fem::Expression, --exact and --source), for reports:
  /// they evaluate to exact and source (tests/fem/test_problems.cpp checks that), with c written out.
  std::string exact_expression, source_expression;
  std::optional<ProblemDomain> domain;  ///< none: the problem holds on any planar domain
};

/// InputError "<what> belongs to <domain>; the geometry given spans [..] x [..] and (1, 1) is not on its boundary"
/// when the problem has a domain and the geometry is not it: its boundary (sampled at 9 points per boundary edge)
/// must span the domain's bounding box and pass through its boundary points, to 1e-6 of the box's diameter.
void check_problem_domain(const ManufacturedProblem& problem, const basis::Geometry& geometry, const std::string& what);

/// Names: "sine" (sin(πx) sin(πy)), "harmonic" (e^x sin y), "linear" (1 + 2x - 3y, the patch test),
/// "poly" (x²y + y³ - xy), "corner" (r^(2/3) sin(2φ/3) about the reflex corner (1,1) of the L-shape of
/// basis::bspline::make_l_shape, harmonic; its gradient, singular at the corner, is
/// returned as 0 there; its domain: the L-shape, check_problem_domain). InputError for an unknown name, listing the known ones.
ManufacturedProblem manufactured_problem(const std::string& name, double reaction = 0.0);
std::vector<std::string> manufactured_problem_names();

}  // namespace iga::fem
