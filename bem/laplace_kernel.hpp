#pragma once
// The fundamental solution of the 2D Laplace equation and its normal derivative (thesis §4.3.1, (4.43) and
// §4.3.3), as small point kernels apart from the element–point loop: P is the source (collocation or interior)
// point, Q the field point on the boundary, n_Q the outward unit normal at Q. Both in the same (internal,
// scaled) coordinates; kernels are dimensionless apart from the 1/length of the double layer.
#include <Eigen/Core>
#include <cmath>
#include <numbers>

namespace iga::bem {

inline constexpr double kInvTwoPi = 0.5 / std::numbers::pi;

/// v(P, Q) = −ln|Q − P| / (2π)  (4.43): −Δ_Q v = δ(Q − P).
struct SingleLayerKernel {
  double operator()(const Eigen::Vector2d& p, const Eigen::Vector2d& q) const {
    return -kInvTwoPi * std::log((q - p).norm());
  }
};

/// ∂v/∂n_Q(P, Q) = −((Q − P) · n_Q) / (2π |Q − P|²)  (§4.3.3): bounded on a smooth arc through P (→ −κ/(4π)).
struct DoubleLayerKernel {
  double operator()(const Eigen::Vector2d& p, const Eigen::Vector2d& q, const Eigen::Vector2d& n) const {
    const Eigen::Vector2d r = q - p;
    return -kInvTwoPi * r.dot(n) / r.squaredNorm();
  }
};

}  // namespace iga::bem
