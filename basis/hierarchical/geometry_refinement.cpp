#include "basis/hierarchical/geometry_refinement.hpp"

#include "basis/hierarchical/graded.hpp"
#include "basis/hierarchical/refine.hpp"
#include "core/error.hpp"

namespace iga::basis::hierarchical {

Eigen::SparseMatrix<double> level0_permutation(const HierarchicalSpace& coarse, Index level0_dofs) {
  Eigen::SparseMatrix<double> p(coarse.num_dofs(), level0_dofs);
  std::vector<Eigen::Triplet<double>> entries;
  for (Index d = 0; d < coarse.num_dofs(); ++d) entries.emplace_back(d, static_cast<Index>(coarse.dof_function(d)), 1.0);
  p.setFromTriplets(entries.begin(), entries.end());
  return p;
}

namespace {

// The geometry on `fine` (nested in `coarse`), its control points prolongated from those of `geometry` (on `coarse`
// after `to_coarse`; empty: already on it), with the prolongation when asked for.
Refinement prolongated(const Geometry& geometry, const HierarchicalSpace& coarse,
                       const Eigen::SparseMatrix<double>& to_coarse, std::shared_ptr<const HierarchicalSpace> fine,
                       bool with_prolongation) {
  const bool permuted = to_coarse.size() > 0;
  const Eigen::MatrixXd coarse_cp = permuted ? Eigen::MatrixXd(to_coarse * geometry.control_points()) : geometry.control_points();
  Eigen::SparseMatrix<double> p;
  Eigen::MatrixXd cp;
  if (with_prolongation || fine->built_from(coarse)) {  // an incremental build's prolongation is cheap
    p = fine->prolongation_from(coarse);
    cp = p * coarse_cp;
    if (!with_prolongation) {
      p = Eigen::SparseMatrix<double>();
    } else if (permuted) {
      Eigen::SparseMatrix<double> composed = p * to_coarse;
      p.swap(composed);
    }
  } else {
    cp = fine->coefficients_from(coarse, coarse_cp);
  }
  return {Geometry(std::move(fine), std::move(cp), geometry), std::move(p), true};
}

}  // namespace

Refinement refine_marked_geometry(const Geometry& geometry, const std::shared_ptr<const HierarchicalSpace>& coarse,
                                  const Eigen::SparseMatrix<double>& to_coarse, std::span<const Index> marked,
                                  int admissibility, BackendFacts& facts, bool with_prolongation) {
  const LocalRefinement r = marked.size() == static_cast<std::size_t>(coarse->num_elements()) && admissibility == 0
                                ? refine_all(*coarse)
                                : refine_marked(*coarse, marked, admissibility);
  facts.counts["marked"] = r.marked;
  facts.counts["added"] = r.added;
  facts.counts["levels"] = r.space->num_levels();
  return prolongated(geometry, *coarse, to_coarse, r.space, with_prolongation);
}

Refinement refine_graded_geometry(const Geometry& geometry, const std::shared_ptr<const HierarchicalSpace>& coarse,
                                  const Eigen::SparseMatrix<double>& to_coarse, int levels,
                                  const std::function<int(int)>& rings, int admissibility, BackendFacts& facts,
                                  bool keep_steps) {
  GradedCells plan = graded_cells(*coarse, levels, rings, admissibility);
  facts.counts["graded_levels"] = static_cast<long long>(plan.steps.size());
  facts.counts["marked"] = plan.marked;
  facts.counts["added"] = plan.added;
  if (!keep_steps) {
    // One build of the final space, from the coarse one.
    std::vector<LevelCell> all;
    for (const auto& step : plan.steps) all.insert(all.end(), step.begin(), step.end());
    auto fine = refined_space(*coarse, std::move(plan.refined), all);
    facts.counts["levels"] = fine->num_levels();
    return prolongated(geometry, *coarse, to_coarse, std::move(fine), false);
  }
  // Every step's space and prolongation (the levels of a multigrid solver).
  Refinement r{geometry, Eigen::SparseMatrix<double>(), true};
  std::shared_ptr<const HierarchicalSpace> current = coarse;
  RefinedCells refined = coarse->refined();
  Eigen::SparseMatrix<double> step_to_coarse = to_coarse;
  for (const auto& step : plan.steps) {
    for (const LevelCell& c : step) {
      if (refined.size() <= static_cast<std::size_t>(c.level)) refined.resize(static_cast<std::size_t>(c.level) + 1);
      refined[static_cast<std::size_t>(c.level)].insert(c.cell);
    }
    auto fine = refined_space(*current, refined, step);
    Refinement next = prolongated(r.geometry, *current, step_to_coarse, fine, true);
    r.prolongation = r.prolongation.size() == 0 ? next.prolongation
                                                : Eigen::SparseMatrix<double>(next.prolongation * r.prolongation);
    r.steps.push_back(std::move(next.prolongation));
    r.geometry = std::move(next.geometry);
    current = std::move(fine);
    step_to_coarse = Eigen::SparseMatrix<double>();
  }
  facts.counts["levels"] = current->num_levels();
  return r;
}

Refinement refine_all_geometry(const Geometry& geometry, int steps, BackendFacts& facts) {
  auto space = std::dynamic_pointer_cast<const HierarchicalSpace>(geometry.space_ptr());
  if (!space) throw InputError("refine_all_geometry: the geometry's space is not hierarchical");
  const Index n = space->num_dofs();
  Eigen::SparseMatrix<double> identity(n, n);
  identity.setIdentity();
  Refinement r{geometry, identity, true};
  for (int s = 0; s < steps; ++s) {
    auto current = std::dynamic_pointer_cast<const HierarchicalSpace>(r.geometry.space_ptr());
    std::vector<Index> all(static_cast<std::size_t>(current->num_elements()));
    for (std::size_t e = 0; e < all.size(); ++e) all[e] = static_cast<Index>(e);
    Refinement next = refine_marked_geometry(r.geometry, current, {}, all, 0, facts, true);
    Eigen::SparseMatrix<double> composed = next.prolongation * r.prolongation;
    r = {next.geometry, std::move(composed), true};
  }
  return r;
}

}  // namespace iga::basis::hierarchical
