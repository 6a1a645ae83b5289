#include "basis/bspline/knot_insertion.hpp"

#include <algorithm>
#include <cstdio>
#include <string>

#include "core/error.hpp"

namespace iga::basis::bspline {

void oslo_rows(int p, std::span<const double> t, std::span<const double> tau, const OsloRowSink& row) {
  const auto at = [](std::span<const double> k, Index i) { return k[static_cast<std::size_t>(i)]; };
  const Index nf = static_cast<Index>(tau.size()) - p - 1;
  const std::vector<Index> spans = domain_intervals(p, t);
  std::vector<double> reversed(static_cast<std::size_t>(p));
  std::size_t s = 0;  // the coarse piece of tau_j (non-decreasing in j)
  for (Index j = 0; j < nf; ++j) {
    const double* args = tau.data() + j + 1;
    Index mu;
    if (at(tau, j) >= at(t, p)) {
      // t_mu <= tau_j < t_{mu+1} (the last piece for tau_j at the domain end): at degree k the recursion takes
      // tau_{j+k} <= t_{mu+k} (the coarse knots after tau_j are fine knots), so every factor is in [0, 1] or
      // multiplies an exact zero (a coefficient (t_{mu+1} - tau_{j+1}) = 0 when tau_{j+2} passes t_{mu+1}).
      while (s + 1 < spans.size() && at(tau, j) >= at(t, spans[s] + 1)) ++s;
      mu = spans[s];
    } else {
      // tau_j before the domain (unclamped knots: j < p), where no piece has a knot window: the mirror image,
      // t_mu < tau_{j+p+1} <= t_{mu+1}, with the arguments from the right.
      const auto past = std::lower_bound(t.begin(), t.end(), at(tau, j + p + 1));
      mu = std::clamp(static_cast<Index>(past - t.begin()) - 1, spans.front(), spans.back());
      std::reverse_copy(args, args + p, reversed.begin());
      args = reversed.data();
    }
    row(j, mu - p, blossom_row(t.data() + (mu - p), p, args));
  }
}

Eigen::SparseMatrix<double> oslo_matrix(int p, std::span<const double> coarse, std::span<const double> fine) {
  const Index nf = static_cast<Index>(fine.size()) - p - 1;
  std::vector<Eigen::Triplet<double>> entries;
  entries.reserve(static_cast<std::size_t>(nf * (p + 1)));
  oslo_rows(p, coarse, fine, [&](Index j, Index first, const Eigen::VectorXd& values) {
    for (int i = 0; i <= p; ++i) {
      if (values(i) != 0.0) entries.emplace_back(j, first + i, values(i));
    }
  });
  Eigen::SparseMatrix<double> r(nf, static_cast<Index>(coarse.size()) - p - 1);
  r.setFromTriplets(entries.begin(), entries.end());
  return r;
}

Eigen::SparseMatrix<double> refinement_matrix(const KnotVector& coarse, const KnotVector& fine) {
  const int p = coarse.degree();
  if (fine.degree() != p) throw InputError("knot insertion: the fine knot vector has another degree");
  if (fine.front() != coarse.front() || fine.back() != coarse.back()) {
    throw InputError("knot insertion: the knot vectors have different domains");
  }
  if (!std::includes(fine.knots().begin(), fine.knots().end(), coarse.knots().begin(), coarse.knots().end())) {
    throw InputError("knot insertion: the fine knot vector does not contain every coarse knot");
  }
  return oslo_matrix(p, coarse.knots(), fine.knots());
}

std::string too_narrow_to_halve(double a, double b, const std::string& which) {
  char text[96];
  std::snprintf(text, sizeof text, " [%.17g, %.17g]", a, b);
  return which + text + " is too narrow to halve in double precision: its midpoint rounds to an end, so halving " +
         "it would repeat a knot instead";
}

KnotVector insert_midpoints(const KnotVector& kv, const std::string& which) {
  std::vector<double> t;
  t.reserve(kv.knots().size() + kv.interval_spans().size());
  const Index m = kv.size();
  Index interval = 0;
  for (Index i = 0; i < m; ++i) {
    t.push_back(kv[i]);
    if (i + 1 < m && kv[i] < kv[i + 1] && i >= kv.degree() && i < kv.num_basis()) {
      const double mid = 0.5 * (kv[i] + kv[i + 1]);
      if (!(kv[i] < mid && mid < kv[i + 1])) {
        throw InputError(too_narrow_to_halve(kv[i], kv[i + 1], which + " " + std::to_string(interval)));
      }
      t.push_back(mid);
      ++interval;
    }
  }
  return KnotVector(kv.degree(), std::move(t));
}

KnotVector split_intervals(const KnotVector& kv, int parts, const std::string& which) {
  if (parts < 1) throw InputError(which + ": cannot split a knot interval into " + std::to_string(parts) + " parts");
  std::vector<double> t;
  const Index m = kv.size();
  Index interval = 0;
  for (Index i = 0; i < m; ++i) {
    t.push_back(kv[i]);
    if (i + 1 < m && kv[i] < kv[i + 1] && i >= kv.degree() && i < kv.num_basis()) {
      double last = kv[i];
      for (int k = 1; k < parts; ++k) {
        const double x = kv[i] + (kv[i + 1] - kv[i]) * k / parts;
        if (!(last < x && x < kv[i + 1])) {
          throw InputError(which + " " + std::to_string(interval) + " [" + std::to_string(kv[i]) + ", " +
                           std::to_string(kv[i + 1]) + "] is too narrow to split into " + std::to_string(parts) +
                           " distinct parts in double precision");
        }
        t.push_back(x);
        last = x;
      }
      ++interval;
    }
  }
  return KnotVector(kv.degree(), std::move(t));
}

}  // namespace iga::basis::bspline
