#pragma once
// The local penalty of Nitsche's method (forms.hpp, NitscheForm): from each element's own inverse estimate, so
// that no global constant has to fit every kind of element (extraordinary vertices, ghost functions cut by the
// boundary).
#include <functional>
#include <memory>
#include <span>
#include <vector>

#include "basis/space.hpp"
#include "fem/assembler.hpp"
#include "fem/function.hpp"

namespace iga::fem {

/// Per element: β_K = 4 λ_max(B_K, A_K) with B_K = Σ over its sides in `edges` of ∫ ∂_n φ ∂_n φᵀ ds and
/// A_K = ∫_K ∇φ · ∇φᵀ dx (the local generalized eigenvalue problem of Griebel and Schweitzer 2003; Embar,
/// Dolbow and Harari 2010 for IgA): then 2 ∫_∂K∩Γ ∂_n u u ≤ ½ |u|²_{1,K} + β_K ‖u‖²_{∂K∩Γ}, and the symmetric
/// Nitsche form is coercive. Both forms vanish on constants (partition of unity), which local_penalties() below
/// removes from A_K. 0 for elements without a side in `edges`. `equivalent_gamma` (optional) receives
/// max_K β_K h_K, h_K the length of the element's sides in `edges`: the γ of a γ / h penalty that would match.
std::vector<double> nitsche_penalties(const Assembler& assembler, std::span<const basis::BoundaryEdge> edges,
                                      double* equivalent_gamma = nullptr);

/// The same estimate for any pair of operators (a fourth-order problem's Δφ on the side against Δφ on the element):
/// β_K = 4 λ_max(B_K, A_K) with B_K = Σ over its sides in `edges` of ∫ s sᵀ ds, s = side(ctx) (nloc × q at the
/// side's points, prepared to `derivatives`), and A_K = ∫_K Σ_c a_c W a_cᵀ over the blocks a_c of element(ctx)
/// (nloc × c·q). The eigenproblem is solved on the range of A_K: its kernel (constants for ∇, the element's harmonic
/// functions for Δ) is one of B_K too, since a function whose operator vanishes on K vanishes on K's sides.
using SideOperator = std::function<void(const BoundaryContext&, Eigen::MatrixXd&)>;
using ElementOperator = std::function<const Eigen::MatrixXd&(const ElementContext&)>;
std::vector<double> local_penalties(const Assembler& assembler, std::span<const basis::BoundaryEdge> edges,
                                    const SideOperator& side, const ElementOperator& element, int derivatives,
                                    double* equivalent_gamma = nullptr);

/// The penalty of a Nitsche form on `edges`: β = γ / h_side when gamma > 0, else β_K = local_penalties(side,
/// element) (the form's own operators). *used receives γ, or max_K β_K h_K, for the report.
NitschePenalty nitsche_penalty(const Assembler& assembler, std::span<const basis::BoundaryEdge> edges, double gamma,
                               const SideOperator& side, const ElementOperator& element, int derivatives,
                               double* used);

/// Nitsche's terms for u = g on `edges`, to be added to the system: a (num_dofs²) and b (num_dofs) are overwritten.
/// β = γ / h per side when gamma > 0, else the local estimate above. Returns the γ used (or max_K β_K h_K), for
/// the report.
double nitsche_terms(const Assembler& assembler, std::span<const basis::BoundaryEdge> edges,
                     const std::shared_ptr<const Function>& g, double gamma, Eigen::SparseMatrix<double>& a,
                     Eigen::VectorXd& b);

}  // namespace iga::fem
