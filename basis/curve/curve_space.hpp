#pragma once
// Spline spaces of parametric dimension 1: the boundary of a planar domain as a space of its own (DESIGN.md
// item 6). Elements are parametrised by t in [0, 1]; each has the global dofs of the functions that are
// non-zero on it, in the local order of evaluate()'s rows.
#include <Eigen/Core>
#include <span>

#include "core/types.hpp"

namespace iga::basis {

/// Values and t-derivatives of an element's local functions at a batch of q points: each block is
/// (local dofs × q). Blocks beyond the requested derivative order are left untouched.
struct CurveBasisValues {
  Eigen::MatrixXd value;
  Eigen::MatrixXd dt;   ///< d/dt, when derivatives >= 1
  Eigen::MatrixXd dtt;  ///< d²/dt², when derivatives >= 2

  void resize(Eigen::Index functions, Eigen::Index points, int derivatives) {
    value.resize(functions, points);
    if (derivatives >= 1) dt.resize(functions, points);
    if (derivatives >= 2) dtt.resize(functions, points);
  }
};

class CurveSpace {
 public:
  virtual ~CurveSpace() = default;
  virtual Index num_dofs() const = 0;
  virtual Index num_elements() const = 0;
  /// Global dofs whose functions are non-zero on element e.
  virtual std::span<const Index> dofs(Index e) const = 0;
  /// The largest dofs(e).size() over all elements.
  virtual Index max_local_dofs() const = 0;
  /// Element e's local functions at parameters t (each in [0, 1]); derivatives 0, 1 or 2.
  /// Allocation-free when `out` already has the sizes.
  virtual void evaluate(Index e, const Eigen::VectorXd& t, int derivatives, CurveBasisValues& out) const = 0;
};

}  // namespace iga::basis
