#pragma once
// Exact derivatives of a user's expression (issue 32): the muparser text is read into a GiNaC expression,
// differentiated there, and each derivative is written back as muparser text, so that it is evaluated as fast as the
// expression itself. GiNaC does the calculus; the reading and writing of muparser's grammar are ours.
#include <array>
#include <optional>
#include <string>
#include <vector>

namespace iga::fem {

/// The first and second partial derivatives of an expression in x, y, z, as muparser texts.
struct SymbolicDerivatives {
  std::string reading;                  ///< the expression itself as it was read, written back (for the check)
  std::array<std::string, 3> gradient;  ///< ∂/∂x, ∂/∂y, ∂/∂z
  std::array<std::string, 6> hessian;   ///< xx, xy, yy, xz, yz, zz (Function::hessians' rows)
  /// Where the expression may be singular: the factors (muparser texts) whose zeros are its poles or log
  /// singularities, and each one named for messages ("the denominator -3/10+x", "the argument of log -1/2+x"): bases of
  /// negative powers, arguments of log, cos(a) for tan(a), split into factors (polynomials factored over the
  /// rationals, abs(a) as a, a^k as a); constants left out; at most 16.
  std::vector<std::string> singular, singular_names;
};

/// The derivatives of `text` (the grammar of fem::Expression without nx, ny, nz: numbers, x, y, z, pi, e, _pi, _e,
/// + - * / ^, unary signs, comparisons, && ||, c ? a : b, and muparser's functions with atan2 and pow). Where the
/// expression is not differentiable (a comparison, sign, rint, the kink of abs, min or max) the derivative is that of
/// the branch taken, as a finite difference would see it away from the kink. nullopt, with the reason in `why`, for
/// a text it does not read or a result it cannot write back. A caller checks `reading` against the text's own values
/// (fem::Expression does, at fixed points) and falls back on finite differences when they differ. Thread-safe (GiNaC
/// is used under one lock).
std::optional<SymbolicDerivatives> differentiate(const std::string& text, std::string& why);

/// The expression as this module reads it, written back as muparser text (fully parenthesised): for tests of the
/// reading. nullopt with `why` as differentiate().
std::optional<std::string> symbolic_reading(const std::string& text, std::string& why);

}  // namespace iga::fem
