#include "basis/curve/spline_curve_space.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "core/error.hpp"

namespace iga::basis {

namespace {

constexpr int kMaxDegree = 30;

// Values and derivatives (up to `nd` <= 2) of the p + 1 B-splines that are non-zero on the knot interval
// [w[p], w[p+1]] at x, from the knot window w[k] = t_{span−p+k}, k = 0..2p+1 (Piegl–Tiller A2.3: the
// triangular table of Cox–de Boor, then the derivative recurrence on its columns). out[r][j], j = 0..p.
void window_basis(const double* w, int p, double x, int nd, double out[3][kMaxDegree + 1]) {
  double ndu[kMaxDegree + 1][kMaxDegree + 1], left[kMaxDegree + 1], right[kMaxDegree + 1];
  ndu[0][0] = 1.0;
  for (int j = 1; j <= p; ++j) {
    left[j] = x - w[p + 1 - j];
    right[j] = w[p + j] - x;
    double saved = 0.0;
    for (int r = 0; r < j; ++r) {
      ndu[j][r] = right[r + 1] + left[j - r];  // lower triangle: knot differences
      const double temp = ndu[r][j - 1] / ndu[j][r];
      ndu[r][j] = saved + right[r + 1] * temp;
      saved = left[j - r] * temp;
    }
    ndu[j][j] = saved;
  }
  for (int j = 0; j <= p; ++j) out[0][j] = ndu[j][p];
  double a[2][kMaxDegree + 1];
  for (int r = 0; r <= p; ++r) {
    int s1 = 0, s2 = 1;
    a[0][0] = 1.0;
    for (int k = 1; k <= nd; ++k) {
      double d = 0.0;
      const int rk = r - k, pk = p - k;
      if (r >= k) {
        a[s2][0] = a[s1][0] / ndu[pk + 1][rk];
        d = a[s2][0] * ndu[rk][pk];
      }
      const int j1 = rk >= -1 ? 1 : -rk;
      const int j2 = (r - 1 <= pk) ? k - 1 : p - r;
      for (int j = j1; j <= j2; ++j) {
        a[s2][j] = (a[s1][j] - a[s1][j - 1]) / ndu[pk + 1][rk + j];
        d += a[s2][j] * ndu[rk + j][pk];
      }
      if (r <= pk) {
        a[s2][k] = -a[s1][k - 1] / ndu[pk + 1][r];
        d += a[s2][k] * ndu[r][pk];
      }
      out[k][r] = d;
      std::swap(s1, s2);
    }
  }
  double factor = p;
  for (int k = 1; k <= nd; ++k) {
    for (int j = 0; j <= p; ++j) out[k][j] *= factor;
    factor *= (p - k);
  }
}

}  // namespace

SplineCurveSpace::SplineCurveSpace(int degree, std::vector<SplineSegment> segments)
    : degree_(degree), segments_(std::move(segments)) {
  if (degree_ < 1 || degree_ > kMaxDegree) {
    throw InputError("spline curve space: degree " + std::to_string(degree_) + " (expected 1.." +
                     std::to_string(kMaxDegree) + ")");
  }
  if (segments_.empty()) throw InputError("spline curve space: no segments");
  const Index p = degree_;
  for (std::size_t k = 0; k < segments_.size(); ++k) {
    const SplineSegment& s = segments_[k];
    if (s.elements < 1 || (s.closed && s.elements < p + 1)) {
      throw InputError("spline curve space: segment " + std::to_string(k) + " has " + std::to_string(s.elements) +
                       " elements (a " + (s.closed ? "closed" : "open") + " segment of degree " +
                       std::to_string(p) + " needs at least " + std::to_string(s.closed ? p + 1 : 1) + ")");
    }
    first_element_.push_back(static_cast<Index>(element_segment_.size()));
    first_dof_.push_back(num_dofs_);
    const Index nd = s.closed ? s.elements : s.elements + p;
    for (Index i = 0; i < s.elements; ++i) {
      element_segment_.push_back(static_cast<Index>(k));
      for (Index j = 0; j <= p; ++j) {
        const Index local = s.closed ? ((i - p + j) % nd + nd) % nd : i + j;
        dofs_.push_back(num_dofs_ + local);
      }
    }
    num_dofs_ += nd;
  }
}

std::span<const Index> SplineCurveSpace::dofs(Index e) const {
  return std::span<const Index>(dofs_).subspan(static_cast<std::size_t>(e * (degree_ + 1)),
                                              static_cast<std::size_t>(degree_ + 1));
}

Index SplineCurveSpace::segment_dofs(Index segment) const {
  const SplineSegment& s = segments_[static_cast<std::size_t>(segment)];
  return s.closed ? s.elements : s.elements + degree_;
}

void SplineCurveSpace::evaluate(Index e, const Eigen::VectorXd& t, int derivatives, CurveBasisValues& out) const {
  const int p = degree_, nd = std::clamp(derivatives, 0, 2);
  const Index seg = segment_of(e), i = index_in_segment(e);
  const SplineSegment& s = segments_[static_cast<std::size_t>(seg)];
  double window[2 * kMaxDegree + 2];
  for (int k = 0; k <= 2 * p + 1; ++k) {
    const Index knot = i + k - p;
    window[k] = static_cast<double>(s.closed ? knot : std::clamp<Index>(knot, 0, s.elements));
  }
  out.resize(p + 1, t.size(), nd);
  double values[3][kMaxDegree + 1];
  for (Index q = 0; q < t.size(); ++q) {
    window_basis(window, p, static_cast<double>(i) + t(q), nd, values);
    for (int j = 0; j <= p; ++j) {
      out.value(j, q) = values[0][j];
      if (nd >= 1) out.dt(j, q) = values[1][j];
      if (nd >= 2) out.dtt(j, q) = values[2][j];
    }
  }
}

Eigen::VectorXd SplineCurveSpace::greville(Index segment) const {
  const SplineSegment& s = segments_[static_cast<std::size_t>(segment)];
  const Index p = degree_, nd = segment_dofs(segment);
  Eigen::VectorXd g(nd);
  for (Index j = 0; j < nd; ++j) {
    if (s.closed) {
      // N_j has the knots j, ..., j + p + 1 (it is non-zero on elements j..j+p, see dofs()).
      g(j) = std::fmod(static_cast<double>(j) + 0.5 * static_cast<double>(p + 1), static_cast<double>(nd));
    } else {
      double sum = 0.0;  // knots t_{j+1}..t_{j+p} of the clamped vector, t_m = clamp(m − p, 0, elements)
      for (Index m = j + 1; m <= j + p; ++m) sum += static_cast<double>(std::clamp<Index>(m - p, 0, s.elements));
      g(j) = sum / static_cast<double>(p);
    }
  }
  return g;
}

Eigen::Vector3d SplineCurveSpace::function(Index segment, Index j, double s) const {
  const SplineSegment& seg = segments_[static_cast<std::size_t>(segment)];
  const double n = static_cast<double>(seg.elements);
  if (seg.closed) s = std::fmod(std::fmod(s, n) + n, n);
  s = std::clamp(s, 0.0, n);
  const Index i = std::min<Index>(static_cast<Index>(std::floor(s)), seg.elements - 1);
  const Index e = first_element(segment) + i;
  CurveBasisValues v;
  evaluate(e, Eigen::VectorXd::Constant(1, s - static_cast<double>(i)), 2, v);
  const std::span<const Index> d = dofs(e);
  Eigen::Vector3d r = Eigen::Vector3d::Zero();
  for (std::size_t k = 0; k < d.size(); ++k) {
    if (d[k] == first_dof(segment) + j) r += Eigen::Vector3d(v.value(static_cast<Index>(k), 0),
                                                             v.dt(static_cast<Index>(k), 0),
                                                             v.dtt(static_cast<Index>(k), 0));
  }
  return r;
}

}  // namespace iga::basis
