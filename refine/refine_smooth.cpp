#include "refine/refine_smooth.hpp"

#include <algorithm>
#include <cstdint>
#include <cmath>
#include <limits>
#include <string>

#include "core/error.hpp"
#include "refine/refine_smooth_stream.hpp"

namespace iga::refine {

using basis::bspline::SplineCurve;

namespace {

using RowMatrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;

using detail::ratio;

// The index sets and the polar labels of the points P^λ_i. Positions p are Z indices for odd d and the Z
// intervals (p, p+1) for even d.
struct Layout {
  int d = 0;
  Index nz = 0, k = 0;
  std::vector<double> u;
  std::vector<char> in_y;
  std::vector<std::int32_t> y;         // Z index of the original knot t_r
  std::vector<std::int32_t> count_le;  // number of Y indices <= j
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

Layout make_layout(int degree, const double* t, Index k, const std::vector<double>& new_knots) {
  if (k > (Index{1} << 29)) throw UnsupportedError("refine-smooth: more than 2^29 knots are not supported");
  Layout L;
  L.d = degree;
  L.k = k;
  L.u.reserve(static_cast<std::size_t>(2 * k));
  L.in_y.reserve(static_cast<std::size_t>(2 * k));
  L.y.reserve(static_cast<std::size_t>(k));
  for (Index j = 0; j < L.k; ++j) {
    L.y.push_back(static_cast<std::int32_t>(L.u.size()));
    L.u.push_back(t[j]);
    L.in_y.push_back(1);
    if (j + 1 < L.k && !std::isnan(new_knots[static_cast<std::size_t>(j)])) {
      L.u.push_back(new_knots[static_cast<std::size_t>(j)]);
      L.in_y.push_back(0);
    }
  }
  L.nz = static_cast<Index>(L.u.size());
  L.count_le.resize(L.u.size());
  Index c = 0;
  for (std::size_t j = 0; j < L.u.size(); ++j) L.count_le[j] = static_cast<std::int32_t>(c += L.in_y[j]);
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

[[gnu::always_inline]] inline Action plan(const Layout& L, Index p, int lambda, bool vprev, bool vself, bool vnext) {
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

// The input of one run in the paper's convention, without copies: k knots t[0..k-1], k - d + 1 control
// points (rows of cp, any number of columns).
struct Input {
  int d = 0;
  const double* t = nullptr;
  Index k = 0;
  const Eigen::MatrixXd* cp = nullptr;
};

// Refine-stage point at position p (P^0 for even d, P^1 for odd d): a copy of an input row, or (3) for a new
// knot of odd degree (Q_{p-1}, Q_{p+1} share d - 1 arguments).
int refine_point(const Layout& L, const Input& in, Index p, double* out) {
  const Index h = L.d / 2, rows = in.cp->rows(), dim = in.cp->cols();
  const double* src = in.cp->data();
  const Index r = L.count_le[static_cast<std::size_t>(p)] - 1;  // the original knot at or below p
  if (L.d % 2 == 0 || L.in_y[static_cast<std::size_t>(p)]) {
    const Index row = L.d % 2 == 0 ? r - h + 1 : r - h;
    for (Index c = 0; c < dim; ++c) out[c] = src[row + c * rows];
    return 0;
  }
  const Index qa = r - h, qb = r + 1 - h;
  const double ta = in.t[qa], td = in.t[qb + L.d - 1];
  const double w = ratio(L.at(p) - ta, td - ta);
  for (Index c = 0; c < dim; ++c) out[c] = (1.0 - w) * src[qa + c * rows] + w * src[qb + c * rows];
  return 1;
}

// The refine stage: P^0 (even d) or P^1 (odd d) on positions L.first..L.last (§3 variant).
RowMatrix refine_stage(const Layout& L, const Input& in, long long& count) {
  const Index n = L.last - L.first + 1;
  RowMatrix P(n, in.cp->cols());
  for (Index p = L.first; p <= L.last; ++p) count += refine_point(L, in, p, P.row(p - L.first).data());
  return P;
}

// §3: every level from a separate copy of the previous one.
RowMatrix run_levels(const Layout& L, const Input& in, std::vector<char>& valid, long long& count) {
  RowMatrix P = refine_stage(L, in, count);
  const Index n = P.rows(), dim = P.cols();
  valid.assign(static_cast<std::size_t>(n), 1);
  auto ok = [&](const std::vector<char>& v, Index q) { return q >= 0 && q < n && v[static_cast<std::size_t>(q)]; };
  RowMatrix next(n, dim);
  std::vector<char> next_valid(valid.size());
  for (int lambda = 2 + L.d % 2; lambda <= L.d; lambda += 2) {
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
  return P;
}

// Runs the algorithm; the surviving control points go to `out` (resized), the refined knots (paper convention)
// to out_knots[offset..] (out_knots resized to offset + count + offset).
void run(const Input& in, const std::vector<double>& new_knots, RefineSmoothVariant variant, long long& count,
         Eigen::MatrixXd& out, std::vector<double>& out_knots, std::size_t offset) {
  const int d = in.d;
  const Index k = in.k;
  if (d < 1 || k < d || in.cp->rows() != k - d + 1) {
    throw InputError("refine_smooth: " + std::to_string(k) + " knots of degree " + std::to_string(d) + " need " +
                     std::to_string(k - d + 1) + " control points, got " + std::to_string(in.cp->rows()));
  }
  if (static_cast<Index>(new_knots.size()) != k - 1) {
    throw InputError("refine_smooth: one entry per knot interval expected (" + std::to_string(k - 1) + "), got " +
                     std::to_string(new_knots.size()));
  }
  for (Index j = 0; j + 1 < k; ++j) {
    const double x = new_knots[static_cast<std::size_t>(j)];
    if (std::isnan(x)) continue;
    const double a = in.t[j], b = in.t[j + 1];
    if (!(a <= x && x <= b)) {
      throw InputError("refine_smooth: new knot " + std::to_string(x) + " is not in its interval [" +
                       std::to_string(a) + ", " + std::to_string(b) + "]");
    }
  }
  if (variant == RefineSmoothVariant::constant_memory) {
    detail::NewKnots knots;
    knots.per_interval = new_knots.data();
    detail::refine_smooth_stream(d, in.t, k, *in.cp, knots, count, out, out_knots, offset);
    return;
  }
  for (Index j = 0; j + 1 < k; ++j) {
    const double x = new_knots[static_cast<std::size_t>(j)];
    if (!std::isnan(x)) detail::check_new_knot(in.t, k, j, x, d);
  }
  const Layout L = make_layout(d, in.t, k, new_knots);
  // §7: the points left are the control points whose arguments reach into [u_a, u_b].
  const Index a = L.y[static_cast<std::size_t>(d - 1)], b = L.y[static_cast<std::size_t>(k - d)];
  const Index expected = b - a + d;
  std::vector<char> valid;
  const RowMatrix P = run_levels(L, in, valid, count);
  const Index n = P.rows();
  Index first = 0;
  while (first < n && !valid[static_cast<std::size_t>(first)]) ++first;
  Index got = 0;
  while (first + got < n && valid[static_cast<std::size_t>(first + got)]) ++got;
  if (got != expected) {
    throw NumericalError("refine_smooth: " + std::to_string(got) + " control points survived the end conditions, " +
                         std::to_string(expected) + " expected");
  }
  out = P.middleRows(first, got);
  const auto nk = static_cast<std::size_t>(b + d - (a - d + 1));
  out_knots.resize(offset + nk + offset);
  std::copy(L.u.begin() + (a - d + 1), L.u.begin() + (b + d), out_knots.begin() + static_cast<std::ptrdiff_t>(offset));
}

}  // namespace

RefineSmoothResult refine_smooth(const PolarSpline& s, const std::vector<double>& new_knots,
                                 RefineSmoothVariant variant) {
  RefineSmoothResult result;
  const Input in{s.degree, s.knots.data(), static_cast<Index>(s.knots.size()), &s.control_points};
  result.spline.degree = s.degree;
  run(in, new_knots, variant, result.affine_combinations, result.spline.control_points, result.spline.knots, 0);
  return result;
}

SplineCurve refine_smooth(const SplineCurve& curve, const std::vector<double>& xs, RefineSmoothVariant variant,
                          long long* count) {
  basis::bspline::validate(curve);
  if (xs.empty()) return curve;
  std::vector<double> rest;
  const bool sorted = std::is_sorted(xs.begin(), xs.end());
  if (!sorted) {
    rest = xs;
    std::sort(rest.begin(), rest.end());
  }
  const std::vector<double>& ordered = sorted ? xs : rest;
  for (double x : ordered) {
    if (!std::isfinite(x) || x < curve.domain_begin() || x > curve.domain_end()) {
      throw InputError("knot " + std::to_string(x) + " to insert is outside the domain [" +
                       std::to_string(curve.domain_begin()) + ", " + std::to_string(curve.domain_end()) + "]");
    }
  }
  const auto interval_empty = [](const SplineCurve& c, Index i) {
    return c.knots[static_cast<std::size_t>(i)] == c.knots[static_cast<std::size_t>(i) + 1];
  };
  if (variant == RefineSmoothVariant::constant_memory) {
    // One pass straight from the sorted knots when each has an interval of its own (no per-interval array).
    // The paper's knots are the standard ones without the first and the last: interval mu is paper mu - 1.
    Index last = curve.num_control_points() - 1;  // the last non-empty domain interval
    while (interval_empty(curve, last)) --last;
    detail::NewKnots knots;
    knots.sorted = ordered.data();
    knots.count = static_cast<Index>(ordered.size());
    knots.first = curve.degree - 1;
    knots.last = last - 1;
    SplineCurve next;
    next.degree = curve.degree;
    long long combinations = 0;
    if (detail::refine_smooth_stream(curve.degree, curve.knots.data() + 1, static_cast<Index>(curve.knots.size()) - 2,
                                     curve.control_points, knots, combinations, next.control_points, next.knots, 1)) {
      next.knots.front() = curve.knots.front();
      next.knots.back() = curve.knots.back();
      if (count) *count += combinations;
      return next;
    }
  }
  if (sorted) rest = xs;
  SplineCurve cur;
  const SplineCurve* from = &curve;  // the curve of the current pass (no copy for the first)
  const double nan = std::numeric_limits<double>::quiet_NaN();
  std::vector<double> per_interval, later;
  while (!rest.empty()) {
    const SplineCurve& cur_in = *from;
    // One pass: the first pending knot of every non-empty interval [t_mu, t_{mu+1}) (the last one closed).
    // The paper's knots are the standard ones without the first and the last: interval mu is paper mu - 1.
    const auto m = cur_in.knots.size();
    const Index n = cur_in.num_control_points();
    per_interval.assign(m - 3, nan);
    later.clear();
    const auto& t = cur_in.knots;
    auto empty = [&](Index i) { return interval_empty(cur_in, i); };
    Index last = n - 1;  // the last non-empty domain interval (the domain is not empty: validate())
    while (empty(last)) --last;
    Index mu = cur_in.degree;  // the non-empty domain interval [t_mu, t_{mu+1}) holding x (the last one closed)
    auto advance = [&](double x) {
      while (mu < last && (empty(mu) || x >= t[static_cast<std::size_t>(mu) + 1])) ++mu;
    };
    for (double x : rest) {
      advance(x);
      double& slot = per_interval[static_cast<std::size_t>(mu) - 1];
      if (std::isnan(slot)) {
        slot = x;
      } else {
        later.push_back(x);
      }
    }
    long long combinations = 0;
    SplineCurve next;
    next.degree = cur_in.degree;
    const Input in{cur_in.degree, cur_in.knots.data() + 1, static_cast<Index>(m) - 2, &cur_in.control_points};
    run(in, per_interval, variant, combinations, next.control_points, next.knots, 1);
    next.knots.front() = cur_in.knots.front();
    next.knots.back() = cur_in.knots.back();
    if (count) *count += combinations;
    cur = std::move(next);
    from = &cur;
    rest.swap(later);
  }
  return cur;
}

}  // namespace iga::refine
