#include "basis/curve/trace_space.hpp"

#include <Eigen/LU>
#include <Eigen/SPQRSupport>
#include <Eigen/SparseCholesky>
#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "core/error.hpp"

namespace iga::basis {

namespace {

constexpr int kSamples = 10;  // per edge: determines traces of degree <= 9 on the edge

// Chebyshev–Gauss points on (0, 1).
Eigen::VectorXd sample_parameters() {
  Eigen::VectorXd t(kSamples);
  for (int k = 0; k < kSamples; ++k) t(k) = 0.5 * (1.0 - std::cos(std::numbers::pi * (k + 0.5) / kSamples));
  return t;
}

// Sample parameters of an edge of an element that is not polynomial (an extraordinary corner may sit at either
// end): the Chebyshev points on each dyadic piece [2^-(l+1), 2^-l], l = 1..kGradedLevels, of both halves
// and on the two end pieces. The traces are piecewise polynomial on such pieces, so functions that differ only
// near an end are told apart (10 points on the whole edge would call them dependent).
constexpr int kGradedLevels = 24;

Eigen::VectorXd graded_sample_parameters() {
  const Eigen::VectorXd c = sample_parameters();
  Eigen::VectorXd t(2 * (kGradedLevels + 1) * kSamples);
  Eigen::Index k = 0;
  auto piece = [&](double a, double b) {
    for (int i = 0; i < kSamples; ++i) {
      const double x = a + (b - a) * c(i);
      t(k++) = x;
      t(k++) = 1.0 - x;
    }
  };
  for (int l = 1; l <= kGradedLevels; ++l) piece(std::ldexp(1.0, -l - 1), std::ldexp(1.0, -l));
  piece(0.0, std::ldexp(1.0, -kGradedLevels - 1));
  return t;
}

Eigen::Matrix2Xd side_points(Shape shape, int side, const Eigen::VectorXd& t) {
  Eigen::Matrix2Xd pts(2, t.size());
  for (Index k = 0; k < t.size(); ++k) pts.col(k) = side_point(shape, side, t(k));
  return pts;
}

void check_edges(const Space& space, const std::vector<BoundaryEdge>& edges) {
  if (edges.empty()) throw InputError("trace: no boundary edges");
  for (std::size_t k = 0; k < edges.size(); ++k) {
    const BoundaryEdge& b = edges[k];
    if (b.element < 0 || b.element >= space.num_elements()) {
      throw InputError("trace: edge " + std::to_string(k) + " names element " + std::to_string(b.element) +
                       " of a space with " + std::to_string(space.num_elements()) + " elements");
    }
    if (b.side < 0 || b.side >= num_sides(space.kind(b.element).shape)) {
      throw InputError("trace: edge " + std::to_string(k) + " names side " + std::to_string(b.side) +
                       " of element " + std::to_string(b.element));
    }
  }
}

// Which functions are dependent on the others, and how: the rank-revealing QR of the (sampled) Gram matrix g
// of the boundary functions. Fills s (independent, ascending positions), j (the rest) and A (|s| × |j| as
// triplets in (position in s, position in j)).
void split_dependent(const Eigen::SparseMatrix<double>& g, std::vector<Index>& s, std::vector<Index>& j,
                     std::vector<Eigen::Triplet<double>>& a) {
  const Index nd = g.rows();
  const double max_diag = g.diagonal().maxCoeff();
  Eigen::SparseMatrix<double> gc = g;
  gc.makeCompressed();
  Eigen::SPQR<Eigen::SparseMatrix<double>> qr;
  qr.setPivotThreshold(1e-10 * max_diag);
  qr.compute(gc);
  if (qr.info() != Eigen::Success) throw NumericalError("trace: QR of the boundary Gram matrix failed");
  const Index rank = qr.rank();
  std::vector<char> in_s(static_cast<std::size_t>(nd), 0);
  for (Index k = 0; k < rank; ++k) in_s[static_cast<std::size_t>(qr.colsPermutation().indices()(k))] = 1;
  std::vector<Index> pos(static_cast<std::size_t>(nd));
  for (Index k = 0; k < nd; ++k) {
    std::vector<Index>& to = in_s[static_cast<std::size_t>(k)] ? s : j;
    pos[static_cast<std::size_t>(k)] = static_cast<Index>(to.size());
    to.push_back(k);
  }
  std::vector<Eigen::Triplet<double>> tss, tsj;
  for (Index col = 0; col < g.outerSize(); ++col) {
    for (Eigen::SparseMatrix<double>::InnerIterator it(g, col); it; ++it) {
      if (!in_s[static_cast<std::size_t>(it.row())]) continue;
      const Index r = pos[static_cast<std::size_t>(it.row())], c = pos[static_cast<std::size_t>(col)];
      (in_s[static_cast<std::size_t>(col)] ? tss : tsj).emplace_back(r, c, it.value());
    }
  }
  const Index ns = static_cast<Index>(s.size()), nj = static_cast<Index>(j.size());
  Eigen::SparseMatrix<double> gss(ns, ns), gsj(ns, nj);
  gss.setFromTriplets(tss.begin(), tss.end());
  gsj.setFromTriplets(tsj.begin(), tsj.end());
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> ldlt(gss);
  if (ldlt.info() != Eigen::Success || ldlt.vectorD().minCoeff() <= 0.0) {
    throw NumericalError("trace: the independent boundary traces are not definite");
  }
  // Column by column (A = G_SS⁻¹ G_SJ is local, hence sparse). Each dependent trace must lie in the span of S:
  // G_JJ(j, j) = G_SJ(:, j) · A(:, j).
  Eigen::VectorXd column(ns);
  for (Index b = 0; b < nj; ++b) {
    column = ldlt.solve(Eigen::VectorXd(gsj.col(b)));
    double fit = 0.0;
    for (Eigen::SparseMatrix<double>::InnerIterator it(gsj, b); it; ++it) fit += it.value() * column(it.row());
    const Index jb = j[static_cast<std::size_t>(b)];
    if (std::abs(fit - g.coeff(jb, jb)) > 1e-8 * max_diag) {
      throw NumericalError("trace: a boundary trace is not in the span of the independent ones");
    }
    for (Index r = 0; r < ns; ++r) {
      if (std::abs(column(r)) > 1e-13) a.emplace_back(r, b, column(r));
    }
  }
}

// Chebyshev polynomials T_m(x) of x in [−1, 1], m = 0..n−1.
Eigen::RowVectorXd chebyshev_row(double x, int n) {
  Eigen::RowVectorXd r(n);
  r(0) = 1.0;
  if (n > 1) r(1) = x;
  for (int m = 2; m < n; ++m) r(m) = 2.0 * x * r(m - 1) - r(m - 2);
  return r;
}

// First and second derivatives (in t, x = 2t − 1) of T_m at the ends x = ±1: T_m'(±1) = (±1)^{m+1} m²,
// T_m''(±1) = (±1)^m m²(m² − 1)/3.
Eigen::RowVectorXd chebyshev_end_derivative(bool right, int n, int order) {
  Eigen::RowVectorXd r(n);
  for (int m = 0; m < n; ++m) {
    const double m2 = static_cast<double>(m) * m;
    const double sign = right ? 1.0 : ((m + order) % 2 == 0 ? 1.0 : -1.0);
    r(m) = (order == 1 ? 2.0 * m2 : 4.0 * m2 * (m2 - 1.0) / 3.0) * sign;
  }
  return r;
}

}  // namespace

void TraceSpace::end_derivatives(Index e, Index k, double t, int derivatives, CurveBasisValues& out) const {
  // The edge's traces interpolated at the Chebyshev sample points (exact for traces of degree < kSamples).
  const BoundaryEdge& b = edges_[static_cast<std::size_t>(e)];
  const Eigen::VectorXd ts = sample_parameters();
  BasisValues v;
  space_->evaluate(b.element, side_points(space_->kind(b.element).shape, b.side, ts), 0, v);
  Eigen::MatrixXd vander(kSamples, kSamples);
  for (int j = 0; j < kSamples; ++j) vander.row(j) = chebyshev_row(2.0 * ts(j) - 1.0, kSamples);
  const Eigen::PartialPivLU<Eigen::MatrixXd> lu(vander);
  const auto first = static_cast<std::size_t>(dof_offsets_[static_cast<std::size_t>(e)]);
  const bool right = t > 0.5;
  for (Index i = 0; i < out.value.rows(); ++i) {
    const Eigen::VectorXd c = lu.solve(v.value.row(local_rows_[first + static_cast<std::size_t>(i)]).transpose());
    out.dt(i, k) = chebyshev_end_derivative(right, kSamples, 1).dot(c);
    if (derivatives >= 2) out.dtt(i, k) = chebyshev_end_derivative(right, kSamples, 2).dot(c);
  }
}

TraceSpace::TraceSpace(std::shared_ptr<const Space> space, std::vector<BoundaryEdge> edges)
    : space_(std::move(space)), edges_(std::move(edges)) {
  if (!space_) throw InputError("trace: no space");
  check_edges(*space_, edges_);
  const Index n = space_->num_dofs();
  const Eigen::VectorXd t = sample_parameters(), graded = graded_sample_parameters();
  // Sampled restrictions, edge by edge; the largest |value| of each function on each edge.
  std::vector<Eigen::MatrixXd> samples(edges_.size());
  std::vector<double> peak(static_cast<std::size_t>(n), 0.0);
  BasisValues values;
  for (std::size_t k = 0; k < edges_.size(); ++k) {
    const BoundaryEdge& b = edges_[k];
    const bool polynomial = space_->polynomial_degree(b.element).has_value();
    space_->evaluate(b.element, side_points(space_->kind(b.element).shape, b.side, polynomial ? t : graded), 0, values);
    samples[k] = values.value;
    const std::span<const Index> dofs = space_->dofs(b.element);
    for (std::size_t i = 0; i < dofs.size(); ++i) {
      double& p = peak[static_cast<std::size_t>(dofs[i])];
      p = std::max(p, values.value.row(static_cast<Index>(i)).cwiseAbs().maxCoeff());
    }
  }
  const double top = *std::max_element(peak.begin(), peak.end());
  if (!(top > 0.0)) throw NumericalError("trace: every function vanishes on the boundary edges");
  // Position of each boundary function among them, -1 for the others; the Gram matrix at the samples.
  std::vector<Index> on(static_cast<std::size_t>(n), -1), boundary;
  for (Index i = 0; i < n; ++i) {
    if (peak[static_cast<std::size_t>(i)] > 1e-7 * top) {
      on[static_cast<std::size_t>(i)] = static_cast<Index>(boundary.size());
      boundary.push_back(i);
    }
  }
  const Index nb = static_cast<Index>(boundary.size());
  std::vector<Eigen::Triplet<double>> entries;
  for (std::size_t k = 0; k < edges_.size(); ++k) {
    const std::span<const Index> dofs = space_->dofs(edges_[k].element);
    const Eigen::MatrixXd gram = samples[k] * samples[k].transpose() / static_cast<double>(samples[k].cols());
    for (std::size_t a = 0; a < dofs.size(); ++a) {
      const Index ra = on[static_cast<std::size_t>(dofs[a])];
      if (ra < 0) continue;
      for (std::size_t c = 0; c < dofs.size(); ++c) {
        const Index rc = on[static_cast<std::size_t>(dofs[c])];
        if (rc >= 0) entries.emplace_back(ra, rc, gram(static_cast<Index>(a), static_cast<Index>(c)));
      }
    }
  }
  Eigen::SparseMatrix<double> g(nb, nb);
  g.setFromTriplets(entries.begin(), entries.end());
  std::vector<Index> s, j;
  std::vector<Eigen::Triplet<double>> a;
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> ldlt(g);
  if (ldlt.info() == Eigen::Success && ldlt.vectorD().minCoeff() > 1e-11 * ldlt.vectorD().maxCoeff()) {
    for (Index k = 0; k < nb; ++k) s.push_back(k);
  } else {
    split_dependent(g, s, j, a);
  }
  // Trace dofs and the maps.
  std::vector<Index> trace_of(static_cast<std::size_t>(n), -1);
  for (Index k : s) {
    trace_of[static_cast<std::size_t>(boundary[static_cast<std::size_t>(k)])] = static_cast<Index>(surface_dofs_.size());
    surface_dofs_.push_back(boundary[static_cast<std::size_t>(k)]);
  }
  const Index ns = static_cast<Index>(surface_dofs_.size());
  std::vector<Eigen::Triplet<double>> dep, res;
  for (const Eigen::Triplet<double>& e : a) {
    dep.emplace_back(e.row(), boundary[static_cast<std::size_t>(j[static_cast<std::size_t>(e.col())])], e.value());
  }
  res = dep;
  for (Index k = 0; k < ns; ++k) res.emplace_back(k, surface_dofs_[static_cast<std::size_t>(k)], 1.0);
  dependent_.resize(ns, n);
  dependent_.setFromTriplets(dep.begin(), dep.end());
  restriction_.resize(ns, n);
  restriction_.setFromTriplets(res.begin(), res.end());
  // Per element: the trace functions not zero on its edge, and their rows among the surface element's.
  dof_offsets_.push_back(0);
  for (std::size_t k = 0; k < edges_.size(); ++k) {
    const std::span<const Index> dofs = space_->dofs(edges_[k].element);
    for (std::size_t i = 0; i < dofs.size(); ++i) {
      const Index tr = trace_of[static_cast<std::size_t>(dofs[i])];
      if (tr < 0 || !(samples[k].row(static_cast<Index>(i)).cwiseAbs().maxCoeff() > 1e-7 * top)) continue;
      local_dofs_.push_back(tr);
      local_rows_.push_back(static_cast<Index>(i));
    }
    dof_offsets_.push_back(static_cast<Index>(local_dofs_.size()));
    max_local_ = std::max(max_local_, dof_offsets_.back() - dof_offsets_[dof_offsets_.size() - 2]);
  }
}

std::span<const Index> TraceSpace::dofs(Index e) const {
  const auto b = static_cast<std::size_t>(dof_offsets_[static_cast<std::size_t>(e)]);
  const auto f = static_cast<std::size_t>(dof_offsets_[static_cast<std::size_t>(e) + 1]);
  return {local_dofs_.data() + b, f - b};
}

void TraceSpace::evaluate(Index e, const Eigen::VectorXd& t, int derivatives, CurveBasisValues& out) const {
  const BoundaryEdge& b = edges_[static_cast<std::size_t>(e)];
  const Shape shape = space_->kind(b.element).shape;
  thread_local BasisValues surface;
  thread_local Eigen::Matrix2Xd pts;
  pts.resize(2, t.size());
  for (Index k = 0; k < t.size(); ++k) pts.col(k) = side_point(shape, b.side, t(k));
  space_->evaluate(b.element, pts, derivatives, surface);
  const Eigen::Vector2d d = side_tangent(shape, b.side);
  const auto first = static_cast<std::size_t>(dof_offsets_[static_cast<std::size_t>(e)]);
  const Index nl = dof_offsets_[static_cast<std::size_t>(e) + 1] - dof_offsets_[static_cast<std::size_t>(e)];
  out.resize(nl, t.size(), derivatives);
  for (Index i = 0; i < nl; ++i) {
    const Index r = local_rows_[first + static_cast<std::size_t>(i)];
    out.value.row(i) = surface.value.row(r);
    if (derivatives >= 1) out.dt.row(i) = d.x() * surface.du.row(r) + d.y() * surface.dv.row(r);
    if (derivatives >= 2) {
      out.dtt.row(i) = d.x() * d.x() * surface.duu.row(r) + 2.0 * d.x() * d.y() * surface.duv.row(r) +
                       d.y() * d.y() * surface.dvv.row(r);
    }
  }
  // At an end of the edge the surface evaluator may give no derivatives (Catmull–Clark at an extraordinary
  // vertex: the limit stencil only); there the one-sided derivatives come from the edge's interpolant.
  if (derivatives >= 1 && nl > 0) {
    for (Index k = 0; k < t.size(); ++k) {
      const bool end = t(k) <= 1e-14 || t(k) >= 1.0 - 1e-14;
      if (end && out.dt.col(k).cwiseAbs().maxCoeff() == 0.0) end_derivatives(e, k, t(k), derivatives, out);
    }
  }
}

BoundaryTrace trace_geometry(const Geometry& geometry, std::vector<BoundaryEdge> edges) {
  if (geometry.dim() != 2) throw InputError("trace: the geometry is a surface in 3D, not a planar domain");
  if (edges.empty()) edges = geometry.space().boundary_edges();
  auto space = std::make_shared<const TraceSpace>(geometry.space_ptr(), std::move(edges));
  Eigen::MatrixXd points = space->restriction() * geometry.control_points();
  return BoundaryTrace{space, CurveGeometry(space, std::move(points))};
}

}  // namespace iga::basis
