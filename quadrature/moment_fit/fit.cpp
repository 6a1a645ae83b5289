#include "quadrature/moment_fit/fit.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <mutex>
#include <random>
#include <utility>

#include <Eigen/Dense>
#include <nlopt.hpp>

#include "basis/catmull_clark/stam.hpp"
#include "core/error.hpp"
#include "quadrature/exact/irregular_integrals.hpp"

namespace iga::quadrature::moment_fit {

std::string to_string(Space space) {
  switch (space) {
    case Space::Phi: return "phi";
    case Space::Mass: return "mass";
    case Space::Stiffness: return "stiffness";
  }
  return "?";
}

Space parse_space(const std::string& text) {
  if (text == "phi") return Space::Phi;
  if (text == "mass") return Space::Mass;
  if (text == "stiffness") return Space::Stiffness;
  throw InputError("moment fit: unknown space '" + text + "' (known: phi, mass, stiffness)");
}

int num_functions(int valence, Space space) {
  const int p = 2 * valence + 8;
  return space == Space::Phi ? p : p * (p + 1) / 2;
}

void evaluate_functions(int valence, Space space, const Eigen::Matrix2Xd& pts, Eigen::MatrixXd& f,
                        Eigen::MatrixXd* fu, Eigen::MatrixXd* fv) {
  const auto& stam = basis::catmull_clark::stam_evaluator(valence);
  const bool grad = fu != nullptr && fv != nullptr;
  const int derivatives = space == Space::Stiffness ? (grad ? 2 : 1) : (grad ? 1 : 0);
  basis::BasisValues bv;
  stam.evaluate(pts, derivatives, bv);
  if (space == Space::Phi) {
    f = bv.value;
    if (grad) {
      *fu = bv.du;
      *fv = bv.dv;
    }
    return;
  }
  const int p = stam.num_points();
  const Eigen::Index q = pts.cols();
  f.resize(num_functions(valence, space), q);
  if (grad) {
    fu->resize(f.rows(), q);
    fv->resize(f.rows(), q);
  }
  Eigen::Index m = 0;
  for (int a = 0; a < p; ++a) {
    for (int b = a; b < p; ++b, ++m) {
      if (space == Space::Mass) {
        f.row(m) = bv.value.row(a).cwiseProduct(bv.value.row(b));
        if (grad) {
          fu->row(m) = bv.du.row(a).cwiseProduct(bv.value.row(b)) + bv.value.row(a).cwiseProduct(bv.du.row(b));
          fv->row(m) = bv.dv.row(a).cwiseProduct(bv.value.row(b)) + bv.value.row(a).cwiseProduct(bv.dv.row(b));
        }
      } else {
        f.row(m) = bv.du.row(a).cwiseProduct(bv.du.row(b)) + bv.dv.row(a).cwiseProduct(bv.dv.row(b));
        if (grad) {
          fu->row(m) = bv.duu.row(a).cwiseProduct(bv.du.row(b)) + bv.du.row(a).cwiseProduct(bv.duu.row(b)) +
                       bv.duv.row(a).cwiseProduct(bv.dv.row(b)) + bv.dv.row(a).cwiseProduct(bv.duv.row(b));
          fv->row(m) = bv.duv.row(a).cwiseProduct(bv.du.row(b)) + bv.du.row(a).cwiseProduct(bv.duv.row(b)) +
                       bv.dvv.row(a).cwiseProduct(bv.dv.row(b)) + bv.dv.row(a).cwiseProduct(bv.dvv.row(b));
        }
      }
    }
  }
}

const Eigen::VectorXd& moments(int valence, Space space) {
  static std::mutex mutex;
  static std::map<std::pair<int, int>, Eigen::VectorXd> cache;
  const std::lock_guard<std::mutex> lock(mutex);
  auto& b = cache[{valence, static_cast<int>(space)}];
  if (b.size() == 0) {
    const auto& exact = exact::irregular_integrals(valence);
    if (space == Space::Phi) {
      b = exact.phi;
    } else {
      const Eigen::MatrixXd g = space == Space::Mass ? exact.phi_phi : Eigen::MatrixXd(exact.d[0][0] + exact.d[1][1]);
      const int p = 2 * valence + 8;
      b.resize(num_functions(valence, space));
      Eigen::Index m = 0;
      for (int a = 0; a < p; ++a) {
        for (int c = a; c < p; ++c, ++m) b(m) = g(a, c);
      }
    }
  }
  return b;
}

double residual(int valence, Space space, const Rule& rule) {
  Eigen::MatrixXd f;
  evaluate_functions(valence, space, rule.points, f);
  return (f * rule.weights - moments(valence, space)).norm();
}

int FitResult::successes() const {
  return static_cast<int>(std::count_if(attempts.begin(), attempts.end(), [](const Attempt& a) { return a.converged; }));
}

namespace {

// U^T for Problem::projection: left singular vectors of the function values (functions × 4·functions points,
// a quarter uniform in [0,1]², the others in [0, 2^-k]², k = 1..12, fixed seed) with σ > 1e-14 σ_1. Cached.
const Eigen::MatrixXd& range_projection(int valence, Space space) {
  static std::mutex mutex;
  static std::map<std::pair<int, int>, Eigen::MatrixXd> cache;
  const std::lock_guard<std::mutex> lock(mutex);
  auto& p = cache[{valence, static_cast<int>(space)}];
  if (p.size() == 0) {
    const int m = num_functions(valence, space), count = 4 * m;
    std::mt19937 gen(12345);
    Eigen::Matrix2Xd pts(2, count);
    for (int i = 0; i < count; ++i) {
      const double scale = i < count / 4 ? 1.0 : std::ldexp(1.0, -(1 + i % 12));
      const double u = (static_cast<double>(gen()) + 0.5) / 4294967296.0;
      const double v = (static_cast<double>(gen()) + 0.5) / 4294967296.0;
      pts.col(i) << scale * u, scale * v;
    }
    Eigen::MatrixXd f;
    evaluate_functions(valence, space, pts, f);
    const Eigen::BDCSVD<Eigen::MatrixXd> svd(f, Eigen::ComputeThinU);
    const Eigen::VectorXd& sv = svd.singularValues();
    Eigen::Index rank = 0;
    while (rank < sv.size() && sv(rank) > 1e-14 * sv(0)) ++rank;
    p = svd.matrixU().leftCols(rank).transpose();
  }
  return p;
}

// The unknowns x: `free` points as (u, v, w), then `pairs` as (u, v, w) giving (u,v) and (v,u) with weight w
// each, then `diagonal` points as (t, w) giving (t, t).
struct Problem {
  int valence = 0;
  Space space = Space::Phi;
  int free = 0, pairs = 0, diagonal = 0;
  double lower = 1e-6;
  const Eigen::VectorXd* b = nullptr;
  /// Mass and stiffness: U^T (rank × functions), U an orthonormal basis of the span of the function values
  /// (the functions are linearly dependent); residual and Jacobian are taken in that basis, so that the
  /// Levenberg–Marquardt normal matrix J J^T is not singular. nullptr: the residual itself.
  const Eigen::MatrixXd* projection = nullptr;
  int evaluations = 0;

  int dimension() const { return 3 * free + 3 * pairs + 2 * diagonal; }
  int points() const { return free + 2 * pairs + diagonal; }

  Rule expand(const Eigen::VectorXd& x) const {
    Rule r;
    r.points.resize(2, points());
    r.weights.resize(points());
    int j = 0, k = 0;
    for (int i = 0; i < free; ++i, k += 3, ++j) {
      r.points.col(j) << x(k), x(k + 1);
      r.weights(j) = x(k + 2);
    }
    for (int i = 0; i < pairs; ++i, k += 3, j += 2) {
      r.points.col(j) << x(k), x(k + 1);
      r.points.col(j + 1) << x(k + 1), x(k);
      r.weights(j) = r.weights(j + 1) = x(k + 2);
    }
    for (int i = 0; i < diagonal; ++i, k += 2, ++j) {
      r.points.col(j) << x(k), x(k);
      r.weights(j) = x(k + 1);
    }
    return r;
  }

  // Residual r = Φ w − b and, when jac is non-null, dr/dx.
  Eigen::VectorXd evaluate(const Eigen::VectorXd& x, Eigen::MatrixXd* jac) {
    ++evaluations;
    const Rule r = expand(x);
    Eigen::MatrixXd f, fu, fv;
    if (jac != nullptr) {
      evaluate_functions(valence, space, r.points, f, &fu, &fv);
    } else {
      evaluate_functions(valence, space, r.points, f);
    }
    if (jac != nullptr) {
      jac->resize(f.rows(), dimension());
      int j = 0, k = 0;
      for (int i = 0; i < free; ++i, k += 3, ++j) {
        jac->col(k) = x(k + 2) * fu.col(j);
        jac->col(k + 1) = x(k + 2) * fv.col(j);
        jac->col(k + 2) = f.col(j);
      }
      for (int i = 0; i < pairs; ++i, k += 3, j += 2) {
        jac->col(k) = x(k + 2) * (fu.col(j) + fv.col(j + 1));
        jac->col(k + 1) = x(k + 2) * (fv.col(j) + fu.col(j + 1));
        jac->col(k + 2) = f.col(j) + f.col(j + 1);
      }
      for (int i = 0; i < diagonal; ++i, k += 2, ++j) {
        jac->col(k) = x(k + 1) * (fu.col(j) + fv.col(j));
        jac->col(k + 1) = f.col(j);
      }
    }
    if (projection != nullptr) {
      if (jac != nullptr) *jac = (*projection) * (*jac);
      return (*projection) * (f * r.weights - *b);
    }
    return f * r.weights - *b;
  }

  void bounds(Eigen::VectorXd& lo, Eigen::VectorXd& hi) const {
    lo.resize(dimension());
    hi.resize(dimension());
    int k = 0;
    for (int i = 0; i < free + pairs; ++i, k += 3) {
      lo.segment<3>(k) << lower, lower, 0.0;
      hi.segment<3>(k) << 1.0, 1.0, 1.0;
    }
    for (int i = 0; i < diagonal; ++i, k += 2) {
      lo.segment<2>(k) << lower, 0.0;
      hi.segment<2>(k) << 1.0, 1.0;
    }
  }
};

// Uniform in [0, 1) from 32 random bits (the same sequence on every platform, unlike the distributions).
double uniform(std::mt19937& gen) { return (static_cast<double>(gen()) + 0.5) / 4294967296.0; }

Eigen::VectorXd random_start(const Problem& pb, std::mt19937& gen) {
  Eigen::VectorXd x(pb.dimension());
  double total = 0.0;
  int k = 0;
  for (int i = 0; i < pb.free + pb.pairs; ++i, k += 3) {
    x(k) = pb.lower + (1.0 - pb.lower) * uniform(gen);
    x(k + 1) = pb.lower + (1.0 - pb.lower) * uniform(gen);
    x(k + 2) = 0.5 + uniform(gen);
    total += (i < pb.free ? 1.0 : 2.0) * x(k + 2);
  }
  for (int i = 0; i < pb.diagonal; ++i, k += 2) {
    x(k) = pb.lower + (1.0 - pb.lower) * uniform(gen);
    x(k + 1) = 0.5 + uniform(gen);
    total += x(k + 1);
  }
  // Weights sum to the area 1 (the splines are a partition of unity).
  k = 0;
  for (int i = 0; i < pb.free + pb.pairs; ++i, k += 3) x(k + 2) /= total;
  for (int i = 0; i < pb.diagonal; ++i, k += 2) x(k + 1) /= total;
  return x;
}

nlopt::algorithm parse_algorithm(const std::string& name) {
  if (name == "LD_LBFGS") return nlopt::LD_LBFGS;
  if (name == "LD_SLSQP") return nlopt::LD_SLSQP;
  if (name == "LD_MMA") return nlopt::LD_MMA;
  if (name == "LN_BOBYQA") return nlopt::LN_BOBYQA;
  throw InputError("moment fit: unknown algorithm '" + name + "' (known: LD_LBFGS, LD_SLSQP, LD_MMA, LN_BOBYQA, none)");
}

double nlopt_objective(unsigned dim, const double* x, double* grad, void* data) {
  auto& pb = *static_cast<Problem*>(data);
  const Eigen::Map<const Eigen::VectorXd> xv(x, dim);
  Eigen::MatrixXd jac;
  const Eigen::VectorXd r = pb.evaluate(xv, grad != nullptr ? &jac : nullptr);
  if (grad != nullptr) Eigen::Map<Eigen::VectorXd>(grad, dim) = 2.0 * jac.transpose() * r;
  return r.squaredNorm();
}

bool past(const std::optional<std::chrono::steady_clock::time_point>& deadline) {
  return deadline && std::chrono::steady_clock::now() >= *deadline;
}

void run_nlopt(Problem& pb, const std::string& algorithm, int max_evaluations, double tolerance,
               const Eigen::VectorXd& lo, const Eigen::VectorXd& hi, Eigen::VectorXd& x,
               const std::optional<std::chrono::steady_clock::time_point>& deadline) {
  nlopt::opt opt(parse_algorithm(algorithm), static_cast<unsigned>(pb.dimension()));
  opt.set_lower_bounds(std::vector<double>(lo.data(), lo.data() + lo.size()));
  opt.set_upper_bounds(std::vector<double>(hi.data(), hi.data() + hi.size()));
  opt.set_min_objective(nlopt_objective, &pb);
  opt.set_stopval(0.01 * tolerance * tolerance);
  opt.set_ftol_abs(1e-32);
  opt.set_xtol_rel(1e-15);
  opt.set_maxeval(max_evaluations);
  if (deadline) {
    const double left = std::chrono::duration<double>(*deadline - std::chrono::steady_clock::now()).count();
    opt.set_maxtime(std::max(left, 1e-3));
  }
  std::vector<double> xs(x.data(), x.data() + x.size());
  double value = 0.0;
  try {
    opt.optimize(xs, value);
  } catch (const std::exception&) {
    // roundoff_limited and the like: keep the best point NLopt reached (xs holds it).
  }
  for (Eigen::Index i = 0; i < x.size(); ++i) {
    if (std::isfinite(xs[static_cast<std::size_t>(i)])) x(i) = std::clamp(xs[static_cast<std::size_t>(i)], lo(i), hi(i));
  }
}

// Bound-constrained Levenberg–Marquardt with damping mu = lambda ||r|| (quadratic convergence also for the
// underdetermined systems, where J^T J is singular): step -J^T (J J^T + mu I)^{-1} r, or the equal
// -(J^T J + mu I)^{-1} J^T r when J has more rows than columns, over the free variables only; a variable is
// held fixed while it sits on a bound and the descent direction -J^T r points outward (projected LM: without
// this a clamped coordinate blocks every step and the iteration stalls), and the trial point is clamped to
// the bounds.
void polish(Problem& pb, int iterations, const Eigen::VectorXd& lo, const Eigen::VectorXd& hi, Eigen::VectorXd& x) {
  Eigen::MatrixXd jac;
  Eigen::VectorXd r = pb.evaluate(x, &jac);
  double norm = r.norm();
  double lambda = 1e-3;
  for (int it = 0; it < iterations && norm > 1e-16; ++it) {
    const double mu = lambda * norm;
    const Eigen::VectorXd g = jac.transpose() * r;
    std::vector<Eigen::Index> free;
    for (Eigen::Index i = 0; i < x.size(); ++i) {
      const bool at_lo = x(i) <= lo(i) && g(i) > 0.0, at_hi = x(i) >= hi(i) && g(i) < 0.0;
      if (!at_lo && !at_hi) free.push_back(i);
    }
    if (free.empty()) break;
    Eigen::MatrixXd jf(jac.rows(), static_cast<Eigen::Index>(free.size()));
    for (std::size_t k = 0; k < free.size(); ++k) jf.col(static_cast<Eigen::Index>(k)) = jac.col(free[k]);
    Eigen::VectorXd sf;
    if (jf.rows() <= jf.cols()) {
      Eigen::MatrixXd a = jf * jf.transpose();
      a.diagonal().array() += mu;
      sf = -jf.transpose() * a.ldlt().solve(r);
    } else {
      Eigen::MatrixXd a = jf.transpose() * jf;
      a.diagonal().array() += mu;
      sf = -a.ldlt().solve(jf.transpose() * r);
    }
    Eigen::VectorXd step = Eigen::VectorXd::Zero(x.size());
    for (std::size_t k = 0; k < free.size(); ++k) step(free[k]) = sf(static_cast<Eigen::Index>(k));
    const Eigen::VectorXd trial = (x + step).cwiseMax(lo).cwiseMin(hi);
    if (!trial.allFinite()) {
      lambda *= 10.0;
      continue;
    }
    const Eigen::VectorXd rt = pb.evaluate(trial, nullptr);
    if (rt.norm() < norm) {
      x = trial;
      r = pb.evaluate(x, &jac);
      norm = r.norm();
      lambda = std::max(lambda / 5.0, 1e-12);
    } else {
      lambda *= 8.0;
      if (lambda > 1e16) break;
    }
  }
}

}  // namespace

FitResult fit_rule(int valence, int points, const FitOptions& options) {
  if (valence < 3 || valence > 16) throw InputError("moment fit: valence must be 3..16, got " + std::to_string(valence));
  if (points < 1) throw InputError("moment fit: need at least one point, got " + std::to_string(points));
  if (options.attempts < 1) throw InputError("moment fit: attempts must be >= 1");
  if (!(options.lower_bound > 0.0 && options.lower_bound < 1.0)) throw InputError("moment fit: lower_bound must be in (0, 1)");
  Problem pb;
  pb.valence = valence;
  pb.space = options.space;
  pb.lower = options.lower_bound;
  pb.b = &moments(valence, options.space);
  FitResult result;
  result.valence = valence;
  result.points = points;
  result.space = options.space;
  result.symmetric = options.symmetric;
  result.seed = options.seed;
  if (options.symmetric) {
    const int d = options.diagonal_points < 0 ? points % 2 : options.diagonal_points;
    if (d > points || (points - d) % 2 != 0) {
      throw InputError("moment fit: a symmetric rule of " + std::to_string(points) + " points cannot have " +
                       std::to_string(d) + " diagonal points");
    }
    pb.pairs = (points - d) / 2;
    pb.diagonal = d;
    result.diagonal_points = d;
  } else {
    pb.free = points;
  }
  if (options.algorithm != "none") parse_algorithm(options.algorithm);  // InputError before any work
  Eigen::VectorXd lo, hi;
  pb.bounds(lo, hi);
  double best = std::numeric_limits<double>::infinity();
  for (int attempt = 0; attempt < options.attempts; ++attempt) {
    if (attempt > 0 && past(options.deadline)) break;
    std::mt19937 gen(options.seed + static_cast<unsigned>(attempt));
    Eigen::VectorXd x = random_start(pb, gen);
    pb.evaluations = 0;
    if (options.algorithm != "none") run_nlopt(pb, options.algorithm, options.max_evaluations, options.tolerance, lo, hi, x, options.deadline);
    polish(pb, options.polish_iterations, lo, hi, x);
    const Rule rule = pb.expand(x);
    Attempt a;
    a.residual = residual(valence, options.space, rule);
    a.min_weight = rule.weights.minCoeff();
    a.evaluations = pb.evaluations;
    a.converged = a.residual <= options.tolerance && a.min_weight >= options.min_weight;
    result.attempts.push_back(a);
    const bool take = a.converged ? !result.converged : (!result.converged && a.residual < best);
    if (take) {
      result.rule = rule;
      result.residual = a.residual;
      result.best_attempt = attempt;
      result.converged = a.converged;
      best = a.residual;
    }
    if (a.converged && options.stop_at_first) break;
  }
  return result;
}

}  // namespace iga::quadrature::moment_fit

namespace iga::quadrature::moment_fit {

namespace {
Eigen::VectorXd pack(const Rule& rule) {
  Eigen::VectorXd x(3 * rule.size());
  for (Eigen::Index i = 0; i < rule.size(); ++i) x.segment<3>(3 * i) << rule.points(0, i), rule.points(1, i), rule.weights(i);
  return x;
}
}  // namespace

FitResult eliminate_points(int valence, const Rule& start, const FitOptions& options, int min_points) {
  if (valence < 3 || valence > 16) throw InputError("moment fit: valence must be 3..16, got " + std::to_string(valence));
  if (start.size() < 1) throw InputError("moment fit: elimination needs a start rule");
  Problem pb;
  pb.valence = valence;
  pb.space = options.space;
  pb.lower = options.lower_bound;
  pb.b = &moments(valence, options.space);
  if (options.space != Space::Phi) pb.projection = &range_projection(valence, options.space);
  FitResult result;
  result.valence = valence;
  result.space = options.space;
  auto converged = [&](const Rule& r, Attempt& a) {
    a.residual = residual(valence, options.space, r);
    a.min_weight = r.weights.minCoeff();
    a.converged = a.residual <= options.tolerance && a.min_weight >= options.min_weight;
    return a.converged;
  };
  // Polish the start (points clamped into the bounds first).
  Rule current = start;
  current.points = current.points.cwiseMax(options.lower_bound).cwiseMin(1.0);
  {
    pb.free = static_cast<int>(current.size());
    Eigen::VectorXd lo, hi, x = pack(current);
    pb.bounds(lo, hi);
    polish(pb, options.polish_iterations, lo, hi, x);
    current = pb.expand(x);
    Attempt a;
    result.converged = converged(current, a);
    result.residual = a.residual;
    result.attempts.push_back(a);
    if (!result.converged) {
      result.rule = current;
      result.points = static_cast<int>(current.size());
      return result;
    }
  }
  const Eigen::Index rows = pb.projection != nullptr ? pb.projection->rows() : pb.b->size();
  while (current.size() > min_points && !past(options.deadline)) {
    Eigen::MatrixXd f;
    evaluate_functions(valence, options.space, current.points, f);
    std::vector<std::pair<double, Eigen::Index>> significance;
    for (Eigen::Index i = 0; i < current.size(); ++i) significance.emplace_back(current.weights(i) * f.col(i).norm(), i);
    std::sort(significance.begin(), significance.end());
    // Many points left: remove a batch (5 % of them) per step; near the end one at a time.
    const Eigen::Index batch = current.size() > 2 * rows ? std::max<Eigen::Index>(1, current.size() / 20) : 1;
    bool accepted = false;
    for (int k = 0; k < options.attempts && !accepted && !past(options.deadline); ++k) {
      std::vector<bool> drop(static_cast<std::size_t>(current.size()), false);
      for (Eigen::Index j = 0; j < batch; ++j) {
        const auto pick = static_cast<std::size_t>(batch == 1 ? k : j);
        if (pick >= significance.size()) break;
        drop[static_cast<std::size_t>(significance[pick].second)] = true;
      }
      Rule trial;
      const auto kept = static_cast<Eigen::Index>(std::count(drop.begin(), drop.end(), false));
      trial.points.resize(2, kept);
      trial.weights.resize(kept);
      for (Eigen::Index i = 0, j = 0; i < current.size(); ++i) {
        if (drop[static_cast<std::size_t>(i)]) continue;
        trial.points.col(j) = current.points.col(i);
        trial.weights(j++) = current.weights(i);
      }
      pb.free = static_cast<int>(kept);
      Eigen::VectorXd lo, hi, x = pack(trial);
      pb.bounds(lo, hi);
      pb.evaluations = 0;
      polish(pb, options.polish_iterations, lo, hi, x);
      trial = pb.expand(x);
      Attempt a;
      a.evaluations = pb.evaluations;
      if (converged(trial, a)) {
        current = std::move(trial);
        result.residual = a.residual;
        accepted = true;
      }
      result.attempts.push_back(a);
      if (batch > 1) break;  // a failed batch: retry the step one point at a time
    }
    if (!accepted && batch == 1) break;
    if (!accepted) {
      // Batch failed: fall back to single removals by pretending the batch threshold is passed.
      bool single = false;
      for (int k = 0; k < options.attempts && !single && !past(options.deadline); ++k) {
        Rule trial;
        trial.points.resize(2, current.size() - 1);
        trial.weights.resize(current.size() - 1);
        for (Eigen::Index i = 0, j = 0; i < current.size(); ++i) {
          if (i == significance[static_cast<std::size_t>(k)].second) continue;
          trial.points.col(j) = current.points.col(i);
          trial.weights(j++) = current.weights(i);
        }
        pb.free = static_cast<int>(trial.size());
        Eigen::VectorXd lo, hi, x = pack(trial);
        pb.bounds(lo, hi);
        polish(pb, options.polish_iterations, lo, hi, x);
        trial = pb.expand(x);
        Attempt a;
        if (converged(trial, a)) {
          current = std::move(trial);
          result.residual = a.residual;
          single = true;
        }
        result.attempts.push_back(a);
      }
      if (!single) break;
    }
  }
  result.rule = current;
  result.points = static_cast<int>(current.size());
  result.best_attempt = 0;
  result.seed = 0;
  return result;
}

}  // namespace iga::quadrature::moment_fit
