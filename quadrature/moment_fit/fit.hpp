#pragma once
// Moment fitting of quadrature rules for Catmull–Clark elements at an extraordinary vertex (thesis §4.2.4):
// q points (u_i, v_i) in (0,1]² and weights w_i > 0 with Φ w = b, Φ_{m,i} = f_m(u_i, v_i), b_m = ∫ f_m over
// [0,1]², for a family of functions f_m built from the 2n+8 subdivision splines φ_m of valence n.
#include <chrono>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "quadrature/rule.hpp"

namespace iga::quadrature::moment_fit {

/// The functions a rule is fitted to.
///   Phi:       the 2n+8 subdivision splines φ_a (so every function in their span is integrated exactly);
///   Mass:      the products φ_a φ_b, a <= b ((2n+8)(2n+9)/2 functions, linearly dependent);
///   Stiffness: φ_a,u φ_b,u + φ_a,v φ_b,v, a <= b (the planar Poisson integrand on the parameter domain).
enum class Space { Phi, Mass, Stiffness };

std::string to_string(Space space);
/// "phi", "mass", "stiffness"; InputError otherwise.
Space parse_space(const std::string& text);

/// Number of functions f_m of the space for valence n.
int num_functions(int valence, Space space);

/// Values F (functions × points) and, when fu and fv are non-null, their d/du and d/dv at pts (2 × q, inside
/// [0,1]²; evaluated with basis::catmull_clark::stam_evaluator(valence)).
void evaluate_functions(int valence, Space space, const Eigen::Matrix2Xd& pts, Eigen::MatrixXd& f,
                        Eigen::MatrixXd* fu = nullptr, Eigen::MatrixXd* fv = nullptr);

/// The moments b_m = ∫_{[0,1]²} f_m, exact (geometric series of quadrature/exact/irregular_integrals.hpp:
/// phi, phi_phi, d[0][0] + d[1][1]). Cached per (valence, space); thread-safe.
const Eigen::VectorXd& moments(int valence, Space space);

/// ||Φ w − b||_2 of a rule (points inside [0,1]²) for the space of valence n.
double residual(int valence, Space space, const Rule& rule);

struct FitOptions {
  Space space = Space::Phi;
  /// Search only rules symmetric about u = v: pairs (u,v), (v,u) of equal weight plus diagonal_points points
  /// (t,t). Then q − diagonal_points must be even.
  bool symmetric = false;
  /// Symmetric rules only: points on the diagonal; -1 means q mod 2.
  int diagonal_points = -1;
  unsigned seed = 20240601;  ///< attempt k uses std::mt19937(seed + k)
  int attempts = 20;         ///< random starts
  bool stop_at_first = true; ///< stop after the first converged attempt (false: run all, for success rates)
  double tolerance = 1e-13;  ///< convergence: ||Φ w − b||_2 <= tolerance
  double lower_bound = 1e-12; ///< u, v in [lower_bound, 1]: the EV (0,0) is never a point
  double min_weight = 1e-12; ///< convergence also needs every weight >= min_weight
  /// First stage: an NLopt algorithm on S = ||Φ w − b||² with bound constraints ("LD_LBFGS", "LD_SLSQP",
  /// "LD_MMA", "LN_BOBYQA") or "none"; then a bound-constrained Levenberg–Marquardt polish (Eigen).
  std::string algorithm = "LD_SLSQP";
  int max_evaluations = 3000;    ///< first stage
  int polish_iterations = 300;   ///< second stage
  /// A time limit: no attempt (fit_rule: after the first) or removal step (eliminate_points) starts after it, and
  /// NLopt's first stage stops at it (its maxtime). None: no limit.
  std::optional<std::chrono::steady_clock::time_point> deadline;
};

/// One random start.
struct Attempt {
  bool converged = false;
  double residual = 0.0;    ///< ||Φ w − b||_2 at the end
  double min_weight = 0.0;
  int evaluations = 0;      ///< NLopt evaluations + polish iterations
};

struct FitResult {
  int valence = 0;
  int points = 0;
  Space space = Space::Phi;
  bool symmetric = false;
  int diagonal_points = 0;
  bool converged = false;
  int best_attempt = -1;    ///< index of the returned rule (the first converged attempt, else the best)
  unsigned seed = 0;        ///< FitOptions::seed; the rule came from std::mt19937(seed + best_attempt)
  double residual = 0.0;    ///< of the returned rule
  Rule rule;                ///< points 2 × q, weights q
  std::vector<Attempt> attempts;
  int successes() const;
};

/// Fits a q-point rule for valence n (3..16) from random starts (see FitOptions). Never throws for a failed
/// fit (converged = false); InputError for bad arguments.
FitResult fit_rule(int valence, int points, const FitOptions& options);

/// Node elimination (an alternative to random starts, which rarely converge for the mass and stiffness spaces):
/// starts from `start` (a rule integrating the space to options.tolerance, e.g. tiled_rule(4, 16)) and
/// repeatedly removes the point of least significance w_i ||Φ_i|| (several at once while many points are left),
/// re-solving points and weights of the rest with the projected Levenberg–Marquardt iteration
/// (options.polish_iterations per step). When a removal does not re-converge, the next candidates are tried
/// (options.attempts of them); then it stops. Returns the smallest converged rule (converged = false only when
/// `start` itself does not converge); attempts lists one entry per accepted or rejected removal. Stops at
/// min_points. Deterministic (no random numbers; seed and best_attempt are 0).
FitResult eliminate_points(int valence, const Rule& start, const FitOptions& options, int min_points = 1);

}  // namespace iga::quadrature::moment_fit
