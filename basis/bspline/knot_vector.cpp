#include "basis/bspline/knot_vector.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "core/error.hpp"

namespace iga::basis::bspline {

KnotVector::KnotVector(int degree, std::vector<double> knots) : degree_(degree), knots_(std::move(knots)) {
  const int p = degree_;
  if (p < 1) throw InputError("knot vector: degree " + std::to_string(p) + " is not >= 1");
  const Index m = size();
  if (m < 2 * p + 2) {
    throw InputError("knot vector: " + std::to_string(m) + " knots; degree " + std::to_string(p) +
                     " needs at least " + std::to_string(2 * p + 2));
  }
  for (Index i = 0; i < m; ++i) {
    if (!std::isfinite(knots_[i])) throw InputError("knot vector: knot " + std::to_string(i) + " is not finite");
    if (i > 0 && knots_[i] < knots_[i - 1]) {
      std::ostringstream s;
      s << "knot vector: knots decrease at index " << i << " (" << knots_[i - 1] << " > " << knots_[i] << ")";
      throw InputError(s.str());
    }
  }
  for (int i = 1; i <= p; ++i) {
    if (knots_[i] != knots_[0] || knots_[m - 1 - i] != knots_[m - 1]) {
      throw InputError("knot vector: not open (clamped): the first and last " + std::to_string(p + 1) +
                       " knots must be equal");
    }
  }
  if (!(front() < back())) throw InputError("knot vector: empty domain");
  // Interior multiplicities.
  for (Index i = p + 1; i < num_basis();) {
    Index j = i;
    while (j + 1 < num_basis() && knots_[j + 1] == knots_[i]) ++j;
    const Index mult = j - i + 1;
    if (mult > p) {
      std::ostringstream s;
      s << "knot vector: interior knot " << knots_[i] << " has multiplicity " << mult << " > degree " << p;
      throw InputError(s.str());
    }
    i = j + 1;
  }
  spans_ = domain_intervals(p, knots_);
}

KnotVector KnotVector::uniform(int degree, Index intervals, double a, double b) {
  if (intervals < 1) throw InputError("knot vector: need at least one interval");
  std::vector<double> t;
  for (int i = 0; i < degree; ++i) t.push_back(a);
  for (Index i = 0; i <= intervals; ++i) {
    t.push_back(i == intervals ? b : a + (b - a) * static_cast<double>(i) / static_cast<double>(intervals));
  }
  for (int i = 0; i < degree; ++i) t.push_back(b);
  return KnotVector(degree, std::move(t));
}

std::vector<double> KnotVector::breakpoints() const {
  std::vector<double> b;
  for (Index mu : spans_) b.push_back(knots_[mu]);
  b.push_back(back());
  return b;
}

Index KnotVector::span(double x) const { return find_span(degree_, knots_, x); }

namespace {

// One degree of the Cox–de Boor recursion on the knot window w (w[k] = t_{span-p+k}), in place: b(0..k-1)
// holds N_{span-k+1+j, k-1}(x) on entry, b(0..k) holds N_{span-k+j, k}(x) on exit (from the top down, so each
// entry reads only entries not yet overwritten).
void cox_de_boor_step(const double* w, int p, int k, double x, double* b) {
  for (int j = k; j >= 0; --j) {
    const int i = p - k + j;  // window index of t_{span-k+j}
    double v = 0.0;
    if (j >= 1) {
      const double den = w[i + k] - w[i];
      if (den > 0) v += (x - w[i]) / den * b[j - 1];
    }
    if (j <= k - 1) {
      const double den = w[i + k + 1] - w[i + 1];
      if (den > 0) v += (w[i + k + 1] - x) / den * b[j];
    }
    b[j] = v;
  }
}

}  // namespace

std::vector<Index> domain_intervals(int p, std::span<const double> t) {
  std::vector<Index> spans;
  const Index n = static_cast<Index>(t.size()) - p - 1;
  for (Index mu = p; mu < n; ++mu) {
    if (t[static_cast<std::size_t>(mu)] < t[static_cast<std::size_t>(mu) + 1]) spans.push_back(mu);
  }
  return spans;
}

Index find_span(int p, std::span<const double> t, double x) {
  const auto n = t.size() - static_cast<std::size_t>(p) - 1;
  // The largest mu with t_mu <= x (x inside), with t_mu <= t_p (x before), or with t_mu < t_n (x after, or
  // not a number).
  if (!(x < t[n])) return static_cast<Index>(std::lower_bound(t.begin(), t.end(), t[n]) - t.begin()) - 1;
  const double y = std::max(x, t[static_cast<std::size_t>(p)]);
  return static_cast<Index>(std::upper_bound(t.begin(), t.end(), y) - t.begin()) - 1;
}

Eigen::MatrixXd basis_functions(const KnotVector& kv, Index span, double x, int derivatives) {
  return basis_functions(kv.knots().data() + (span - kv.degree()), kv.degree(), x, derivatives);
}

Eigen::MatrixXd basis_functions(const double* w, int p, double x, int derivatives) {
  // vals[q](j) = N_{span-q+j, q}(x), j = 0..q (Cox–de Boor, degree by degree).
  std::vector<Eigen::VectorXd> vals(p + 1);
  Eigen::VectorXd b = Eigen::VectorXd::Zero(p + 1);
  b(0) = 1.0;
  vals[0] = b.head(1);
  for (int q = 1; q <= p; ++q) {
    cox_de_boor_step(w, p, q, x, b.data());
    vals[q] = b.head(q + 1);
  }
  // D^r N_{i,q} = q (D^{r-1} N_{i,q-1}/(t_{i+q}-t_i) - D^{r-1} N_{i+1,q-1}/(t_{i+q+1}-t_{i+1})).
  auto derivative = [&](auto&& self, int r, int q) -> Eigen::VectorXd {
    if (r == 0) return vals[q];
    if (q == 0) return Eigen::VectorXd::Zero(1);
    const Eigen::VectorXd lo = self(self, r - 1, q - 1);
    Eigen::VectorXd hi = Eigen::VectorXd::Zero(q + 1);
    for (int j = 0; j <= q; ++j) {
      const int i = p - q + j;  // window index of t_{span-q+j}
      double v = 0.0;
      if (j >= 1) {
        const double den = w[i + q] - w[i];
        if (den > 0) v += lo(j - 1) / den;
      }
      if (j <= q - 1) {
        const double den = w[i + q + 1] - w[i + 1];
        if (den > 0) v -= lo(j) / den;
      }
      hi(j) = q * v;
    }
    return hi;
  };
  Eigen::MatrixXd out(derivatives + 1, p + 1);
  for (int r = 0; r <= derivatives; ++r) out.row(r) = derivative(derivative, r, p).transpose();
  return out;
}

Eigen::VectorXd blossom_row(const double* w, int p, const double* args) {
  // The recursion of basis_functions with argument args[k-1] at degree k.
  Eigen::VectorXd b = Eigen::VectorXd::Zero(p + 1);
  b(0) = 1.0;
  for (int k = 1; k <= p; ++k) cox_de_boor_step(w, p, k, args[k - 1], b.data());
  return b;
}

Eigen::VectorXd blossom_row(const KnotVector& kv, Index span, const double* args) {
  return blossom_row(kv.knots().data() + (span - kv.degree()), kv.degree(), args);
}

}  // namespace iga::basis::bspline
