#pragma once
// Functions given as text, parsed with muparser: "sin(pi*x)*sin(pi*y)".
#include <memory>
#include <string>

#include "fem/function.hpp"

namespace iga::fem {

/// A scalar expression in x, y, z (and, for boundary data, nx, ny, nz: the outward unit normal).
/// Constants pi and e; muparser's functions (sin, cos, tan, asin, acos, atan, sinh, cosh, tanh, exp, ln,
/// log, log10, sqrt, abs, sign, min, max, ...) plus atan2(y, x) and pow(a, b).
/// The text is checked when the object is made: InputError("<what>: <muparser's message>") for a syntax
/// error or an unknown variable, where `what` names the option (e.g. "--source").
/// Evaluation is thread-safe (one parser per thread). A value that is not finite (1/0, sqrt(-1), log(0), an
/// overflow) throws InputError naming the option, the expression and the point: data are never NaN.
class Expression final : public Function, public BoundaryFunction {
 public:
  Expression(std::string text, std::string what, bool allow_normal = false);
  ~Expression() override;
  const std::string& text() const { return text_; }
  void values(const Eigen::Matrix3Xd& x, Eigen::VectorXd& out) const override;
  void values(const Eigen::Matrix3Xd& x, const Eigen::Matrix3Xd& n, Eigen::VectorXd& out) const override;

 private:
  struct Evaluator;
  Evaluator& evaluator() const;
  void check_finite(const Eigen::Matrix3Xd& x, const Eigen::VectorXd& out) const;
  std::string text_, what_, quoted_;
  bool allow_normal_;
  std::uint64_t id_;
};

}  // namespace iga::fem
