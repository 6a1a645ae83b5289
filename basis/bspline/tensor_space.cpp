#include "basis/bspline/tensor_space.hpp"

#include <algorithm>

#include "basis/bspline/bernstein.hpp"
#include "basis/bspline/extraction.hpp"
#include "basis/bspline/knot_insertion.hpp"
#include "core/error.hpp"

namespace iga::basis::bspline {

namespace {
// For each interval, the lowest interval whose extraction operator equals its own to 1e-14 (the entries lie in
// [0, 1]; uniform knots give operators that differ by rounding only). Compared against at most 64 distinct
// operators (uniform knots have 2p − 1), so irregular knot vectors cost O(64) per interval and simply find fewer twins.
std::vector<Index> twin_intervals(const std::vector<Eigen::MatrixXd>& c) {
  std::vector<Index> twin(c.size());
  std::vector<Index> distinct;
  for (std::size_t i = 0; i < c.size(); ++i) {
    twin[i] = static_cast<Index>(i);
    for (Index d : distinct) {
      if ((c[static_cast<std::size_t>(d)] - c[i]).cwiseAbs().maxCoeff() <= 1e-14) {
        twin[i] = d;
        break;
      }
    }
    if (twin[i] == static_cast<Index>(i) && distinct.size() < 64) distinct.push_back(twin[i]);
  }
  return twin;
}
}  // namespace

TensorSpace::TensorSpace(KnotVector u, KnotVector v) : u_(std::move(u)), v_(std::move(v)) {
  nu_ = u_.num_basis();
  nv_ = v_.num_basis();
  nex_ = u_.num_intervals();
  ney_ = v_.num_intervals();
  const int pu = u_.degree(), pv = v_.degree();
  nloc_ = (pu + 1) * (pv + 1);
  cu_ = extraction_operators(u_);
  cv_ = extraction_operators(v_);
  twin_u_ = twin_intervals(cu_);
  twin_v_ = twin_intervals(cv_);
  dofs_.resize(static_cast<std::size_t>(num_elements() * nloc_));
  for (Index ey = 0; ey < ney_; ++ey) {
    const Index sy = v_.interval_spans()[ey] - pv;
    for (Index ex = 0; ex < nex_; ++ex) {
      const Index sx = u_.interval_spans()[ex] - pu;
      Index* d = &dofs_[static_cast<std::size_t>((ex + nex_ * ey) * nloc_)];
      for (int b = 0; b <= pv; ++b) {
        for (int a = 0; a <= pu; ++a) *d++ = (sx + a) + nu_ * (sy + b);
      }
    }
  }
}

Index TensorSpace::reference_element(Index e) const {
  const Index ex = e % nex_, ey = e / nex_;
  return twin_u_[static_cast<std::size_t>(ex)] + nex_ * twin_v_[static_cast<std::size_t>(ey)];
}

std::span<const Index> TensorSpace::dofs(Index e) const {
  return {&dofs_[static_cast<std::size_t>(e * nloc_)], static_cast<std::size_t>(nloc_)};
}

Eigen::Vector4d TensorSpace::element_box(Index e) const {
  const Index ex = e % nex_, ey = e / nex_;
  const Index mx = u_.interval_spans()[ex], my = v_.interval_spans()[ey];
  return {u_[mx], u_[mx + 1], v_[my], v_[my + 1]};
}

void evaluate_bezier_tensor(const Eigen::MatrixXd& cu, const Eigen::MatrixXd& cv, const Eigen::Matrix2Xd& pts,
                            int derivatives, BasisValues& out) {
  const int pu = static_cast<int>(cu.rows()) - 1, pv = static_cast<int>(cv.rows()) - 1;
  const Index nloc = (pu + 1) * (pv + 1);
  const Index q = pts.cols();
  // 1D Bernstein values at the points (cached per thread: quadrature evaluates every element at the same
  // reference points), then the element's B-splines by extraction: N = C B.
  struct Cache {
    Eigen::Matrix2Xd pts;
    int pu = -1, pv = -1, derivatives = -1;
    Eigen::MatrixXd bu[3], bv[3];
  };
  thread_local Cache cache;
  if (cache.pu != pu || cache.pv != pv || cache.derivatives < derivatives || cache.pts.cols() != q ||
      cache.pts != pts) {
    cache.pts = pts;
    cache.pu = pu;
    cache.pv = pv;
    cache.derivatives = derivatives;
    bernstein(pu, pts.row(0), derivatives, cache.bu[0], &cache.bu[1], &cache.bu[2]);
    bernstein(pv, pts.row(1), derivatives, cache.bv[0], &cache.bv[1], &cache.bv[2]);
  }
  thread_local Eigen::MatrixXd nu[3], nv[3];
  for (int d = 0; d <= derivatives; ++d) {
    nu[d].noalias() = cu.lazyProduct(cache.bu[d]);  // small products: no GEMM blocking
    nv[d].noalias() = cv.lazyProduct(cache.bv[d]);
  }
  // Tensor products, local index a + (pu+1) b.
  auto tensor = [&](const Eigen::MatrixXd& fu, const Eigen::MatrixXd& fv, Eigen::MatrixXd& dst) {
    dst.resize(nloc, q);
    for (int b = 0; b <= pv; ++b) {
      dst.middleRows(b * (pu + 1), pu + 1) = fu.array().rowwise() * fv.row(b).array();
    }
  };
  tensor(nu[0], nv[0], out.value);
  if (derivatives >= 1) {
    tensor(nu[1], nv[0], out.du);
    tensor(nu[0], nv[1], out.dv);
  }
  if (derivatives >= 2) {
    tensor(nu[2], nv[0], out.duu);
    tensor(nu[1], nv[1], out.duv);
    tensor(nu[0], nv[2], out.dvv);
  }
}

void TensorSpace::evaluate(Index e, const Eigen::Matrix2Xd& pts, int derivatives, BasisValues& out) const {
  const Index ex = e % nex_, ey = e / nex_;
  evaluate_bezier_tensor(cu_[static_cast<std::size_t>(ex)], cv_[static_cast<std::size_t>(ey)], pts, derivatives, out);
}

std::vector<BoundaryEdge> TensorSpace::boundary_edges() const {
  std::vector<BoundaryEdge> edges;
  for (Index ex = 0; ex < nex_; ++ex) edges.push_back({ex, 0, 0});
  for (Index ey = 0; ey < ney_; ++ey) edges.push_back({nex_ - 1 + nex_ * ey, 1, 1});
  for (Index ex = nex_ - 1; ex >= 0; --ex) edges.push_back({ex + nex_ * (ney_ - 1), 2, 2});
  for (Index ey = ney_ - 1; ey >= 0; --ey) edges.push_back({nex_ * ey, 3, 3});
  return edges;
}

std::vector<InteriorEdge> TensorSpace::interior_edges() const {
  // Interval k starts at knot index spans[k]; the knot between intervals k − 1 and k has multiplicity
  // spans[k] − spans[k − 1] (t_mu < t_{mu+1} = ... = t_{mu'} < t_{mu'+1}).
  auto continuity = [](const KnotVector& kv, Index k) {
    const auto& spans = kv.interval_spans();
    return kv.degree() - static_cast<int>(spans[static_cast<std::size_t>(k)] - spans[static_cast<std::size_t>(k - 1)]);
  };
  std::vector<InteriorEdge> edges;
  edges.reserve(static_cast<std::size_t>(std::max<Index>(0, (nex_ - 1) * ney_) + std::max<Index>(0, nex_ * (ney_ - 1))));
  for (Index ey = 0; ey < ney_; ++ey) {
    for (Index ex = 1; ex < nex_; ++ex) {
      // side 1 of the left element runs up (1, t), side 3 of the right one down (0, 1 − t).
      const Index e = ex - 1 + nex_ * ey;
      edges.push_back({{e, e + 1}, {1, 3}, {0.0, 1.0}, {1.0, 0.0}, continuity(u_, ex)});
    }
  }
  for (Index ey = 1; ey < ney_; ++ey) {
    for (Index ex = 0; ex < nex_; ++ex) {
      // side 2 of the lower element runs left (1 − t, 1), side 0 of the upper one right (t, 0).
      const Index e = ex + nex_ * (ey - 1);
      edges.push_back({{e, e + nex_}, {2, 0}, {0.0, 1.0}, {1.0, 0.0}, continuity(v_, ey)});
    }
  }
  return edges;
}

const TensorSpace* tensor_space(const Space& space) { return dynamic_cast<const TensorSpace*>(&space); }

Eigen::SparseMatrix<double> refinement_matrix(const TensorSpace& coarse, const TensorSpace& fine) {
  const Eigen::SparseMatrix<double> ru = refinement_matrix(coarse.knots_u(), fine.knots_u());
  const Eigen::SparseMatrix<double> rv = refinement_matrix(coarse.knots_v(), fine.knots_v());
  std::vector<Eigen::Triplet<double>> entries;
  entries.reserve(static_cast<std::size_t>(ru.nonZeros() * rv.nonZeros()));
  const Index nuf = fine.num_basis_u(), nuc = coarse.num_basis_u();
  for (Index kv = 0; kv < rv.outerSize(); ++kv) {
    for (Eigen::SparseMatrix<double>::InnerIterator itv(rv, kv); itv; ++itv) {
      for (Index ku = 0; ku < ru.outerSize(); ++ku) {
        for (Eigen::SparseMatrix<double>::InnerIterator itu(ru, ku); itu; ++itu) {
          entries.emplace_back(itu.row() + nuf * itv.row(), itu.col() + nuc * itv.col(), itu.value() * itv.value());
        }
      }
    }
  }
  Eigen::SparseMatrix<double> r(fine.num_dofs(), coarse.num_dofs());
  r.setFromTriplets(entries.begin(), entries.end());
  return r;
}

}  // namespace iga::basis::bspline
