#pragma once
// Values and parametric derivatives of an element's local basis functions at a batch of points.
#include <Eigen/Core>

namespace iga::basis {

/// Every block is (local dofs × points), column-major. Derivatives are with respect to the element's
/// reference coordinates (u, v) on the unit square or triangle, not the physical coordinates.
/// Blocks beyond the requested derivative order are left untouched (their size is unspecified).
struct BasisValues {
  Eigen::MatrixXd value;
  Eigen::MatrixXd du, dv;         ///< first derivatives, when derivatives >= 1
  Eigen::MatrixXd duu, duv, dvv;  ///< second derivatives, when derivatives >= 2

  /// Sizes the blocks needed for `derivatives` to functions × points (no allocation when unchanged).
  void resize(Eigen::Index functions, Eigen::Index points, int derivatives) {
    value.resize(functions, points);
    if (derivatives >= 1) {
      du.resize(functions, points);
      dv.resize(functions, points);
    }
    if (derivatives >= 2) {
      duu.resize(functions, points);
      duv.resize(functions, points);
      dvv.resize(functions, points);
    }
  }

  /// Calls f(from_block, to_block) for each pair of blocks of `from` and `to` needed for `derivatives`
  /// (value, then du, dv, then duu, duv, dvv).
  template <class F>
  static void for_each_block(const BasisValues& from, BasisValues& to, int derivatives, F&& f) {
    f(from.value, to.value);
    if (derivatives >= 1) {
      f(from.du, to.du);
      f(from.dv, to.dv);
    }
    if (derivatives >= 2) {
      f(from.duu, to.duu);
      f(from.duv, to.duv);
      f(from.dvv, to.dvv);
    }
  }

  /// Zeroes column p (one point) of the blocks needed for `derivatives`.
  void zero_column(Eigen::Index p, int derivatives) {
    value.col(p).setZero();
    if (derivatives >= 1) {
      du.col(p).setZero();
      dv.col(p).setZero();
    }
    if (derivatives >= 2) {
      duu.col(p).setZero();
      duv.col(p).setZero();
      dvv.col(p).setZero();
    }
  }
};

}  // namespace iga::basis
