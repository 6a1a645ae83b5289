#pragma once
// Error norms of a discrete solution against an exact one: a list of norms (DESIGN.md item 1), each with the
// exact solution's own norm for relative figures.
#include <Eigen/Core>
#include <span>
#include <string>
#include <vector>

#include "fem/assembler.hpp"
#include "fem/function.hpp"

namespace iga::fem {

/// kL2: ‖e‖_L2. kH1: |e|_H1, the L2 norm of the (surface) gradient. kH2: |e|_H2 = (∫ e_xx² + 2 e_xy² + e_yy²)^½
/// (planar domains). kLaplacian: ‖Δe‖_L2 (planar; the biharmonic equation's energy norm).
enum class Norm { kL2, kH1, kH2, kLaplacian };
/// "L2", "H1", "H2", "laplacian".
std::string norm_name(Norm norm);

/// One figure of a report: a norm's name as the problem gives it ("L2", "H1 x", "energy"), the error and the exact
/// solution's own norm (for relative errors).
struct NormError {
  std::string name;
  double error = 0.0;  ///< of u − u_h
  double exact = 0.0;  ///< of u
  /// How the exact solution's derivatives in this norm were computed (Function::derivative_method; "values" for a
  /// norm without derivatives), when the problem says (Problem::error_derivatives()).
  std::string derivatives;
  /// The estimated error of finite-difference derivatives in this norm (0 when they are exact).
  double derivative_error = 0.0;
};

/// Refused above this: a norm whose finite-difference derivatives have an estimated error above this fraction of the
/// error itself is not reported (norm_errors).
constexpr double kDerivativeErrorShare = 0.01;
/// How `exact`'s derivatives enter `norm`: "values" (L2), else exact.derivative_method(1 or 2).
std::string derivatives_in(Norm norm, const Function& exact);

/// Per norm in order, ‖u − u_h‖² and ‖u‖² (2 entries per norm), then per norm the square of the estimated error of
/// the exact solution's derivatives in it (3 entries per norm in all), over the elements e with only[e] != 0 (all
/// when only is null): a distributed run sums its ranks' parts before norm_errors() takes the roots. Gradients of the
/// exact solution come from exact.gradients() (projected onto the tangent plane on surfaces), Hessians from
/// exact.hessians(). Where those are finite differences (exact_gradient() or exact_hessian() false) their error is
/// estimated as the difference between steps h and 2h (fourth order: 15 times the error at h, asymptotically, so a
/// safe bound); 0 where they are exact. UnsupportedError for kH2 or kLaplacian on a surface.
Eigen::VectorXd norm_squares(const Assembler& assembler, const Eigen::VectorXd& u, const Function& exact,
                             std::span<const Norm> norms, const std::vector<char>* only = nullptr);
/// The norms from their squares (2 per name, or 3 with the derivative-error estimates, as norm_squares gives them);
/// NumericalError naming the norm when one is not finite (an exact solution that overflows, a solve that diverged),
/// and when the estimated error of finite-difference derivatives is above kDerivativeErrorShare of the norm's error:
/// never a NaN or untrustworthy figure in a report. `derivatives` (empty, or one per name) goes into the figures.
std::vector<NormError> norm_errors(const std::vector<std::string>& names, const Eigen::VectorXd& squares,
                                   const std::vector<std::string>& derivatives = {});

struct ErrorNorms {
  double l2 = 0.0;        ///< ||u - u_h||_L2
  double h1 = 0.0;        ///< |u - u_h|_H1 (seminorm: L2 norm of the (surface) gradient error)
  double l2_exact = 0.0;  ///< ||u||_L2, for relative errors
  double h1_exact = 0.0;  ///< |u|_H1
};

/// L2 and H1 by the assembler's quadrature (norm_squares with kL2, kH1).
ErrorNorms compute_errors(const Assembler& assembler, const Eigen::VectorXd& u, const Function& exact);

/// The squares behind compute_errors (‖u − u_h‖², |u − u_h|²_1, ‖u‖², |u|²_1) over the elements e with
/// only[e] != 0 (all when only is null): a distributed run sums its ranks' parts before the square roots.
Eigen::Vector4d error_squares(const Assembler& assembler, const Eigen::VectorXd& u, const Function& exact,
                              const std::vector<char>* only = nullptr);
ErrorNorms error_norms(const Eigen::Vector4d& squares);

}  // namespace iga::fem
