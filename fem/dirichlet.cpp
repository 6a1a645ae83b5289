#include "fem/dirichlet.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <Eigen/OrderingMethods>
#include <Eigen/SparseCholesky>

#include "basis/curve/trace_space.hpp"
#include "core/error.hpp"

namespace iga::fem {

namespace {
std::string format_ratio(double r) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.1e", r);
  return buf;
}
}  // namespace

DirichletConditions project_dirichlet(const Assembler& assembler, std::span<const basis::BoundaryEdge> edges,
                                      std::shared_ptr<const Function> g) {
  DirichletConditions bc;
  if (edges.empty()) return bc;
  // The trace space says which functions live on the edges and how the dependent ones are coupled
  // (basis/curve/trace_space.hpp); the projection is onto its functions ψ_s = φ_s|Γ.
  const basis::TraceSpace trace(assembler.geometry().space_ptr(), {edges.begin(), edges.end()});
  Eigen::SparseMatrix<double> m;
  Eigen::VectorXd rhs;
  const BoundaryMassForm mass;
  const BoundaryLoadForm load(std::move(g));
  assembler.assemble_boundary(edges, &mass, &load, &m, &rhs);
  bc.dofs = trace.surface_dofs();
  const Index ns = static_cast<Index>(bc.dofs.size());
  std::vector<Index> local(static_cast<std::size_t>(m.rows()), -1);
  for (Index k = 0; k < ns; ++k) local[static_cast<std::size_t>(bc.dofs[static_cast<std::size_t>(k)])] = k;
  std::vector<Eigen::Triplet<double>> entries;
  for (Index j = 0; j < m.outerSize(); ++j) {
    for (Eigen::SparseMatrix<double>::InnerIterator it(m, j); it; ++it) {
      const Index r = local[static_cast<std::size_t>(it.row())], c = local[static_cast<std::size_t>(it.col())];
      if (r >= 0 && c >= 0) entries.emplace_back(r, c, it.value());
    }
  }
  Eigen::SparseMatrix<double> mss(ns, ns);
  mss.setFromTriplets(entries.begin(), entries.end());
  // Scaled to unit diagonal (S = D^-1/2 M D^-1/2), so that the pivot ratio measures how nearly dependent the traces
  // are, not how different their supports' lengths are: on an adaptive mesh graded toward a corner the diagonal spans
  // the ratio of the largest to the smallest boundary element (2^levels), and the unscaled ratio refused the
  // adaptive L-shape at 3e5 dofs (1.4e8 unscaled; 1.8–2.0 scaled, up to 1e6 dofs and 35 levels).
  Eigen::VectorXd scale(ns);
  for (Index k = 0; k < ns; ++k) {
    const double d = mss.coeff(k, k);
    scale(k) = d > 0.0 ? 1.0 / std::sqrt(d) : 1.0;
  }
  mss = scale.asDiagonal() * mss * scale.asDiagonal();
  Eigen::VectorXd bs(ns);
  for (Index k = 0; k < ns; ++k) bs(k) = scale(k) * rhs(bc.dofs[static_cast<std::size_t>(k)]);
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> ldlt(mss);
  if (ldlt.info() != Eigen::Success || !(ldlt.vectorD().minCoeff() > 0.0)) {
    // The usual cause is a rule with fewer points on an element side than functions live there (gauss:1 on
    // quadratics): say so with the counts, not only that the matrix is singular.
    Index side_points = 0;
    for (const basis::BoundaryEdge& e : edges) {
      side_points += assembler.rules().side_rule(assembler.geometry().space().kind(e.element), e.side).size();
    }
    throw NumericalError("Dirichlet projection: the boundary mass matrix of the " + std::to_string(ns) +
                         " functions on the Dirichlet boundary is singular: either quadrature '" + assembler.rules().name() +
                         "' puts too few points on the element sides (" + std::to_string(side_points) + " on " +
                         std::to_string(edges.size()) + "; each side needs at least degree + 1: use more points) or the "
                         "traces are dependent (impose the conditions weakly, --dirichlet-method nitsche, or give that "
                         "part Neumann data)");
  }
  // Traces that are independent only in principle (their differences live in ever smaller pieces near a point,
  // e.g. at an extraordinary vertex of the clamped Catmull–Clark boundary) give coefficients that fit the
  // boundary but not the interior: an affine solution came out 4e-3 wrong. Measured pivot ratios of the scaled
  // matrix: B-spline and NURBS 2.4–3.8, THB graded 35 levels deep 1.8–2.0, Catmull–Clark natural 2.4 and clamped on
  // a regular net 17–251, polyhedral 4–13, half-box 1.2e3–7.3e3 (refine 0..4, levelling off); clamped Catmull–Clark
  // at boundary EVs (square_evs.obj) 9.4e7, 3.9e8, 4.0e8 at refine 0..2.
  const double pivots = ldlt.vectorD().maxCoeff() / ldlt.vectorD().minCoeff();
  if (!(pivots <= kMaxDirichletPivotRatio)) {
    throw NumericalError("Dirichlet projection: the traces of the " + std::to_string(ns) +
                         " functions on the Dirichlet boundary are nearly dependent (pivot ratio " + format_ratio(pivots) +
                         " of their boundary mass matrix scaled to unit diagonal, above " +
                         format_ratio(kMaxDirichletPivotRatio) + "): strong conditions would be wrong; impose them weakly (--dirichlet-method nitsche), give that "
                         "part Neumann data, or use a basis whose traces are independent there");
  }
  bc.values = scale.asDiagonal() * ldlt.solve(bs);
  if (trace.dependent().nonZeros() > 0) bc.coupling = trace.dependent();
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

DirichletConditions component_conditions(const DirichletConditions& scalar, int c, int d) {
  DirichletConditions bc;
  bc.dofs.reserve(scalar.dofs.size());
  for (Index i : scalar.dofs) bc.dofs.push_back(d * i + c);
  bc.values = scalar.values;
  if (scalar.coupling.nonZeros() > 0) {
    std::vector<Eigen::Triplet<double>> t;
    for (Index r = 0; r < scalar.coupling.outerSize(); ++r) {
      for (Eigen::SparseMatrix<double, Eigen::RowMajor>::InnerIterator it(scalar.coupling, r); it; ++it) {
        t.emplace_back(r, d * it.col() + c, it.value());
      }
    }
    bc.coupling.resize(scalar.coupling.rows(), d * scalar.coupling.cols());
    bc.coupling.setFromTriplets(t.begin(), t.end());
  }
  return bc;
}

DirichletConditions linear_conditions(const Eigen::SparseMatrix<double, Eigen::RowMajor>& r,
                                      const std::vector<Index>& prefer, double tolerance) {
  // The touched columns, preferred ones first.
  std::vector<char> touched(static_cast<std::size_t>(r.cols()), 0);
  for (Index i = 0; i < r.outerSize(); ++i) {
    for (Eigen::SparseMatrix<double, Eigen::RowMajor>::InnerIterator it(r, i); it; ++it) {
      if (it.value() != 0.0) touched[static_cast<std::size_t>(it.col())] = 1;
    }
  }
  std::vector<Index> order;
  std::vector<Index> column(static_cast<std::size_t>(r.cols()), -1);
  for (Index p : prefer) {
    if (p >= 0 && p < r.cols() && touched[static_cast<std::size_t>(p)] == 1) {
      touched[static_cast<std::size_t>(p)] = 2;
      order.push_back(p);
    }
  }
  for (Index c = 0; c < r.cols(); ++c) {
    if (touched[static_cast<std::size_t>(c)] == 1) order.push_back(c);
  }
  for (std::size_t k = 0; k < order.size(); ++k) column[static_cast<std::size_t>(order[k])] = static_cast<Index>(k);
  Eigen::MatrixXd a = Eigen::MatrixXd::Zero(r.rows(), static_cast<Index>(order.size()));
  for (Index i = 0; i < r.outerSize(); ++i) {
    for (Eigen::SparseMatrix<double, Eigen::RowMajor>::InnerIterator it(r, i); it; ++it) {
      if (it.value() != 0.0) a(i, column[static_cast<std::size_t>(it.col())]) += it.value();
    }
  }
  for (Index i = 0; i < a.rows(); ++i) {
    const double m = a.row(i).cwiseAbs().maxCoeff();
    if (m > 0) a.row(i) /= m;
  }
  std::vector<std::pair<Index, Index>> pivots;  // (dof, row of a)
  Index rank = 0;
  for (Index j = 0; j < a.cols() && rank < a.rows(); ++j) {
    Index best = rank;
    a.col(j).tail(a.rows() - rank).cwiseAbs().maxCoeff(&best);
    best += rank;
    if (!(std::abs(a(best, j)) > tolerance)) continue;
    a.row(best).swap(a.row(rank));
    a.row(rank) /= a(rank, j);
    for (Index i = 0; i < a.rows(); ++i) {
      if (i != rank && a(i, j) != 0.0) a.row(i) -= a(i, j) * a.row(rank);
    }
    pivots.emplace_back(order[static_cast<std::size_t>(j)], rank);
    ++rank;
  }
  std::sort(pivots.begin(), pivots.end());
  std::vector<char> is_pivot(order.size(), 0);
  for (const auto& [dof, row] : pivots) is_pivot[static_cast<std::size_t>(column[static_cast<std::size_t>(dof)])] = 1;
  DirichletConditions bc;
  bc.values = Eigen::VectorXd::Zero(static_cast<Index>(pivots.size()));
  std::vector<Eigen::Triplet<double>> t;
  for (std::size_t k = 0; k < pivots.size(); ++k) {
    bc.dofs.push_back(pivots[k].first);
    for (Index j = 0; j < a.cols(); ++j) {
      const double v = a(pivots[k].second, j);
      if (!is_pivot[static_cast<std::size_t>(j)] && std::abs(v) > 1e-14) {
        t.emplace_back(static_cast<Index>(k), order[static_cast<std::size_t>(j)], v);
      }
    }
  }
  bc.coupling.resize(static_cast<Index>(pivots.size()), r.cols());
  bc.coupling.setFromTriplets(t.begin(), t.end());
  return bc;
}

DirichletConditions merge_conditions(const std::vector<DirichletConditions>& sets, Index num_dofs) {
  std::vector<std::pair<Index, std::pair<std::size_t, Index>>> all;  // dof → (set, row)
  bool coupled = false;
  for (std::size_t s = 0; s < sets.size(); ++s) {
    for (std::size_t k = 0; k < sets[s].dofs.size(); ++k) all.push_back({sets[s].dofs[k], {s, static_cast<Index>(k)}});
    coupled = coupled || sets[s].coupling.nonZeros() > 0;
  }
  std::sort(all.begin(), all.end());
  DirichletConditions bc;
  bc.values.resize(static_cast<Index>(all.size()));
  std::vector<Eigen::Triplet<double>> t;
  for (std::size_t k = 0; k < all.size(); ++k) {
    if (k > 0 && all[k].first == all[k - 1].first) {
      throw InputError("Dirichlet conditions: dof " + std::to_string(all[k].first + 1) +
                       " is prescribed by two conditions (one component given twice where two parts meet: give it one "
                       "condition over both parts)");
    }
    const auto [s, row] = all[k].second;
    bc.dofs.push_back(all[k].first);
    bc.values(static_cast<Index>(k)) = sets[s].values(row);
    if (sets[s].coupling.nonZeros() > 0) {
      for (Eigen::SparseMatrix<double, Eigen::RowMajor>::InnerIterator it(sets[s].coupling, row); it; ++it) {
        t.emplace_back(static_cast<Index>(k), it.col(), it.value());
      }
    }
  }
  if (coupled) {
    bc.coupling.resize(static_cast<Index>(all.size()), num_dofs);
    bc.coupling.setFromTriplets(t.begin(), t.end());
  }
  return bc;
}

}  // namespace iga::fem
