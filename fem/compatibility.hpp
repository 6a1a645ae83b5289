#pragma once
// The solvability condition of a pure-Neumann problem (no Dirichlet boundary, no reaction term): -Δu = f with
// ∂u/∂n = g has a solution only when ∫f + ∫g = 0. How far given data are from it, and what a program does:
// solve, warn, or refuse (the FEM in fem/poisson.cpp and the BEM in bem/solve.cpp share the rule).
#include <string>

namespace iga::fem {

/// The integrals of the data by one quadrature: ∫f over the domain, ∫g over the Neumann boundary, and of |f|, |g|.
struct DataIntegrals {
  double source = 0.0, neumann = 0.0, source_abs = 0.0, neumann_abs = 0.0;
  double defect() const { return source + neumann; }
  double scale() const { return source_abs + neumann_abs; }
};

/// Round-off: |∫f + ∫g| at most this times ∫|f| + ∫|g| is compatible data ("exact"). Sums of a few million
/// quadrature terms in double precision stay below it.
inline constexpr double kCompatibilityRoundoff = 1e-12;
/// Beyond round-off but at most this times ∫|f| + ∫|g|: a small defect, removed with a warning; above it the
/// problem is refused. Compatible smooth data measured at most 3.3e-13 of the scale by the finer rules once the
/// mesh resolves them (README, "Pure-Neumann problems"); the margin of 1e4 covers data known to ~8 digits.
inline constexpr double kCompatibilityTolerance = 1e-8;

/// A defect at most this many times the quadrature-error estimate (the difference between the assembly's rules
/// and the finer ones) cannot be told from the quadrature's own error. Compatible data measured up to 12 times it
/// (Catmull–Clark near extraordinary vertices, where the finer rule gains little); 100 leaves a margin of 8.
inline constexpr double kQuadratureMargin = 100.0;

/// The data's defect by the assembly's quadrature and by finer rules (two more points per direction: the error
/// rules). The finer value is the one judged; a defect within kQuadratureMargin times the difference of the two
/// is not refused (coarse meshes under-resolve smooth data: ∫f + ∫g = -3.6 on the one-element quarter annulus
/// for compatible data).
struct Compatibility {
  DataIntegrals assembly, finer;
  bool has_source = true;  ///< false for the BEM (Laplace: only g)

  enum class Verdict { kExact, kQuadrature, kWarned, kRefused };
  double defect() const { return finer.defect(); }
  double scale() const { return finer.scale(); }
  double quadrature_error() const;
  /// |defect| / scale (0 when the data are zero).
  double relative() const;
  Verdict verdict() const;
  /// For the report: "exact", "within the quadrature error", "small defect removed (warned)", "refused".
  std::string word() const;
  /// The warning line (kWarned), without the program's name.
  std::string warning() const;
  /// The refusal (kRefused): the integrals named, then `remedy`.
  std::string refusal(const std::string& remedy) const;
};

/// InputError(refusal(remedy)) when the verdict is kRefused.
void check_compatibility(const Compatibility& c, const std::string& remedy);

}  // namespace iga::fem
