// The refine-and-smooth algorithm applied to B-spline spaces: refinement matrices (coarse → fine
// coefficients) of a knot vector and the tensor-product prolongation of a Geometry (refine_smooth.hpp).
#include <memory>
#include <string>

#include "basis/bspline/rational_space.hpp"
#include "basis/bspline/tensor_space.hpp"
#include "core/error.hpp"
#include "refine/refine_smooth.hpp"

namespace iga::refine {

using basis::bspline::SplineCurve;

Eigen::SparseMatrix<double> refine_smooth_matrix(int degree, const std::vector<double>& knots,
                                                 const std::vector<double>& xs, std::vector<double>& fine_knots) {
  // Column j is the refinement of the unit vector e_j. A fine B-spline's coefficient on coarse B-spline j is
  // non-zero only if its support lies inside j's support, which holds for at most degree + 1 consecutive j
  // (those with the coarse interval under any non-empty fine interval of it). So G = degree + 2 runs on the
  // sums of every G-th unit vector give the whole matrix: in run r, fine coefficient i belongs to the one
  // j ≡ r (mod G) whose support contains fine i's. O(n·degree) work and memory instead of O(n²).
  const Index n = static_cast<Index>(knots.size()) - degree - 1;
  SplineCurve c;
  c.degree = degree;
  c.knots = knots;
  if (n < 1) throw InputError("refine-smooth: too few knots for degree " + std::to_string(degree));
  const Index groups = degree + 2;
  std::vector<Eigen::Triplet<double>> trip;
  const auto& t = knots;
  for (Index r = 0; r < groups; ++r) {
    c.control_points = Eigen::MatrixXd::Zero(n, 1);
    for (Index j = r; j < n; j += groups) c.control_points(j, 0) = 1.0;
    const SplineCurve f = refine_smooth(c, xs, RefineSmoothVariant::constant_memory);
    if (r == 0) fine_knots = f.knots;
    const auto& tau = f.knots;
    Index jmax = 0;  // the largest j with t_j <= tau_i (non-decreasing in i)
    for (Index i = 0; i < f.num_control_points(); ++i) {
      const double v = f.control_points(i, 0);
      if (v == 0.0) continue;
      while (jmax + 1 < n && t[static_cast<std::size_t>(jmax + 1)] <= tau[static_cast<std::size_t>(i)]) ++jmax;
      Index owner = -1;
      for (Index j = jmax; j >= 0 && j >= jmax - degree; --j) {
        if ((j - r) % groups == 0 &&
            tau[static_cast<std::size_t>(i + degree + 1)] <= t[static_cast<std::size_t>(j + degree + 1)]) {
          owner = j;
          break;
        }
      }
      if (owner < 0) throw NumericalError("refine-smooth (internal error): a fine coefficient outside every coarse support");
      trip.emplace_back(static_cast<int>(i), static_cast<int>(owner), v);
    }
  }
  Eigen::SparseMatrix<double> m(static_cast<Index>(fine_knots.size()) - degree - 1, n);
  m.setFromTriplets(trip.begin(), trip.end());
  return m;
}

Refinement refine_smooth_tensor(const basis::Geometry& geometry, const std::vector<Index>& intervals_u,
                                const std::vector<Index>& intervals_v) {
  // NURBS: the B-spline space underneath is refined, the weights carried along (refine_rational).
  const basis::bspline::RationalSpace* rational = basis::bspline::rational_space(geometry.space());
  const basis::bspline::TensorSpace* tensor = rational ? &rational->base() : basis::bspline::tensor_space(geometry.space());
  if (!tensor) {
    throw UnsupportedError("refine-and-smooth refinement of a '" + geometry.space().name() +
                           "' space is not implemented (tensor-product B-splines and NURBS only)");
  }
  auto one = [](const basis::bspline::KnotVector& kv, const std::vector<Index>& intervals,
                basis::bspline::KnotVector& fine) {
    SplineCurve c;
    c.degree = kv.degree();
    c.knots = kv.knots();
    c.control_points.resize(kv.num_basis(), 1);
    std::vector<double> fine_knots;
    Eigen::SparseMatrix<double> r =
        refine_smooth_matrix(kv.degree(), kv.knots(), basis::bspline::interval_midpoints(c, intervals), fine_knots);
    fine = basis::bspline::KnotVector(kv.degree(), fine_knots);
    return r;
  };
  basis::bspline::KnotVector fu, fv;
  const Eigen::SparseMatrix<double> ru = one(tensor->knots_u(), intervals_u, fu);
  const Eigen::SparseMatrix<double> rv = one(tensor->knots_v(), intervals_v, fv);
  // Global dof i + nu * j: R = kron(R_v, R_u).
  std::vector<Eigen::Triplet<double>> trip;
  trip.reserve(static_cast<std::size_t>(ru.nonZeros() * rv.nonZeros()));
  for (int kv = 0; kv < rv.outerSize(); ++kv) {
    for (Eigen::SparseMatrix<double>::InnerIterator itv(rv, kv); itv; ++itv) {
      for (int ku = 0; ku < ru.outerSize(); ++ku) {
        for (Eigen::SparseMatrix<double>::InnerIterator itu(ru, ku); itu; ++itu) {
          trip.emplace_back(itu.row() + ru.rows() * itv.row(), itu.col() + ru.cols() * itv.col(),
                            itu.value() * itv.value());
        }
      }
    }
  }
  Eigen::SparseMatrix<double> r(ru.rows() * rv.rows(), ru.cols() * rv.cols());
  r.setFromTriplets(trip.begin(), trip.end());
  auto fine = std::make_shared<const basis::bspline::TensorSpace>(fu, fv);
  if (rational) {
    Eigen::SparseMatrix<double> prolongation;
    basis::Geometry g = basis::bspline::refine_rational(geometry, fine, r, &prolongation);
    return {std::move(g), std::move(prolongation), true};
  }
  Eigen::MatrixXd cp = r * geometry.control_points();
  return {basis::Geometry(fine, std::move(cp)), std::move(r), true};
}

}  // namespace iga::refine
