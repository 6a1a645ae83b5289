#pragma once
// The adaptive loop solve → estimate → mark → refine (thesis §4.1.6; deal.II step-6), on any backend whose
// registry entry refines locally (basis::Backend::refine_marked: THB for bspline).
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "basis/registry.hpp"
#include "fem/estimator.hpp"
#include "fem/poisson.hpp"
#include "refine/marking.hpp"

namespace iga::refine {

struct AdaptiveOptions {
  int steps = 8;                 ///< refinement steps (steps + 1 solves), unless max_dofs stops it first
  double theta = 0.5;            ///< marking parameter
  Marking marking = Marking::Doerfler;
  Index max_dofs = 0;            ///< stop after the first solve with at least this many dofs (0: no limit)
  int admissibility = 2;         ///< class m of the refined meshes (0: no closure)
};

/// One solve of the loop and what led to the next.
struct AdaptiveStep {
  int step = 0;
  Index dofs = 0, elements = 0, quadrature_points = 0;
  int levels = 1;
  double estimate = 0.0;                ///< η
  std::optional<double> energy_error;   ///< (|u − u_h|²_H1 + c ‖u − u_h‖²)^½ with an exact solution
  std::optional<double> l2_error;
  std::optional<double> efficiency;     ///< η / energy error
  Index marked = 0, added = 0;          ///< elements marked after this solve, and added for admissibility
  double setup_seconds = 0, assembly_seconds = 0, solve_seconds = 0, error_seconds = 0;
  double estimate_seconds = 0, mark_seconds = 0, refine_seconds = 0;
};

/// Called after each solve and estimate (before marking): for output (VTU per step).
using StepCallback = std::function<void(const AdaptiveStep&, const basis::Geometry&, const fem::PoissonResult&,
                                        const fem::Estimate&)>;

/// The step to come, as known once the last one's elements are marked.
struct NextStep {
  int step = 0;
  /// Its refinement needs a level of the hierarchy that is not built yet (LevelHierarchy::level_built: Catmull–Clark
  /// builds a whole level, 4 times the elements of the one above, on first use).
  bool builds_level = false;
};

/// Called after each step (after on_step, and after marking when a step follows): `next` is the step to come, or
/// none when the loop ends anyway (the steps asked for, --max-dofs, nothing marked). Returns "" to go on, or why
/// the loop stops before `next` (the run's `stopped`; the last solve is kept), e.g. a time limit.
using StepCheck = std::function<std::string(const AdaptiveStep& done, const std::optional<NextStep>& next)>;

struct AdaptiveRun {
  std::vector<AdaptiveStep> history;
  /// Why the loop ended: "steps", "max_dofs", "estimate is zero", "deepest level: ..." when a marked element
  /// could not be refined because the hierarchy has no finer level, or the reason the StepCheck gave (the last
  /// solve is kept).
  std::string stopped;
};

/// Runs the loop from `geometry`. The problem, rules and solver options are the same at every step.
/// UnsupportedError (before any solve) when the geometry's backend has no local refinement.
AdaptiveRun adaptive_solve(const basis::Geometry& geometry, const quadrature::RuleProvider& rules,
                                         const fem::PoissonProblem& problem, const fem::SolverOptions& solver,
                                         const AdaptiveOptions& options, const StepCallback& on_step = {},
                                         const StepCheck& check = {});

}  // namespace iga::refine
