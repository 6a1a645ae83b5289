#include "quadrature/spline_gauss/generator.hpp"

#include <Eigen/LU>
#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "core/error.hpp"
#include "quadrature/gauss_legendre.hpp"

namespace iga::quadrature::spline_gauss {

namespace {

using Real = long double;
using VecR = Eigen::Matrix<Real, Eigen::Dynamic, 1>;
using MatR = Eigen::Matrix<Real, Eigen::Dynamic, Eigen::Dynamic>;

// All degree-p B-splines (and optionally their derivatives) at x on knots t (size m + p + 1).
template <class T>
void eval_all(int p, const std::vector<T>& t, T x, std::vector<T>& val, std::vector<T>* der) {
  const int nk = static_cast<int>(t.size());
  const int m = nk - p - 1;
  // The interval: last mu with t_mu <= x < t_{mu+1}; x at (or beyond) the end uses the last non-empty one.
  int mu = -1;
  if (x >= t[static_cast<std::size_t>(nk - 1)]) {
    for (int k = nk - 2; k >= 0; --k) {
      if (t[static_cast<std::size_t>(k)] < t[static_cast<std::size_t>(k + 1)]) {
        mu = k;
        break;
      }
    }
  } else {
    for (int k = 0; k + 1 < nk; ++k) {
      if (t[static_cast<std::size_t>(k)] <= x && x < t[static_cast<std::size_t>(k + 1)]) mu = k;
    }
  }
  // Degree-0 functions on all nk - 1 intervals, raised degree by degree (O(nk p), fine for small spaces).
  std::vector<T> n(static_cast<std::size_t>(nk - 1), T(0));
  if (mu >= 0) n[static_cast<std::size_t>(mu)] = T(1);
  std::vector<T> lower;  // degree p-1 values for the derivative
  for (int d = 1; d <= p; ++d) {
    if (d == p) lower = n;
    std::vector<T> next(static_cast<std::size_t>(nk - 1 - d), T(0));
    for (int j = 0; j < nk - 1 - d; ++j) {
      const auto J = static_cast<std::size_t>(j);
      const T a = t[J + static_cast<std::size_t>(d)] - t[J];
      const T b = t[J + static_cast<std::size_t>(d) + 1] - t[J + 1];
      T s = 0;
      if (a > 0) s += (x - t[J]) / a * n[J];
      if (b > 0) s += (t[J + static_cast<std::size_t>(d) + 1] - x) / b * n[J + 1];
      next[J] = s;
    }
    n.swap(next);
  }
  val.assign(n.begin(), n.begin() + m);
  if (der) {
    der->assign(static_cast<std::size_t>(m), T(0));
    if (p >= 1) {
      for (int j = 0; j < m; ++j) {
        const auto J = static_cast<std::size_t>(j);
        const T a = t[J + static_cast<std::size_t>(p)] - t[J];
        const T b = t[J + static_cast<std::size_t>(p) + 1] - t[J + 1];
        T s = 0;
        if (a > 0) s += lower[J] / a;
        if (b > 0) s -= lower[J + 1] / b;
        (*der)[J] = static_cast<T>(p) * s;
      }
    }
  }
}

void check_knots(int p, const std::vector<double>& t) {
  const std::string where = "spline Gauss rule: ";
  if (p < 0 || p > 40) throw InputError(where + "degree must be 0..40, got " + std::to_string(p));
  if (t.size() < static_cast<std::size_t>(p + 2)) throw InputError(where + "need at least degree + 2 knots");
  for (std::size_t i = 0; i < t.size(); ++i) {
    if (!std::isfinite(t[i])) throw InputError(where + "knots must be finite");
    if (i > 0 && t[i] < t[i - 1]) throw InputError(where + "knots must be non-decreasing");
  }
  std::size_t run = 1;
  for (std::size_t i = 1; i < t.size(); ++i) {
    run = t[i] == t[i - 1] ? run + 1 : 1;
    if (run > static_cast<std::size_t>(p + 1)) throw InputError(where + "knot multiplicity exceeds degree + 1");
  }
  if (!(t.front() < t.back())) throw InputError(where + "empty domain");
}

// Nodes strictly increasing inside (a, b), weights positive.
bool feasible(const VecR& z, int q, Real a, Real b) {
  for (int i = 0; i < q; ++i) {
    if (!(z(i) > a && z(i) < b) || !(z(q + i) > 0)) return false;
    if (i > 0 && !(z(i) > z(i - 1))) return false;
  }
  return true;
}

struct System {
  int p, q;
  std::vector<Real> t;
  VecR target;  // exact moments
  // F(z) = sum_i w_i N_j(x_i) - mu, and its Jacobian.
  VecR residual(const VecR& z, const VecR& mu, MatR* jac) const {
    const int m = 2 * q;
    VecR f = -mu;
    if (jac) jac->setZero(m, m);
    std::vector<Real> v, d;
    for (int i = 0; i < q; ++i) {
      eval_all<Real>(p, t, z(i), v, jac ? &d : nullptr);
      for (int j = 0; j < m; ++j) {
        f(j) += z(q + i) * v[static_cast<std::size_t>(j)];
        if (jac) {
          (*jac)(j, i) = z(q + i) * d[static_cast<std::size_t>(j)];
          (*jac)(j, q + i) = v[static_cast<std::size_t>(j)];
        }
      }
    }
    return f;
  }
};

// Newton from z towards mu; true (and z updated) when converged to `tol` while staying feasible.
bool newton(const System& sys, VecR& z, const VecR& mu, Real tol, Real a, Real b, int max_iter) {
  VecR x = z;
  MatR jac;
  Real last = std::numeric_limits<Real>::infinity();
  for (int it = 0; it < max_iter; ++it) {
    const VecR f = sys.residual(x, mu, &jac);
    const Real r = f.cwiseAbs().maxCoeff();
    if (r <= tol) {
      // one more step to polish, kept only if it does not make things worse
      Eigen::PartialPivLU<MatR> lu(jac);
      VecR y = x - lu.solve(f);
      if (feasible(y, sys.q, a, b) && sys.residual(y, mu, nullptr).cwiseAbs().maxCoeff() <= r) x = y;
      z = x;
      return true;
    }
    if (it > 4 && r > last) return false;  // diverging
    last = r;
    Eigen::PartialPivLU<MatR> lu(jac);
    if (!(std::abs(lu.determinant()) > 0)) return false;
    const VecR dx = lu.solve(f);
    if (!dx.allFinite()) return false;
    x -= dx;
    if (!feasible(x, sys.q, a, b)) return false;
  }
  return false;
}

// The knots with one simple knot inserted at the midpoint of the longest interval (nearest the centre).
std::vector<double> superspace_knots(const std::vector<double>& t) {
  const double centre = 0.5 * (t.front() + t.back());
  std::size_t best = 0;
  double best_len = -1, best_dist = 0;
  for (std::size_t i = 0; i + 1 < t.size(); ++i) {
    const double len = t[i + 1] - t[i];
    const double dist = std::abs(0.5 * (t[i] + t[i + 1]) - centre);
    if (len > best_len * (1 + 1e-12) || (len >= best_len * (1 - 1e-12) && dist < best_dist)) {
      best = i;
      best_len = len;
      best_dist = dist;
    }
  }
  std::vector<double> out(t);
  out.insert(out.begin() + static_cast<std::ptrdiff_t>(best) + 1, 0.5 * (t[best] + t[best + 1]));
  return out;
}

}  // namespace

void bspline_values(int degree, const std::vector<double>& knots, double x, std::vector<double>& values,
                    std::vector<double>* derivatives) {
  eval_all<double>(degree, knots, x, values, derivatives);
}

std::vector<double> bspline_integrals(int degree, const std::vector<double>& knots) {
  const std::size_t m = knots.size() - static_cast<std::size_t>(degree) - 1;
  std::vector<double> out(m);
  for (std::size_t j = 0; j < m; ++j) out[j] = (knots[j + static_cast<std::size_t>(degree) + 1] - knots[j]) / (degree + 1);
  return out;
}

std::vector<double> open_knots(int degree, const std::vector<double>& breakpoints, const std::vector<int>& continuity) {
  if (breakpoints.size() < 2) throw InputError("spline Gauss rule: need at least two break points");
  if (continuity.size() + 2 != breakpoints.size()) {
    throw InputError("spline Gauss rule: need one continuity per inner break point");
  }
  std::vector<double> t(static_cast<std::size_t>(degree + 1), breakpoints.front());
  for (std::size_t k = 1; k + 1 < breakpoints.size(); ++k) {
    const int c = continuity[k - 1];
    if (c < -1 || c > degree - 1) throw InputError("spline Gauss rule: continuity must be -1..degree-1");
    if (!(breakpoints[k] > breakpoints[k - 1])) throw InputError("spline Gauss rule: break points must increase");
    t.insert(t.end(), static_cast<std::size_t>(degree - c), breakpoints[k]);
  }
  if (!(breakpoints.back() > breakpoints[breakpoints.size() - 2])) {
    throw InputError("spline Gauss rule: break points must increase");
  }
  t.insert(t.end(), static_cast<std::size_t>(degree + 1), breakpoints.back());
  return t;
}

Rule1D gaussian_rule(int degree, const std::vector<double>& knots_in) {
  check_knots(degree, knots_in);
  const int p = degree;
  // Polynomial space on an open knot vector: Gauss–Legendre with ceil((p+1)/2) points.
  if (static_cast<int>(knots_in.size()) == 2 * (p + 1) && knots_in[static_cast<std::size_t>(p)] == knots_in.front() &&
      knots_in[static_cast<std::size_t>(p + 1)] == knots_in.back()) {
    const double a = knots_in.front(), b = knots_in.back();
    Rule1D gl = gauss_legendre((p + 2) / 2);
    gl.points = (a + (b - a) * gl.points.array()).matrix();
    gl.weights *= (b - a);
    return gl;
  }
  std::vector<double> knots = knots_in;
  if ((knots.size() - static_cast<std::size_t>(p) - 1) % 2 == 1) knots = superspace_knots(knots);
  const int m = static_cast<int>(knots.size()) - p - 1;
  const int q = m / 2;
  const double a = knots.front(), b = knots.back();

  System sys;
  sys.p = p;
  sys.q = q;
  sys.t.assign(knots.begin(), knots.end());
  const std::vector<double> ints = bspline_integrals(p, knots);
  sys.target.resize(m);
  for (int j = 0; j < m; ++j) sys.target(j) = ints[static_cast<std::size_t>(j)];

  // Start rule: Greville pairs.
  VecR z(2 * q);
  for (int i = 0; i < q; ++i) {
    Real xi[2];
    for (int s = 0; s < 2; ++s) {
      const int j = 2 * i + s;
      Real g = 0;
      for (int k = 1; k <= std::max(p, 1); ++k) g += sys.t[static_cast<std::size_t>(std::min(j + k, m + p))];
      xi[s] = g / std::max(p, 1);
    }
    z(i) = 0.5L * (xi[0] + xi[1]);
    z(q + i) = sys.target(2 * i) + sys.target(2 * i + 1);
  }
  const Real la = a, lb = b;
  if (!feasible(z, q, la, lb)) throw NumericalError("spline Gauss rule: degenerate start rule (repeated Greville abscissae)");
  const VecR mu0 = sys.residual(z, VecR::Zero(m), nullptr);  // moments of the start rule

  const Real scale = static_cast<Real>(b - a);
  const Real step_tol = 1e-12L * scale;
  Real s = 0, ds = 1;
  while (s < 1) {
    const Real s1 = std::min<Real>(1, s + ds);
    const VecR mu = (1 - s1) * mu0 + s1 * sys.target;
    VecR trial = z;
    if (newton(sys, trial, mu, step_tol, la, lb, 30)) {
      z = trial;
      s = s1;
      ds = std::min<Real>(1, 2 * ds);
    } else {
      ds /= 2;
      if (ds < 1e-8L) throw NumericalError("spline Gauss rule: homotopy stalled at s = " + std::to_string(static_cast<double>(s)));
    }
  }
  if (!newton(sys, z, sys.target, 1e-17L * scale, la, lb, 20)) {
    // Long double may stall just above 1e-17; accept the converged homotopy end point after checking below.
  }

  Rule1D out;
  out.points.resize(q);
  out.weights.resize(q);
  for (int i = 0; i < q; ++i) {
    out.points(i) = static_cast<double>(z(i));
    out.weights(i) = static_cast<double>(z(q + i));
  }
  const double res = moment_residual(out, p, knots);
  for (int i = 0; i < q; ++i) {
    if (!(out.points(i) > a && out.points(i) < b && out.weights(i) > 0 && (i == 0 || out.points(i) > out.points(i - 1)))) {
      throw NumericalError("spline Gauss rule: infeasible rule after rounding");
    }
  }
  if (!(res <= 1e-14 * (b - a))) {
    throw NumericalError("spline Gauss rule: moment residual " + std::to_string(res) + " above tolerance");
  }
  return out;
}

Rule1D gaussian_rule(int degree, const std::vector<double>& breakpoints, const std::vector<int>& continuity) {
  return gaussian_rule(degree, open_knots(degree, breakpoints, continuity));
}

double moment_residual(const Rule1D& rule, int degree, const std::vector<double>& knots) {
  const std::vector<double> ints = bspline_integrals(degree, knots);
  std::vector<double> acc(ints.size(), 0.0), v;
  for (Eigen::Index i = 0; i < rule.size(); ++i) {
    bspline_values(degree, knots, rule.points(i), v);
    for (std::size_t j = 0; j < ints.size(); ++j) acc[j] += rule.weights(i) * v[j];
  }
  double r = 0;
  for (std::size_t j = 0; j < ints.size(); ++j) r = std::max(r, std::abs(acc[j] - ints[j]));
  return r;
}

}  // namespace iga::quadrature::spline_gauss
