#include "refine/refine_smooth.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <string>

#include "basis/bspline/tensor_space.hpp"
#include "core/error.hpp"

namespace iga::refine {
namespace {

using RowMatrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;

// (num / den) for an affine weight; 0/0 (all the knots involved coincide, so both points carry the same
// arguments) is 0.
double ratio(double num, double den) {
  if (den > 0.0) return num / den;
  if (num == 0.0) return 0.0;
  throw NumericalError("refine-and-smooth: a zero knot span in an affine combination");
}

// The index sets and the polar labels of the points P^λ_i. Positions p are Z indices for odd d and the Z
// intervals (p, p+1) for even d.
struct Layout {
  int d = 0;
  Index nz = 0, k = 0;
  std::vector<double> u;
  std::vector<char> in_y;
  std::vector<Index> y;         // Z index of the original knot t_r
  std::vector<Index> count_le;  // number of Y indices <= j
  Index first = 0, last = -1;   // the positions computed (§7)

  Index count_lt(Index j) const { return j <= 0 ? 0 : count_le[static_cast<std::size_t>(j - 1)]; }
  // The region cen^λ_p(Z) = [lo, hi] (hi = lo - 1 when empty).
  void region(Index p, int lambda, Index& lo, Index& hi) const {
    if (d % 2) {
      lo = p - (lambda - 1) / 2;
      hi = p + (lambda - 1) / 2;
    } else {
      lo = p + 1 - lambda / 2;
      hi = p + lambda / 2;
    }
  }
  // Least and greatest index of the polar arguments of P^λ_p; -1 if they run out of Z.
  Index min_label(Index p, int lambda) const {
    Index lo, hi;
    region(p, lambda, lo, hi);
    const Index s = (d - lambda) / 2;
    if (lo < 0) return -1;
    if (s == 0) return lo;
    const Index idx = count_lt(lo) - s;
    return idx < 0 ? -1 : y[static_cast<std::size_t>(idx)];
  }
  Index max_label(Index p, int lambda) const {
    Index lo, hi;
    region(p, lambda, lo, hi);
    const Index s = (d - lambda) / 2;
    if (hi >= nz) return -1;
    if (s == 0) return hi;
    const Index idx = count_le[static_cast<std::size_t>(hi)] + s - 1;
    return idx >= k ? -1 : y[static_cast<std::size_t>(idx)];
  }
  double at(Index j) const { return u[static_cast<std::size_t>(j)]; }
};

Layout make_layout(const PolarSpline& s, const std::vector<double>& new_knots) {
  Layout L;
  L.d = s.degree;
  L.k = static_cast<Index>(s.knots.size());
  const auto& t = s.knots;
  for (Index j = 0; j < L.k; ++j) {
    L.y.push_back(static_cast<Index>(L.u.size()));
    L.u.push_back(t[static_cast<std::size_t>(j)]);
    L.in_y.push_back(1);
    if (j + 1 < L.k && !std::isnan(new_knots[static_cast<std::size_t>(j)])) {
      L.u.push_back(new_knots[static_cast<std::size_t>(j)]);
      L.in_y.push_back(0);
    }
  }
  L.nz = static_cast<Index>(L.u.size());
  L.count_le.resize(L.u.size());
  Index c = 0;
  for (std::size_t j = 0; j < L.u.size(); ++j) L.count_le[j] = c += L.in_y[j];
  const Index h = L.d / 2;
  if (L.d % 2) {
    L.first = L.y[static_cast<std::size_t>(h)];
    L.last = L.y[static_cast<std::size_t>(L.k - 1 - h)];
  } else {
    L.first = L.y[static_cast<std::size_t>(h - 1)];
    L.last = L.y[static_cast<std::size_t>(L.k - h)] - 1;
  }
  return L;
}

// One point of a smoothing stage: its weights on P^{λ-2}_{p-1}, P_p, P_{p+1}, or a marker.
struct Action {
  enum Kind { copy, left_pair, right_pair, factorised, three, marker } kind = marker;
  double w0 = 0, w1 = 0, w2 = 0;  // pairs: (w0, w1) on the two points; three: all; factorised: see apply
  double dm = 0, de = 0, pm = 0;  // factorised: D weight on P_{p-1}, E weight on P_{p+1}, P weight on D
};

Action plan(const Layout& L, Index p, int lambda, bool vprev, bool vself, bool vnext) {
  Action a;
  if (!vself) return a;
  Index beta, gamma;
  L.region(p, lambda, beta, gamma);
  if (beta < 0 || gamma >= L.nz) return a;
  const bool nb = !L.in_y[static_cast<std::size_t>(beta)], ng = !L.in_y[static_cast<std::size_t>(gamma)];
  if (!nb && !ng) {
    a.kind = Action::copy;
    return a;
  }
  if (nb && !ng) {  // (b): new knot below p, from P_p and P_{p+1}; displaces t_alpha
    const Index ia = L.min_label(p, lambda - 2), id = L.max_label(p + 1, lambda - 2);
    if (!vnext || ia < 0 || id < 0) return a;
    const double ta = L.at(ia), td = L.at(id), ub = L.at(beta);
    a.kind = Action::right_pair;
    a.w1 = ratio(ub - ta, td - ta);
    a.w0 = 1.0 - a.w1;
    return a;
  }
  if (!nb && ng) {  // (c): new knot above p, from P_{p-1} and P_p; displaces t_delta
    const Index ia = L.min_label(p - 1, lambda - 2), id = L.max_label(p, lambda - 2);
    if (!vprev || ia < 0 || id < 0) return a;
    const double ta = L.at(ia), td = L.at(id), ug = L.at(gamma);
    a.kind = Action::left_pair;
    a.w0 = ratio(td - ug, td - ta);
    a.w1 = 1.0 - a.w0;
    return a;
  }
  // (d): both, from P_{p-1}, P_p, P_{p+1}, which share d - 2 arguments.
  const Index ia = L.min_label(p, lambda - 2), id = L.max_label(p, lambda - 2);
  if (!vprev || !vnext || ia < 0 || id < 0) return a;
  const double ta = L.at(ia), td = L.at(id), ub = L.at(beta), ug = L.at(gamma);
  const double x = L.d % 2 ? L.at(p) : 0.5 * (L.at(p) + L.at(p + 1));  // the pivot
  if (ta < x && x < td) {
    a.kind = Action::factorised;
    a.dm = (td - ug) / (td - x);  // D = dm P_{p-1} + (1 - dm) P_p           (6)
    a.de = (ub - ta) / (x - ta);  // E = (1 - de) P_p + de P_{p+1}           (7)
    a.pm = (td - x) / (td - ta);  // P = pm D + (1 - pm) E                   (8)
  } else {
    a.kind = Action::three;  // (5) unfactorised
    a.w0 = ratio(td - ug, td - ta);
    a.w2 = ratio(ub - ta, td - ta);
    a.w1 = 1.0 - a.w0 - a.w2;
  }
  return a;
}

// Applies an action; prev/self/next are rows of P^{λ-2}. Returns the affine combinations used.
template <class Out, class A, class B, class C>
int apply(const Action& a, Out&& out, const A& prev, const B& self, const C& next) {
  switch (a.kind) {
    case Action::copy:
      out = self;
      return 0;
    case Action::left_pair:
      out = a.w0 * prev + a.w1 * self;
      return 1;
    case Action::right_pair:
      out = a.w0 * self + a.w1 * next;
      return 1;
    case Action::factorised:
      out = a.pm * (a.dm * prev + (1.0 - a.dm) * self) + (1.0 - a.pm) * ((1.0 - a.de) * self + a.de * next);
      return 3;
    case Action::three:
      out = a.w0 * prev + a.w1 * self + a.w2 * next;
      return 2;
    case Action::marker:
      return 0;
  }
  return 0;
}

// The refine stage: P^0 (even d) or P^1 (odd d) on positions L.first..L.last.
RowMatrix refine_stage(const Layout& L, const PolarSpline& s, long long& count) {
  const Index n = L.last - L.first + 1, h = L.d / 2;
  RowMatrix P(n, s.control_points.cols());
  const auto& t = s.knots;
  for (Index p = L.first; p <= L.last; ++p) {
    const Index r = L.count_le[static_cast<std::size_t>(p)] - 1;  // the original knot at or below p
    if (L.d % 2 == 0) {
      P.row(p - L.first) = s.control_points.row(r - h + 1);
    } else if (L.in_y[static_cast<std::size_t>(p)]) {
      P.row(p - L.first) = s.control_points.row(r - h);
    } else {  // (3): Q_{p-1}, Q_{p+1} share d - 1 arguments
      const Index qa = r - h, qb = r + 1 - h;
      const double ta = t[static_cast<std::size_t>(qa)], td = t[static_cast<std::size_t>(qb + L.d - 1)];
      const double w = ratio(L.at(p) - ta, td - ta);
      P.row(p - L.first) = (1.0 - w) * s.control_points.row(qa) + w * s.control_points.row(qb);
      ++count;
    }
  }
  return P;
}

}  // namespace

RefineSmoothResult refine_smooth(const PolarSpline& s, const std::vector<double>& new_knots,
                                 RefineSmoothVariant variant) {
  const int d = s.degree;
  const auto k = static_cast<Index>(s.knots.size());
  if (d < 1 || k < d || s.control_points.rows() != k - d + 1) {
    throw InputError("refine_smooth: " + std::to_string(k) + " knots of degree " + std::to_string(d) + " need " +
                     std::to_string(k - d + 1) + " control points, got " + std::to_string(s.control_points.rows()));
  }
  if (static_cast<Index>(new_knots.size()) != k - 1) {
    throw InputError("refine_smooth: one entry per knot interval expected (" + std::to_string(k - 1) + "), got " +
                     std::to_string(new_knots.size()));
  }
  for (Index j = 0; j + 1 < k; ++j) {
    const double x = new_knots[static_cast<std::size_t>(j)];
    if (std::isnan(x)) continue;
    const double a = s.knots[static_cast<std::size_t>(j)], b = s.knots[static_cast<std::size_t>(j + 1)];
    if (!(a <= x && x <= b)) {
      throw InputError("refine_smooth: new knot " + std::to_string(x) + " is not in its interval [" +
                       std::to_string(a) + ", " + std::to_string(b) + "]");
    }
    // Multiplicity it creates.
    Index m = 1;  // knots are sorted: only runs at the interval ends can equal x
    for (Index i = j; i >= 0 && s.knots[static_cast<std::size_t>(i)] == x; --i) ++m;
    for (Index i = j + 1; i < k && s.knots[static_cast<std::size_t>(i)] == x; ++i) ++m;
    if (m > d) throw InputError("refine_smooth: new knot " + std::to_string(x) + " would have multiplicity above the degree");
  }
  const Layout L = make_layout(s, new_knots);
  RefineSmoothResult result;
  long long& count = result.affine_combinations;
  RowMatrix P = refine_stage(L, s, count);
  const Index n = P.rows(), dim = P.cols();
  std::vector<char> valid(static_cast<std::size_t>(n), 1);
  auto ok = [&](const std::vector<char>& v, Index q) { return q >= 0 && q < n && v[static_cast<std::size_t>(q)]; };
  const Eigen::RowVectorXd zero = Eigen::RowVectorXd::Zero(dim);
  if (variant == RefineSmoothVariant::levels) {
    RowMatrix next(n, dim);
    std::vector<char> next_valid(valid.size());
    for (int lambda = 2 + d % 2; lambda <= d; lambda += 2) {
      for (Index q = 0; q < n; ++q) {
        const Index p = L.first + q;
        const Action a = plan(L, p, lambda, ok(valid, q - 1), ok(valid, q), ok(valid, q + 1));
        next_valid[static_cast<std::size_t>(q)] = a.kind != Action::marker;
        if (a.kind == Action::marker) continue;
        count += apply(a, next.row(q), P.row(q > 0 ? q - 1 : q), P.row(q), P.row(q + 1 < n ? q + 1 : q));
      }
      P.swap(next);
      valid.swap(next_valid);
    }
  } else {
    Eigen::RowVectorXd saved(dim), current(dim);  // P^{λ-2}_{q-1}, overwritten in place
    for (int lambda = 2 + d % 2; lambda <= d; lambda += 2) {
      char saved_valid = 0;
      for (Index q = 0; q < n; ++q) {
        const Index p = L.first + q;
        const char self_valid = valid[static_cast<std::size_t>(q)];
        const Action a = plan(L, p, lambda, saved_valid, self_valid, ok(valid, q + 1));
        current = P.row(q);
        if (a.kind != Action::marker) {
          count += apply(a, P.row(q), saved, current, P.row(q + 1 < n ? q + 1 : q));
        }
        valid[static_cast<std::size_t>(q)] = a.kind != Action::marker;
        saved.swap(current);
        saved_valid = self_valid;
      }
    }
  }
  // §7: the points left are the control points whose arguments reach into [u_a, u_b].
  const Index a = L.y[static_cast<std::size_t>(d - 1)], b = L.y[static_cast<std::size_t>(k - d)];
  const Index expected = b - a + d;
  Index first = 0;
  while (first < n && !valid[static_cast<std::size_t>(first)]) ++first;
  Index got = 0;
  while (first + got < n && valid[static_cast<std::size_t>(first + got)]) ++got;
  if (got != expected) {
    throw NumericalError("refine_smooth: " + std::to_string(got) + " control points survived the end conditions, " +
                         std::to_string(expected) + " expected");
  }
  result.spline.degree = d;
  result.spline.knots.assign(L.u.begin() + (a - d + 1), L.u.begin() + (b + d));
  result.spline.control_points = P.middleRows(first, got);
  return result;
}

SplineCurve refine_smooth(const SplineCurve& curve, const std::vector<double>& xs, RefineSmoothVariant variant,
                          long long* count) {
  validate(curve);
  std::vector<double> rest = xs;
  std::sort(rest.begin(), rest.end());
  for (double x : rest) {
    if (!std::isfinite(x) || x < curve.domain_begin() || x > curve.domain_end()) {
      throw InputError("knot " + std::to_string(x) + " to insert is outside the domain [" +
                       std::to_string(curve.domain_begin()) + ", " + std::to_string(curve.domain_end()) + "]");
    }
  }
  SplineCurve cur = curve;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  while (!rest.empty()) {
    // One pass: the first pending knot of every non-empty interval [t_mu, t_{mu+1}) (the last one closed).
    const std::vector<Index> spans = domain_intervals(cur);
    PolarSpline polar = to_polar(cur);
    std::vector<double> per_interval(polar.knots.size() - 1, nan), later;
    std::size_t s = 0;
    for (double x : rest) {
      while (s + 1 < spans.size() && x >= cur.knots[static_cast<std::size_t>(spans[s]) + 1]) ++s;
      double& slot = per_interval[static_cast<std::size_t>(spans[s]) - 1];  // standard mu = paper mu - 1
      if (std::isnan(slot)) {
        slot = x;
      } else {
        later.push_back(x);
      }
    }
    RefineSmoothResult r = refine_smooth(polar, per_interval, variant);
    if (count) *count += r.affine_combinations;
    cur = to_standard(r.spline, cur.knots.front(), cur.knots.back());
    rest = std::move(later);
  }
  return cur;
}

Eigen::SparseMatrix<double> refine_smooth_matrix(int degree, const std::vector<double>& knots,
                                                 const std::vector<double>& xs, std::vector<double>& fine_knots) {
  SplineCurve c;
  c.degree = degree;
  c.knots = knots;
  const Index n = static_cast<Index>(knots.size()) - degree - 1;
  c.control_points = Eigen::MatrixXd::Identity(std::max<Index>(n, 0), std::max<Index>(n, 0));
  SplineCurve f = refine_smooth(c, xs);
  fine_knots = f.knots;
  return f.control_points.sparseView(0.0, 1e-300);
}

Refinement refine_smooth_tensor(const basis::Geometry& geometry, const std::vector<Index>& intervals_u,
                                const std::vector<Index>& intervals_v) {
  const auto* tensor = dynamic_cast<const basis::bspline::TensorSpace*>(&geometry.space());
  if (!tensor) {
    throw UnsupportedError("refine-and-smooth refinement of a '" + geometry.space().name() +
                           "' space is not implemented (tensor-product B-splines only)");
  }
  auto one = [](const basis::bspline::KnotVector& kv, const std::vector<Index>& intervals,
                basis::bspline::KnotVector& fine) {
    SplineCurve c;
    c.degree = kv.degree();
    c.knots = kv.knots();
    c.control_points.resize(kv.num_basis(), 1);
    std::vector<double> fine_knots;
    Eigen::SparseMatrix<double> r =
        refine_smooth_matrix(kv.degree(), kv.knots(), interval_midpoints(c, intervals), fine_knots);
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
  Eigen::MatrixXd cp = r * geometry.control_points();
  return {basis::Geometry(fine, std::move(cp)), std::move(r)};
}

}  // namespace iga::refine
