#include "fem/dirichlet.hpp"

#include <Eigen/Dense>
#include <Eigen/OrderingMethods>
#include <Eigen/SparseCholesky>
#include <Eigen/SPQRSupport>

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
  if (solver.info() == Eigen::Success && solver.vectorD().minCoeff() > 1e-11 * solver.vectorD().maxCoeff()) {
    bc.values = solver.solve(bd);
    return bc;
  }
  // Dependent traces: an independent set S by rank-revealing sparse QR (columns whose remaining norm falls
  // below the threshold are dependent and moved to the end), the rest coupled to S.
  const double max_diag = mdd.diagonal().maxCoeff();
  mdd.makeCompressed();
  Eigen::SPQR<Eigen::SparseMatrix<double>> qr;
  qr.setPivotThreshold(1e-10 * max_diag);
  qr.compute(mdd);
  if (qr.info() != Eigen::Success) throw NumericalError("Dirichlet projection: QR of the boundary mass matrix failed");
  const Index rank = qr.rank();
  if (rank == 0) throw NumericalError("Dirichlet projection: the boundary mass matrix is zero");
  std::vector<Index> s_local, j_local;
  std::vector<Index> pos(static_cast<std::size_t>(nd), -1);  // position in S (>= 0) or -(1 + position in J)
  {
    std::vector<char> in_s(static_cast<std::size_t>(nd), 0);
    for (Index k = 0; k < rank; ++k) in_s[static_cast<std::size_t>(qr.colsPermutation().indices()(k))] = 1;
    for (Index k = 0; k < nd; ++k) {
      if (in_s[static_cast<std::size_t>(k)]) {
        pos[static_cast<std::size_t>(k)] = static_cast<Index>(s_local.size());
        s_local.push_back(k);
      } else {
        pos[static_cast<std::size_t>(k)] = -1 - static_cast<Index>(j_local.size());
        j_local.push_back(k);
      }
    }
  }
  const Index ns = static_cast<Index>(s_local.size()), nj = static_cast<Index>(j_local.size());
  std::vector<Eigen::Triplet<double>> tss, tsj;
  for (Index col = 0; col < mdd.outerSize(); ++col) {
    for (Eigen::SparseMatrix<double>::InnerIterator it(mdd, col); it; ++it) {
      const Index r = pos[static_cast<std::size_t>(it.row())], c = pos[static_cast<std::size_t>(col)];
      if (r < 0) continue;
      if (c >= 0) tss.emplace_back(r, c, it.value());
      else tsj.emplace_back(r, -1 - c, it.value());
    }
  }
  Eigen::SparseMatrix<double> mss(ns, ns), msj(ns, nj);
  mss.setFromTriplets(tss.begin(), tss.end());
  msj.setFromTriplets(tsj.begin(), tsj.end());
  Eigen::VectorXd bs(ns);
  for (Index a = 0; a < ns; ++a) bs(a) = bd(s_local[static_cast<std::size_t>(a)]);
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> ldlt(mss);
  if (ldlt.info() != Eigen::Success || ldlt.vectorD().minCoeff() <= 0.0) {
    throw NumericalError("Dirichlet projection: the independent boundary traces are not definite");
  }
  // Column by column (A = M_SS⁻¹ M_SJ is local, hence sparse): memory O(|S|), not O(|S|·|J|). Each dependent
  // trace must lie in the span of S: M_JJ(j, j) = M_SJ(:, j) · A(:, j).
  std::vector<Index> all_dofs = bc.dofs;
  bc.dofs.clear();
  for (Index a : s_local) bc.dofs.push_back(all_dofs[static_cast<std::size_t>(a)]);
  bc.values = ldlt.solve(bs);
  std::vector<Eigen::Triplet<double>> c;
  Eigen::VectorXd column(ns);
  for (Index b = 0; b < nj; ++b) {
    const Index jb = j_local[static_cast<std::size_t>(b)];
    column = ldlt.solve(Eigen::VectorXd(msj.col(b)));
    double fit = 0.0;
    for (Eigen::SparseMatrix<double>::InnerIterator it(msj, b); it; ++it) fit += it.value() * column(it.row());
    if (std::abs(fit - mdd.coeff(jb, jb)) > 1e-8 * max_diag) {
      throw NumericalError("Dirichlet projection: a boundary trace is not in the span of the independent ones");
    }
    for (Index a = 0; a < ns; ++a) {
      if (std::abs(column(a)) > 1e-13) c.emplace_back(a, all_dofs[static_cast<std::size_t>(jb)], column(a));
    }
  }
  bc.coupling.resize(ns, m.rows());
  bc.coupling.setFromTriplets(c.begin(), c.end());
  return bc;
}

namespace {

// The free dofs (not in bc.dofs) in order; returns each dof's position among them, -1 for constrained ones.
std::vector<Index> number_free(Index n, const DirichletConditions& bc, std::vector<Index>& free) {
  std::vector<Index> map(static_cast<std::size_t>(n), 0);
  for (Index d : bc.dofs) map[static_cast<std::size_t>(d)] = -1;
  for (Index i = 0; i < n; ++i) {
    if (map[static_cast<std::size_t>(i)] == 0) {
      map[static_cast<std::size_t>(i)] = static_cast<Index>(free.size());
      free.push_back(i);
    }
  }
  return map;
}

// Coupled conditions: u = u0 + T w over the dofs that are not constrained.
ReducedSystem eliminate_coupled(const Eigen::SparseMatrix<double>& a, const Eigen::VectorXd& b,
                                const DirichletConditions& bc) {
  const Index n = a.rows();
  ReducedSystem sys;
  const std::vector<Index> map = number_free(n, bc, sys.free);
  const Index nf = static_cast<Index>(sys.free.size());
  std::vector<Eigen::Triplet<double>> t;
  for (Index k = 0; k < nf; ++k) t.emplace_back(sys.free[static_cast<std::size_t>(k)], k, 1.0);
  sys.u0 = Eigen::VectorXd::Zero(n);
  for (std::size_t k = 0; k < bc.dofs.size(); ++k) {
    sys.u0(bc.dofs[k]) = bc.values(static_cast<Index>(k));
    for (Eigen::SparseMatrix<double, Eigen::RowMajor>::InnerIterator it(bc.coupling, static_cast<Index>(k)); it; ++it) {
      const Index col = map[static_cast<std::size_t>(it.col())];
      if (col < 0) throw NumericalError("eliminate: a constrained dof is coupled to another constrained dof");
      t.emplace_back(bc.dofs[k], col, -it.value());
    }
  }
  sys.t.resize(n, nf);
  sys.t.setFromTriplets(t.begin(), t.end());
  const Eigen::SparseMatrix<double> at = a * sys.t;
  sys.a = sys.t.transpose() * at;
  sys.a.makeCompressed();
  sys.b = sys.t.transpose() * (b - a * sys.u0);
  return sys;
}

}  // namespace

ReducedSystem eliminate(const Eigen::SparseMatrix<double>& a, const Eigen::VectorXd& b,
                        const DirichletConditions& bc) {
  const Index n = a.rows();
  if (!a.isCompressed()) throw InputError("eliminate: the matrix must be compressed");
  if (bc.coupling.nonZeros() > 0) return eliminate_coupled(a, b, bc);
  ReducedSystem sys;
  const std::vector<Index> map = number_free(n, bc, sys.free);
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
  if (sys.t.cols() > 0) return sys.u0 + sys.t * u_free;
  Eigen::VectorXd u = Eigen::VectorXd::Zero(num_dofs);
  for (std::size_t k = 0; k < sys.free.size(); ++k) u(sys.free[k]) = u_free(static_cast<Index>(k));
  for (std::size_t k = 0; k < bc.dofs.size(); ++k) u(bc.dofs[k]) = bc.values(static_cast<Index>(k));
  return u;
}

}  // namespace iga::fem
