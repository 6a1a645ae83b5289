#pragma once
// The scheme-neutral subdivision view (basis/subdivision_view.hpp) of Catmull–Clark elements at extraordinary
// vertices: bicubic B-spline tiles on the unit square, tiles 1..3 of Stam's layers (all with t = 2x − offset
// on layer 1, jacobian 2 I).
#include <array>

#include <Eigen/Core>

#include "basis/subdivision_view.hpp"

namespace iga::basis::catmull_clark {

/// The view of a repeating configuration: subdivision matrix A (m × m), limit stencil w and the three tile
/// operators E_k (16 × m) of layer 1.
SubdivisionView quad_view(const Eigen::MatrixXd& a, const Eigen::VectorXd& w, const std::array<Eigen::MatrixXd, 3>& tiles);

/// The view of Stam's evaluator of valence n (interior EV; 2n+8 points, stam.hpp order): A, its limit stencil
/// and E_k = X^k Ā. Cached per valence, thread-safe; InputError unless 3 <= n <= 16.
const SubdivisionView& stam_view(int n);

}  // namespace iga::basis::catmull_clark
