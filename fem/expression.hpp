#pragma once
// Functions given as text, parsed with muparser: "sin(pi*x)*sin(pi*y)".
#include <memory>
#include <string>
#include <vector>

#include "fem/function.hpp"

namespace iga::fem {

/// A scalar expression in x, y, z (and, for boundary data, nx, ny, nz: the outward unit normal).
/// Constants pi and e; muparser's functions (sin, cos, tan, asin, acos, atan, sinh, cosh, tanh, exp, ln,
/// log, log10, sqrt, abs, sign, min, max, ...) plus atan2(y, x) and pow(a, b).
/// The text is checked when the object is made: InputError("<what>: <muparser's message>") for a syntax
/// error or an unknown variable, where `what` names the option (e.g. "--source").
/// Evaluation is thread-safe (one parser per thread). A value that is not finite (1/0, sqrt(-1), log(0), an
/// overflow) throws InputError naming the option, the expression and the point: data are never NaN.
/// Derivatives (gradients(), hessians(); not for boundary data with nx, ny, nz) are exact: differentiated
/// symbolically once (fem/symbolic.hpp, GiNaC) and evaluated as muparser texts. When that is not possible (the
/// reading, written back, does not give the text's values at fixed points) they are Function's finite differences,
/// derivative_method() says why, and the error norms estimate that difference's error (fem/errors.hpp).
class Expression final : public Function, public BoundaryFunction {
 public:
  Expression(std::string text, std::string what, bool allow_normal = false);
  ~Expression() override;
  const std::string& text() const { return text_; }
  void values(const Eigen::Matrix3Xd& x, Eigen::VectorXd& out) const override;
  void values(const Eigen::Matrix3Xd& x, const Eigen::Matrix3Xd& n, Eigen::VectorXd& out) const override;
  void gradients(const Eigen::Matrix3Xd& x, Eigen::Matrix3Xd& out) const override;
  bool exact_gradient() const override { return symbolic_; }
  void hessians(const Eigen::Matrix3Xd& x, Eigen::Matrix<double, 6, Eigen::Dynamic>& out) const override;
  bool exact_hessian() const override { return symbolic_; }
  /// "symbolic (GiNaC)", or "finite differences (<why not symbolic>)".
  std::string derivative_method(int order) const override;
  /// The derivatives' texts (empty when not symbolic): ∂x, ∂y, ∂z, then xx, xy, yy, xz, yz, zz.
  const std::vector<std::string>& derivative_texts() const { return derivatives_; }
  /// The option and the quoted text, as in messages: "--source", "'1/x'" (cut at 60 characters).
  const std::string& what() const { return what_; }
  const std::string& quoted() const { return quoted_; }
  /// The values at the points without the finiteness check (NaN and ±inf as they come; for fem/data_check.hpp).
  void values_unchecked(const Eigen::Matrix3Xd& x, Eigen::VectorXd& out) const;
  /// Where the expression may be singular (symbolic only; SymbolicDerivatives::singular): each factor named
  /// ("the denominator -3/10+x"), and their values at the points (one row per factor).
  const std::vector<std::string>& singular_factor_names() const { return singular_names_; }
  void singular_factors(const Eigen::Matrix3Xd& x, Eigen::MatrixXd& out) const;

 private:
  struct Evaluator;
  Evaluator& evaluator() const;
  void check_finite(const Eigen::Matrix3Xd& x, const Eigen::VectorXd& out, const char* of = "") const;
  /// Rows first .. first + out.rows() - 1 of the symbolic derivatives (gradient 0..2, Hessian 3..8) at x, checked
  /// finite (the message names `of`).
  void symbolic_derivatives(const Eigen::Matrix3Xd& x, std::size_t first, Eigen::Ref<Eigen::MatrixXd> out,
                            const char* of) const;
  void differentiate();
  std::string text_, what_, quoted_;
  bool allow_normal_;
  bool symbolic_ = false;
  std::vector<std::string> derivatives_;  ///< 3 gradient and 6 Hessian texts when symbolic_
  std::string not_symbolic_;              ///< why not, otherwise
  std::vector<std::string> singular_, singular_names_;  ///< SymbolicDerivatives::singular, when symbolic_
  std::uint64_t id_;
};

}  // namespace iga::fem
