#include "basis/hierarchical/geometry_refinement.hpp"

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

Refinement refine_marked_geometry(const Geometry& geometry, const std::shared_ptr<const HierarchicalSpace>& coarse,
                                  const Eigen::SparseMatrix<double>& to_coarse, std::span<const Index> marked,
                                  int admissibility, BackendFacts& facts, bool with_prolongation) {
  const LocalRefinement r = marked.size() == static_cast<std::size_t>(coarse->num_elements()) && admissibility == 0
                                ? refine_all(*coarse)
                                : refine_marked(*coarse, marked, admissibility);
  facts.counts["marked"] = r.marked;
  facts.counts["added"] = r.added;
  facts.counts["levels"] = r.space->num_levels();
  const bool permuted = to_coarse.size() > 0;
  const Eigen::MatrixXd coarse_cp = permuted ? Eigen::MatrixXd(to_coarse * geometry.control_points()) : geometry.control_points();
  Eigen::SparseMatrix<double> p;
  Eigen::MatrixXd cp;
  if (with_prolongation || r.space->built_from(*coarse)) {  // an incremental build's prolongation is cheap
    p = r.space->prolongation_from(*coarse);
    cp = p * coarse_cp;
    if (!with_prolongation) {
      p = Eigen::SparseMatrix<double>();
    } else if (permuted) {
      Eigen::SparseMatrix<double> composed = p * to_coarse;
      p.swap(composed);
    }
  } else {
    cp = r.space->coefficients_from(*coarse, coarse_cp);
  }
  return {Geometry(r.space, std::move(cp), geometry), std::move(p), true};
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
