#pragma once
// Error norms of a discrete solution against an exact one.
#include <Eigen/Core>

#include "fem/assembler.hpp"
#include "fem/function.hpp"

namespace iga::fem {

struct ErrorNorms {
  double l2 = 0.0;        ///< ||u - u_h||_L2
  double h1 = 0.0;        ///< |u - u_h|_H1 (seminorm: L2 norm of the (surface) gradient error)
  double l2_exact = 0.0;  ///< ||u||_L2, for relative errors
  double h1_exact = 0.0;  ///< |u|_H1
};

/// Norms by the assembler's quadrature. The exact gradient is exact.gradients(), projected onto the tangent
/// plane (for surfaces; for planar domains this drops the z component).
ErrorNorms compute_errors(const Assembler& assembler, const Eigen::VectorXd& u, const Function& exact);

/// The squares behind compute_errors (‖u − u_h‖², |u − u_h|²_1, ‖u‖², |u|²_1) over the elements e with
/// only[e] != 0 (all when only is null): a distributed run sums its ranks' parts before the square roots.
Eigen::Vector4d error_squares(const Assembler& assembler, const Eigen::VectorXd& u, const Function& exact,
                              const std::vector<char>* only = nullptr);
ErrorNorms error_norms(const Eigen::Vector4d& squares);

}  // namespace iga::fem
