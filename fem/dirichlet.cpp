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
  std::vector<Index> map(static_cast<std::size_t>(n), 0);
  Eigen::VectorXd g = Eigen::VectorXd::Zero(n);
  for (std::size_t k = 0; k < bc.dofs.size(); ++k) {
    map[static_cast<std::size_t>(bc.dofs[k])] = -1;
    g(bc.dofs[k]) = bc.values(static_cast<Index>(k));
  }
  ReducedSystem sys;
  for (Index i = 0; i < n; ++i) {
    if (map[static_cast<std::size_t>(i)] == 0) {
      map[static_cast<std::size_t>(i)] = static_cast<Index>(sys.free.size());
      sys.free.push_back(i);
    }
  }
  const Index nf = static_cast<Index>(sys.free.size());
  // b_f - A_fd g_d, and A_ff copied column by column (a is compressed, column-major).
  const Eigen::VectorXd ag = a * g;
  sys.b.resize(nf);
  for (Index k = 0; k < nf; ++k) sys.b(k) = b(sys.free[static_cast<std::size_t>(k)]) - ag(sys.free[static_cast<std::size_t>(k)]);
  Eigen::SparseMatrix<double>& r = sys.a;
  r.resize(nf, nf);
  std::vector<int> outer(static_cast<std::size_t>(nf + 1), 0);
  for (Index k = 0; k < nf; ++k) {
    int count = 0;
    for (Eigen::SparseMatrix<double>::InnerIterator it(a, sys.free[static_cast<std::size_t>(k)]); it; ++it) {
      if (map[static_cast<std::size_t>(it.row())] >= 0) {
        ++count;
      }
    }
    outer[static_cast<std::size_t>(k + 1)] = outer[static_cast<std::size_t>(k)] + count;
  }
  r.resizeNonZeros(outer.back());
  std::copy(outer.begin(), outer.end(), r.outerIndexPtr());
  for (Index k = 0; k < nf; ++k) {
    int pos = outer[static_cast<std::size_t>(k)];
    for (Eigen::SparseMatrix<double>::InnerIterator it(a, sys.free[static_cast<std::size_t>(k)]); it; ++it) {
      if (map[static_cast<std::size_t>(it.row())] >= 0) {
        r.innerIndexPtr()[pos] = static_cast<int>(map[static_cast<std::size_t>(it.row())]);
        r.valuePtr()[pos] = it.value();
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
