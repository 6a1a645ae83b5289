#pragma once
// Random B-spline curves for the refinement tests (fixed seeds by the caller).
#include <random>

#include "basis/bspline/knot_vector.hpp"
#include "basis/bspline/spline_curve.hpp"

namespace iga::refine::test {

using basis::bspline::SplineCurve;

/// Clamped knots on [0, L], `breaks` interior breakpoints of multiplicity 1..degree, control points in R^dim.
inline SplineCurve random_curve(std::mt19937& rng, int degree, int breaks, int dim = 3) {
  std::uniform_real_distribution<double> gap(0.2, 2.0), coord(-1.0, 1.0);
  std::uniform_int_distribution<int> mult(1, degree);
  SplineCurve c;
  c.degree = degree;
  double x = 0.0;
  c.knots.assign(static_cast<std::size_t>(degree) + 1, x);
  for (int b = 0; b < breaks; ++b) {
    x += gap(rng);
    const int m = mult(rng);
    for (int i = 0; i < m; ++i) c.knots.push_back(x);
  }
  x += gap(rng);
  for (int i = 0; i <= degree; ++i) c.knots.push_back(x);
  const Index n = static_cast<Index>(c.knots.size()) - degree - 1;
  c.control_points.resize(n, dim);
  for (Index i = 0; i < n; ++i)
    for (int j = 0; j < dim; ++j) c.control_points(i, j) = coord(rng);
  return c;
}

/// Cox–de Boor value of the curve at x through the library's KnotVector (clamped knots only).
inline Eigen::VectorXd cox_de_boor(const SplineCurve& c, double x) {
  basis::bspline::KnotVector kv(c.degree, c.knots);
  const Index span = kv.span(x);
  const Eigen::MatrixXd n = basis::bspline::basis_functions(kv, span, x, 0);
  Eigen::VectorXd v = Eigen::VectorXd::Zero(c.control_points.cols());
  for (int i = 0; i <= c.degree; ++i) v += n(0, i) * c.control_points.row(span - c.degree + i).transpose();
  return v;
}

/// max |a - b| / max(1, max |b|).
inline double rel_diff(const Eigen::MatrixXd& a, const Eigen::MatrixXd& b) {
  if (a.rows() != b.rows() || a.cols() != b.cols()) return 1e300;
  return (a - b).cwiseAbs().maxCoeff() / std::max(1.0, b.cwiseAbs().maxCoeff());
}

inline double knots_diff(const std::vector<double>& a, const std::vector<double>& b) {
  if (a.size() != b.size()) return 1e300;
  double m = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i) m = std::max(m, std::abs(a[i] - b[i]));
  return m;
}

}  // namespace iga::refine::test
