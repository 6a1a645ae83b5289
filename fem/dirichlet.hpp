#pragma once
// Strong Dirichlet conditions: boundary data projected in L2 onto the functions that live on the boundary.
#include <Eigen/Sparse>
#include <span>
#include <vector>

#include "fem/assembler.hpp"

namespace iga::fem {

/// Prescribed values u(dofs[k]) = values(k), dofs ascending.
struct DirichletConditions {
  std::vector<Index> dofs;
  Eigen::VectorXd values;
};

/// The L2 projection of g onto the span of the functions that are non-zero on `edges`:
/// M_DD g_D = (∫_Γ g φ_i)_D with M_DD(i, j) = ∫_Γ φ_i φ_j. A function counts as on the boundary when
/// ∫_Γ φ_i² > 1e-14 · max_k ∫_Γ φ_k². Empty edges give empty conditions.
DirichletConditions project_dirichlet(const Assembler& assembler, std::span<const basis::BoundaryEdge> edges,
                                      std::shared_ptr<const Function> g);

/// The system for the free dofs: A_ff u_f = b_f - A_fd g_d.
struct ReducedSystem {
  Eigen::SparseMatrix<double> a;
  Eigen::VectorXd b;
  std::vector<Index> free;  ///< global index of each reduced unknown
};
ReducedSystem eliminate(const Eigen::SparseMatrix<double>& a, const Eigen::VectorXd& b,
                        const DirichletConditions& bc);
/// The full vector from the free part and the conditions.
Eigen::VectorXd expand(const ReducedSystem& sys, const Eigen::VectorXd& u_free, const DirichletConditions& bc,
                       Index num_dofs);

}  // namespace iga::fem
