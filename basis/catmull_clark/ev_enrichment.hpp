#pragma once
// Quadratic enrichment at extraordinary vertices (issue 16, part 2): the Catmull–Clark space plus, per
// extraordinary vertex (EV) v, three functions
//     f_{v,k}(x) = χ(|x − x_v|² / ρ_v²) · q_k(ξ),   ξ = Fᵀ (x − x_v) / ρ_v,   q ∈ {ξ₁², ξ₁ξ₂, ξ₂²},
// χ(t) = (1 − t)⁸ for t < 1 and 0 beyond (C⁷: smooth enough for bicubic approximation, and for Gauss rules
// across the circle |x − x_v| = ρ, which no element follows), F the 3 × 2 orthonormal frame of the plane
// (planar domains: the x, y axes; surfaces: the tangent plane at x_v).
//
// Why it restores the rate: the space reproduces linear functions of x (the map is isoparametric, the
// functions a partition of unity) but not quadratics near an EV, where its local error is O(h²)·|∇²u| on the
// EV's ring of elements (L2 rate ≈ 2.4–2.6, H1 ≈ 1.6–1.7 measured for valences 5, 6, 8: test_cc_ev_rates).
// With the enrichment, u − Σ_k c_k f_{v,k} (c the Hessian of u at x_v in the frame) is smooth and has a zero
// Hessian at x_v, so its local error there is O(h³), area O(h²): L2 O(h⁴), H1 O(h³) — the rates of the regular
// parts. ρ_v is fixed when the enrichment is made (the EV's one-ring on the coarse net; interior EVs: capped
// to stay inside the domain, so the functions vanish on the boundary), so uniform refinement keeps the same
// functions and the spaces stay nested (prolongation: the base's, identity on the enrichment dofs). The idea
// is the singular-function / partition-of-unity enrichment of the FEM literature (Babuška–Melenk), here with
// the missing polynomials instead of singular functions.
//
// Cost: 3 dofs per EV, coupled to every element within ρ_v (a few dense rows). The enrichment functions are
// approximated ever better by the base space as h → 0, so the stiffness matrix's conditioning grows like
// h⁻⁴ instead of h⁻²: fine for the direct solver at the accuracies here (measured in test_cc_enrichment).
#include <Eigen/Core>
#include <memory>
#include <optional>
#include <vector>

#include "basis/geometry.hpp"
#include "basis/space.hpp"

namespace iga::basis::catmull_clark {

/// One enriched EV: its limit point, the cutoff radius ρ, the frame F (3 × 2, orthonormal columns) and its
/// valence (for reports).
struct EnrichmentCentre {
  Eigen::Vector3d point = Eigen::Vector3d::Zero();
  double radius = 0.0;
  Eigen::Matrix<double, 3, 2> frame = Eigen::Matrix<double, 3, 2>::Identity();
  int valence = 4;
  bool boundary = false;
};

/// A space plus the enrichment functions of `centres`. Local dofs of an element: the base space's, then
/// 3 per centre whose disc can meet the element (k = 0, 1, 2 for ξ₁², ξ₁ξ₂, ξ₂²); global dof of centre j,
/// function k: base.num_dofs() + 3 j + k. Everything else (kinds, edges, boundary parts, tiles) is the
/// base's; elements with enrichment functions are not polynomial. The name stays the base's, so the base's
/// backend handles it.
class EnrichedSpace final : public Space {
 public:
  /// base_points: the base geometry's control points (base.num_dofs() × dim): the enrichment functions are
  /// functions of the physical point.
  EnrichedSpace(std::shared_ptr<const Space> base, Eigen::MatrixXd base_points, std::vector<EnrichmentCentre> centres);

  const std::shared_ptr<const Space>& base() const { return base_; }
  const Eigen::MatrixXd& base_points() const { return base_points_; }
  const std::vector<EnrichmentCentre>& centres() const { return centres_; }

  std::string name() const override { return base_->name(); }
  Index num_dofs() const override { return base_->num_dofs() + 3 * static_cast<Index>(centres_.size()); }
  Index num_elements() const override { return base_->num_elements(); }
  ElementKind kind(Index e) const override { return base_->kind(e); }
  std::span<const Index> dofs(Index e) const override;
  Index max_local_dofs() const override { return max_local_dofs_; }
  void evaluate(Index e, const Eigen::Matrix2Xd& pts, int derivatives, BasisValues& out) const override;
  std::vector<BoundaryEdge> boundary_edges() const override { return base_->boundary_edges(); }
  std::vector<std::string> boundary_part_names() const override { return base_->boundary_part_names(); }
  std::vector<InteriorEdge> interior_edges() const override { return base_->interior_edges(); }
  int level(Index e) const override { return base_->level(e); }
  /// The base's, with zero columns for the enrichment dofs (exact geometry integrals: the map has no
  /// enrichment part).
  std::optional<SubdivisionElement> subdivision_element(Index e) const override;
  std::optional<int> polynomial_degree(Index e) const override;

  /// Elements whose local functions include enrichment functions.
  Index num_enriched_elements() const;

 private:
  std::shared_ptr<const Space> base_;
  Eigen::MatrixXd base_points_;
  std::vector<EnrichmentCentre> centres_;
  std::vector<int> slot_;                      // per element: index into local_, or -1
  std::vector<std::vector<Index>> local_;      // dofs of enriched elements (base's first)
  std::vector<std::vector<int>> local_centres_;  // the centres of enriched elements
  Index max_local_dofs_ = 0;
};

/// The EVs of a Catmull–Clark geometry that lose order (elements of family Irregular, the EV their corner
/// (0, 0); not interior valence 3, which keeps full order) with their radii and frames, each once, in the
/// order of their first element.
std::vector<EnrichmentCentre> extraordinary_centres(const Geometry& geometry);

/// The geometry on the enriched space of `centres` (the same map: enrichment control points are zero).
Geometry enriched_geometry(const Geometry& base, std::vector<EnrichmentCentre> centres);

/// "none" / "quadratic"; InputError naming the accepted words otherwise.
bool enrichment_option(const std::string& word);

}  // namespace iga::basis::catmull_clark
