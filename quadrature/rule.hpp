#pragma once
// Quadrature rules are data: points and weights on a reference domain.
#include <Eigen/Core>

namespace iga::quadrature {

/// A rule on [0, 1]: integral of f ≈ sum_k weights(k) f(points(k)).
struct Rule1D {
  Eigen::VectorXd points;
  Eigen::VectorXd weights;
  Eigen::Index size() const { return points.size(); }
};

/// A rule on a 2D reference element (unit square or unit triangle): points 2 × q, weights q.
struct Rule {
  Eigen::Matrix2Xd points;
  Eigen::VectorXd weights;
  Eigen::Index size() const { return weights.size(); }
};

}  // namespace iga::quadrature
