#pragma once
// Convergence tables (deal.II's ConvergenceTable): one row per refinement level with its size and error norms,
// the observed rates between consecutive levels and a least-squares rate over all levels.
//
// Rates are exponents r in e ≈ C x^r for a size x, fitted in log-log:
//  - against the mesh size h (Against::h): r_k = log(e_{k-1}/e_k) / log(h_{k-1}/h_k); theory for degree-p
//    splines and a smooth solution: L2 error r = p + 1, H1 seminorm error r = p;
//  - against N^(-1/dim), N the number of dofs (Against::dofs; deal.II's reduction_rate_log2 with dim): the
//    same exponents asymptotically, but on coarse meshes the dofs on the boundary (N = (2^k + p)^2 for one
//    degree-p patch) make these rates larger than the mesh-size ones.
// The least-squares rate is the slope of log e over log x of all rows (ordinary least squares, equal weights).
#include <optional>
#include <string>
#include <vector>

#include "core/types.hpp"

namespace iga::fem {

struct ConvergenceRow {
  int level = 0;               ///< the refinement level (a label; rates use h and dofs)
  Index dofs = 0, elements = 0;
  double h = 0.0;              ///< mesh size (> 0), in the units of the domain
  std::vector<double> errors;  ///< one per norm of the table (>= 0; 0 has no rate)
  double seconds = 0.0;        ///< the time the level took (a column of the text table)
};

class ConvergenceTable {
 public:
  enum class Against { h, dofs };

  /// norms: the names of the error columns ("L2", "H1"); dim: the dimension of the domain (2 for planar
  /// domains and surfaces) for the rates against dofs.
  explicit ConvergenceTable(std::vector<std::string> norms, int dim = 2);

  /// InputError when row.errors does not have one entry per norm, h or dofs is not positive, or an error is
  /// negative or not finite.
  void add_row(const ConvergenceRow& row);

  const std::vector<ConvergenceRow>& rows() const { return rows_; }
  const std::vector<std::string>& norms() const { return norms_; }

  /// Per row the rate from the previous row (entry 0: none; none where an error is 0 or the sizes are equal).
  std::vector<std::optional<double>> rates(std::size_t norm, Against against = Against::h) const;
  /// The least-squares slope over all rows with a positive error (none with fewer than two such rows).
  std::optional<double> fitted_rate(std::size_t norm, Against against = Against::h) const;

  /// The table as text, one line per row (level, dofs, elements, h, per norm error and rate, seconds) and a
  /// last line with the fitted rates; rates against h.
  std::string text() const;

 private:
  double size(const ConvergenceRow& row, Against against) const;
  std::vector<std::string> norms_;
  int dim_;
  std::vector<ConvergenceRow> rows_;
};

}  // namespace iga::fem
