#include "basis/bspline/spline_curve.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "basis/bspline/knot_insertion.hpp"
#include "basis/bspline/knot_vector.hpp"
#include "core/error.hpp"

namespace iga::basis::bspline {
namespace {

std::string num(double x) { return std::to_string(x); }

void check_inside(const SplineCurve& c, double x) {
  if (!std::isfinite(x) || x < c.domain_begin() || x > c.domain_end()) {
    throw InputError("knot " + num(x) + " to insert is outside the domain [" + num(c.domain_begin()) + ", " +
                     num(c.domain_end()) + "]");
  }
}

// xs itself if sorted, else a sorted copy in `storage`.
const std::vector<double>& sorted(const std::vector<double>& xs, std::vector<double>& storage) {
  if (std::is_sorted(xs.begin(), xs.end())) return xs;
  storage = xs;
  std::sort(storage.begin(), storage.end());
  return storage;
}

// InputError if inserting the sorted knots xs would give a knot a multiplicity above degree + 1 (one walk
// over the knots and xs together).
void check_multiplicities(const SplineCurve& c, const std::vector<double>& xs) {
  const auto& t = c.knots;
  std::size_t j = 0;
  for (std::size_t i = 0; i < xs.size();) {
    const double x = xs[i];
    std::size_t run = 0;
    while (i < xs.size() && xs[i] == x) ++i, ++run;
    while (j < t.size() && t[j] < x) ++j;
    for (std::size_t e = j; e < t.size() && t[e] == x; ++e) ++run;
    if (run > static_cast<std::size_t>(c.degree) + 1) {
      throw InputError("knot " + num(x) + " would have multiplicity " + std::to_string(run) + ", above degree + 1 = " +
                       std::to_string(c.degree + 1));
    }
  }
}

}  // namespace

void validate(const SplineCurve& c) {
  if (c.degree < 1) throw InputError("degree must be >= 1, got " + std::to_string(c.degree));
  const auto& t = c.knots;
  for (std::size_t i = 0; i < t.size(); ++i) {
    if (!std::isfinite(t[i])) throw InputError("knot " + std::to_string(i) + " is not a finite number");
    if (i > 0 && t[i] < t[i - 1]) {
      throw InputError("knots decrease at index " + std::to_string(i) + " (" + num(t[i - 1]) + " > " + num(t[i]) +
                       ")");
    }
  }
  std::size_t run = 1;
  for (std::size_t i = 1; i < t.size(); ++i) {
    run = t[i] == t[i - 1] ? run + 1 : 1;
    if (run > static_cast<std::size_t>(c.degree) + 1) {
      throw InputError("knot " + num(t[i]) + " has multiplicity above degree + 1 = " + std::to_string(c.degree + 1));
    }
  }
  const Index n = static_cast<Index>(t.size()) - c.degree - 1;
  if (n < 1) throw InputError("too few knots for degree " + std::to_string(c.degree));
  if (c.control_points.rows() != n) {
    throw InputError("wrong number of control points: " + std::to_string(c.control_points.rows()) + " given, " +
                     std::to_string(t.size()) + " knots and degree " + std::to_string(c.degree) + " need " +
                     std::to_string(n));
  }
  if (c.control_points.cols() < 1) throw InputError("control points have no coordinates");
  if (!c.control_points.allFinite()) throw InputError("a control point coordinate is not a finite number");
  if (!(c.domain_begin() < c.domain_end())) throw InputError("the domain [t_degree, t_n] is empty");
}

std::vector<Index> domain_intervals(const SplineCurve& c) { return domain_intervals(c.degree, c.knots); }

std::vector<double> interval_midpoints(const SplineCurve& c, const std::vector<Index>& intervals) {
  const std::vector<Index> spans = domain_intervals(c);
  std::vector<Index> chosen = intervals;
  if (chosen.empty()) {
    for (Index i = 0; i < static_cast<Index>(spans.size()); ++i) chosen.push_back(i);
  }
  std::vector<double> mids;
  for (std::size_t k = 0; k < chosen.size(); ++k) {
    const Index i = chosen[k];
    if (i < 0 || i >= static_cast<Index>(spans.size())) {
      throw InputError("interval " + std::to_string(i) + " does not exist (the domain has " +
                       std::to_string(spans.size()) + " non-empty intervals, 0-based)");
    }
    if (k > 0 && i <= chosen[k - 1]) throw InputError("intervals must be strictly increasing");
    const auto mu = static_cast<std::size_t>(spans[static_cast<std::size_t>(i)]);
    const double a = c.knots[mu], b = c.knots[mu + 1], mid = 0.5 * (a + b);
    if (!(a < mid && mid < b)) throw InputError(too_narrow_to_halve(a, b, "interval " + std::to_string(i)));
    mids.push_back(mid);
  }
  return mids;
}

SplineCurve insert_knot_boehm(const SplineCurve& c, double x) {
  validate(c);
  check_inside(c, x);
  check_multiplicities(c, {x});
  const int p = c.degree;
  const Index n = c.num_control_points();
  const Index k = find_span(c.degree, c.knots, x);
  const auto& t = c.knots;
  SplineCurve out;
  out.degree = p;
  out.knots = t;
  out.knots.insert(out.knots.begin() + k + 1, x);
  out.control_points.resize(n + 1, c.control_points.cols());
  for (Index i = 0; i <= k - p; ++i) out.control_points.row(i) = c.control_points.row(i);
  for (Index i = k - p + 1; i <= k; ++i) {
    const double ti = t[static_cast<std::size_t>(i)], tp = t[static_cast<std::size_t>(i + p)];
    const double a = (x - ti) / (tp - ti);  // t_i <= t_k < t_{k+1} <= t_{i+p}
    out.control_points.row(i) = (1.0 - a) * c.control_points.row(i - 1) + a * c.control_points.row(i);
  }
  for (Index i = k + 1; i <= n; ++i) out.control_points.row(i) = c.control_points.row(i - 1);
  return out;
}

SplineCurve insert_knots_boehm(const SplineCurve& c, const std::vector<double>& xs_in) {
  // All knots in one backward sweep (Boehm's rule applied knot by knot from the right end, in place, as in
  // Piegl and Tiller's knot-vector refinement): O((n + r) p) instead of a copy of the curve per knot.
  validate(c);
  if (xs_in.empty()) return c;
  for (double x : xs_in) check_inside(c, x);
  std::vector<double> storage;
  const std::vector<double>& xs = sorted(xs_in, storage);
  check_multiplicities(c, xs);
  const int p = c.degree;
  const auto& t = c.knots;
  const Index n = c.num_control_points();  // control points 0..n-1, knots 0..n+p
  const Index r = static_cast<Index>(xs.size());
  const Index a = find_span(c.degree, c.knots, xs.front());
  const Index b = find_span(c.degree, c.knots, xs.back()) + 1;
  SplineCurve out;
  out.degree = p;
  out.knots.assign(static_cast<std::size_t>(n + p + 1 + r), 0.0);
  out.control_points.resize(n + r, c.control_points.cols());
  auto& q = out.control_points;
  auto& tb = out.knots;
  for (Index i = 0; i <= a - p; ++i) q.row(i) = c.control_points.row(i);
  for (Index i = b - 1; i < n; ++i) q.row(i + r) = c.control_points.row(i);
  for (Index i = 0; i <= a; ++i) tb[static_cast<std::size_t>(i)] = t[static_cast<std::size_t>(i)];
  for (Index i = b + p; i <= n + p; ++i) tb[static_cast<std::size_t>(i + r)] = t[static_cast<std::size_t>(i)];
  Index i = b + p - 1, k = b + p + r - 1;
  for (Index j = r - 1; j >= 0; --j) {
    const double x = xs[static_cast<std::size_t>(j)];
    while (x <= t[static_cast<std::size_t>(i)] && i > a) {
      q.row(k - p - 1) = c.control_points.row(i - p - 1);
      tb[static_cast<std::size_t>(k)] = t[static_cast<std::size_t>(i)];
      --k;
      --i;
    }
    q.row(k - p - 1) = q.row(k - p);
    for (int l = 1; l <= p; ++l) {
      const Index ind = k - p + l;
      const double num = tb[static_cast<std::size_t>(k + l)] - x;
      if (num == 0.0) {
        q.row(ind - 1) = q.row(ind);
      } else {
        const double alpha = num / (tb[static_cast<std::size_t>(k + l)] - t[static_cast<std::size_t>(i - p + l)]);
        q.row(ind - 1) = alpha * q.row(ind - 1) + (1.0 - alpha) * q.row(ind);
      }
    }
    tb[static_cast<std::size_t>(k)] = x;
    --k;
  }
  return out;
}

SplineCurve insert_knots_oslo(const SplineCurve& c, const std::vector<double>& xs) {
  validate(c);
  for (double x : xs) check_inside(c, x);
  std::vector<double> storage;
  check_multiplicities(c, sorted(xs, storage));
  const int p = c.degree;
  SplineCurve out;
  out.degree = p;
  out.knots = c.knots;
  out.knots.insert(out.knots.end(), xs.begin(), xs.end());
  std::sort(out.knots.begin(), out.knots.end());
  out.control_points.resize(static_cast<Index>(out.knots.size()) - p - 1, c.control_points.cols());
  oslo_rows(p, c.knots, out.knots, [&](Index j, Index first, const Eigen::VectorXd& row) {
    out.control_points.row(j) = row.transpose() * c.control_points.middleRows(first, p + 1);
  });
  return out;
}

Eigen::RowVectorXd blossom(const SplineCurve& c, Index mu, const double* args) {
  const int p = c.degree;
  return blossom_row(c.knots.data() + (mu - p), p, args).transpose() * c.control_points.middleRows(mu - p, p + 1);
}

Eigen::VectorXd evaluate(const SplineCurve& c, double x) {
  const int p = c.degree;
  const Index mu = find_span(c.degree, c.knots, x);
  const Eigen::MatrixXd n = basis_functions(c.knots.data() + (mu - p), p, x, 0);
  return (n.row(0) * c.control_points.middleRows(mu - p, p + 1)).transpose();
}

}  // namespace iga::basis::bspline
