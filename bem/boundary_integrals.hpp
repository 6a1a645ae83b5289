#pragma once
// The element–point loop of collocation BEM, in one place: for a source point P (internal coordinates), the
// integrals of every basis function against both kernels over the whole boundary,
//   g_j = ∫_Γ φ_j v(P, ·) dΓ,   h_j = ∫_Γ φ_j ∂v/∂n(P, ·) dΓ   (thesis (4.48), (4.50)),
// with the far elements on a cached Gauss rule and the near and singular ones by kernel_quadrature.
#include <Eigen/Core>
#include <vector>

#include "bem/boundary_discretization.hpp"
#include "bem/kernel_quadrature.hpp"

namespace iga::bem {

class BoundaryIntegrator {
 public:
  explicit BoundaryIntegrator(const BoundaryDiscretization& d, const KernelQuadratureOptions& options = {});

  /// h and g (size num_dofs) for P in internal coordinates (scaled_curve()). on_curve_element / curve_t: where P
  /// lies on the boundary (collocation points), or −1 / NaN for other points. Returns false when the adaptive
  /// subdivision found P on the boundary although it was not declared there (the integrals are then not
  /// accurate: P is on Γ).
  bool integrate(const Eigen::Vector2d& p, Index on_curve_element, double curve_t, Eigen::VectorXd& h,
                 Eigen::VectorXd& g) const;

  const BoundaryDiscretization& discretization() const { return d_; }

 private:
  struct ElementCache {
    Eigen::Matrix2Xd x, normal;
    Eigen::VectorXd ws;      // weight × speed
    Eigen::MatrixXd basis;   // local dofs × nodes
    Eigen::Vector2d xa, xm, xb;
    double length = 0.0;
  };
  const BoundaryDiscretization& d_;
  KernelQuadratureOptions options_;
  std::vector<ElementCache> cache_;
};

}  // namespace iga::bem
