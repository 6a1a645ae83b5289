#pragma once
// Tensor-product Bernstein–Bézier patches of the polyhedral spline: the regular bi-2 patch (paper, eq. (2)
// re-expressed in BB form (3)), Bernstein degree elevation (bi-2 → bi-3, (3,2) → (3,3)) and evaluation.
//
// Coefficient layout (as PatchMask in mask.hpp): BB coefficient b_ij (i along u = 0..degree_u, j along v)
// is row j·(degree_u + 1) + i. Parameters (u, v) ∈ [0,1]² (the patch's own domain); derivatives are with
// respect to (u, v).
#include <Eigen/Core>
#include <string>
#include <utility>
#include <vector>

#include "basis/polyhedral/mask.hpp"

namespace iga::basis::polyhedral {

/// A patch: its degrees and BB coefficients ((degree_u+1)(degree_v+1) rows, one column per coordinate — or,
/// for a mask, per gathered vertex).
struct BezierPatch {
  int degree_u = 3;
  int degree_v = 3;
  Eigen::MatrixXd coefficients;
};

/// The Regular configuration's mask: the uniform bi-2 B-spline piece over the dual face of the centre v
/// (eq. (2)) in BB form, 9 rows × 9 gathered vertices in the Regular gather order [v, e_0, f_0, …, e_3, f_3].
/// u runs from e_2 toward e_0 and v from e_3 toward e_1; the control point grid (i, j) (i along u) is
/// f_2 e_3 f_3 / e_2 v e_0 / f_1 e_1 f_0 for j = 0, 1, 2. Closed form per direction: with B-spline control
/// points c_0, c_1, c_2 the BB coefficients are ((c_0 + c_1)/2, c_1, (c_1 + c_2)/2).
PatchMask regular_mask();

/// Univariate Bernstein degree elevation p → q (q >= p): E ((q+1) × (p+1)), b' = E b. One step p → p+1 is
/// b'_i = (i/(p+1)) b_{i−1} + (1 − i/(p+1)) b_i.
Eigen::MatrixXd elevation_matrix(int p, int q);

/// The coefficients of the same polynomial patch in degree (target_u, target_v) (each >= the current one).
/// Works on any number of columns (points or mask columns). InputError if a target is below the degree or
/// the row count does not match the degrees.
BezierPatch elevate(const BezierPatch& patch, int target_u, int target_v);
PatchMask elevate(const PatchMask& mask, int target_u, int target_v);

/// Tensor Bernstein basis values at points pts (2 × q, (u, v) ∈ [0,1]²): rows = coefficient index
/// j·(degree_u+1)+i, columns = points, for the derivative ∂^order_u/∂u ∂^order_v/∂v (orders 0..2).
Eigen::MatrixXd bernstein_tensor(int degree_u, int degree_v, const Eigen::Matrix2Xd& pts, int order_u, int order_v);

/// Positions and parametric derivatives of a patch at points (each q × columns of coefficients).
struct PatchValues {
  Eigen::MatrixXd x, xu, xv;        ///< filled for derivatives >= 0, >= 1
  Eigen::MatrixXd xuu, xuv, xvv;    ///< filled for derivatives >= 2
};
PatchValues evaluate(const BezierPatch& patch, const Eigen::Matrix2Xd& pts, int derivatives);

}  // namespace iga::basis::polyhedral
