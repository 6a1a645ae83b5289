#include "fem/dirichlet.hpp"

#include <Eigen/SparseCholesky>

#include "core/error.hpp"

namespace iga::fem {

DirichletConditions project_dirichlet(const Assembler& assembler, std::span<const basis::BoundaryEdge> edges,
                                      std::shared_ptr<const Function> g) {
  DirichletConditions bc;
  if (edges.empty()) return bc;
  Eigen::SparseMatrix<double> m;
  Eigen::VectorXd rhs;
  const BoundaryMassForm mass;
  const BoundaryLoadForm load(std::move(g));
  assembler.assemble_boundary(edges, &mass, &load, &m, &rhs);
  const Eigen::VectorXd diag = m.diagonal();
  const double tol = 1e-14 * diag.maxCoeff();
  std::vector<Index> local(static_cast<std::size_t>(m.rows()), -1);
  for (Index i = 0; i < m.rows(); ++i) {
    if (diag(i) > tol) {
      local[static_cast<std::size_t>(i)] = static_cast<Index>(bc.dofs.size());
      bc.dofs.push_back(i);
    }
  }
  const Index nd = static_cast<Index>(bc.dofs.size());
  std::vector<Eigen::Triplet<double>> entries;
  for (Index j = 0; j < m.outerSize(); ++j) {
    for (Eigen::SparseMatrix<double>::InnerIterator it(m, j); it; ++it) {
      const Index r = local[static_cast<std::size_t>(it.row())], c = local[static_cast<std::size_t>(it.col())];
      if (r >= 0 && c >= 0) entries.emplace_back(r, c, it.value());
    }
  }
  Eigen::SparseMatrix<double> mdd(nd, nd);
  mdd.setFromTriplets(entries.begin(), entries.end());
  Eigen::VectorXd bd(nd);
  for (Index k = 0; k < nd; ++k) bd(k) = rhs(bc.dofs[static_cast<std::size_t>(k)]);
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> solver(mdd);
  if (solver.info() != Eigen::Success) {
    throw NumericalError("Dirichlet projection: the boundary mass matrix could not be factorised");
  }
  bc.values = solver.solve(bd);
  return bc;
}

ReducedSystem eliminate(const Eigen::SparseMatrix<double>& a, const Eigen::VectorXd& b,
                        const DirichletConditions& bc) {
  const Index n = a.rows();
  if (!a.isCompressed()) throw InputError("eliminate: the matrix must be compressed");
  std::vector<Index> map(static_cast<std::size_t>(n), 0);
  for (Index d : bc.dofs) map[static_cast<std::size_t>(d)] = -1;
  ReducedSystem sys;
  for (Index i = 0; i < n; ++i) {
    if (map[static_cast<std::size_t>(i)] == 0) {
      map[static_cast<std::size_t>(i)] = static_cast<Index>(sys.free.size());
      sys.free.push_back(i);
    }
  }
  const Index nf = static_cast<Index>(sys.free.size());
  // b_f - A_fd g_d: only the Dirichlet columns contribute (A is symmetric, column-major).
  Eigen::VectorXd rhs = b;
  for (std::size_t k = 0; k < bc.dofs.size(); ++k) {
    const double gk = bc.values(static_cast<Index>(k));
    if (gk == 0.0) continue;
    for (Eigen::SparseMatrix<double>::InnerIterator it(a, bc.dofs[k]); it; ++it) rhs(it.row()) -= it.value() * gk;
  }
  sys.b.resize(nf);
  for (Index k = 0; k < nf; ++k) sys.b(k) = rhs(sys.free[static_cast<std::size_t>(k)]);
  // A_ff, column by column in two passes (count, fill), both parallel over columns.
  Eigen::SparseMatrix<double>& r = sys.a;
  r.resize(nf, nf);
  std::vector<int> outer(static_cast<std::size_t>(nf + 1), 0);
  const int* a_outer = a.outerIndexPtr();
  const int* a_inner = a.innerIndexPtr();
  const double* a_values = a.valuePtr();
#pragma omp parallel for schedule(static)
  for (Index k = 0; k < nf; ++k) {
    const Index j = sys.free[static_cast<std::size_t>(k)];
    int count = 0;
    for (int p = a_outer[j]; p < a_outer[j + 1]; ++p) count += map[static_cast<std::size_t>(a_inner[p])] >= 0;
    outer[static_cast<std::size_t>(k + 1)] = count;
  }
  for (Index k = 0; k < nf; ++k) outer[static_cast<std::size_t>(k + 1)] += outer[static_cast<std::size_t>(k)];
  r.resizeNonZeros(outer.back());
  std::copy(outer.begin(), outer.end(), r.outerIndexPtr());
  int* r_inner = r.innerIndexPtr();
  double* r_values = r.valuePtr();
#pragma omp parallel for schedule(static)
  for (Index k = 0; k < nf; ++k) {
    const Index j = sys.free[static_cast<std::size_t>(k)];
    int pos = outer[static_cast<std::size_t>(k)];
    for (int p = a_outer[j]; p < a_outer[j + 1]; ++p) {
      const Index m = map[static_cast<std::size_t>(a_inner[p])];
      if (m >= 0) {
        r_inner[pos] = static_cast<int>(m);
        r_values[pos] = a_values[p];
        ++pos;
      }
    }
  }
  return sys;
}

Eigen::VectorXd expand(const ReducedSystem& sys, const Eigen::VectorXd& u_free, const DirichletConditions& bc,
                       Index num_dofs) {
  Eigen::VectorXd u = Eigen::VectorXd::Zero(num_dofs);
  for (std::size_t k = 0; k < sys.free.size(); ++k) u(sys.free[k]) = u_free(static_cast<Index>(k));
  for (std::size_t k = 0; k < bc.dofs.size(); ++k) u(bc.dofs[k]) = bc.values(static_cast<Index>(k));
  return u;
}

}  // namespace iga::fem
