#pragma once
// What a shell solution shows at points of the surface: the displacement, the membrane forces and bending moments
// per unit length as Cartesian tensors, and von Mises' stress at the top and bottom fibres.
#include <Eigen/Core>
#include <functional>

#include "basis/geometry.hpp"
#include "pde/shell/forms.hpp"

namespace iga::pde {

/// At the points where the basis (with second derivatives) and the map (derivatives 2) were evaluated on element e,
/// for coefficients u (3 per function, interleaved):
///  - displacement 3 × q;
///  - forces N = n^αβ a_α ⊗ a_β with (n¹¹, n²², n¹²) = t D ε, and moments M = m^αβ a_α ⊗ a_β with
///    (m¹¹, m²², m¹²) = −t³/12 D κ (the classical sign: a plate's M_xx = −D_p (w_,xx + ν w_,yy)), each 6 × q in ParaView's
///    symmetric-tensor order XX, YY, ZZ, XY, YZ, XZ;
///  - von Mises' stress of σ = N/t ± 6 M/t² at the top (+t/2 along a_3) and bottom fibres, 2 × q (rows top, bottom).
struct ShellResultants {
  Eigen::MatrixXd displacement, forces, moments, von_mises;
};
void shell_resultants(const basis::Space& space, const Eigen::VectorXd& u, Index e, const basis::BasisValues& bv,
                      const basis::GeometryValues& gv, const ShellMaterial& material, ShellResultants& out);

/// One of shell_resultants's outputs as a sampled writer's field (io::SampledField::values, derivatives 2): which 0 the
/// displacement, 1 the forces, 2 the moments, 3 von Mises' stress (top, bottom). Keeps references to space and u.
std::function<void(Index e, const basis::BasisValues& bv, const basis::GeometryValues& gv, Eigen::MatrixXd& out)>
shell_sampler(const basis::Space& space, const Eigen::VectorXd& u, ShellMaterial material, int which);

/// shell_resultants at one reference point uv of element e (evaluating basis and map there).
ShellResultants shell_resultants_at(const basis::Geometry& geometry, const Eigen::VectorXd& u, Index e,
                                    const Eigen::Vector2d& uv, const ShellMaterial& material);

}  // namespace iga::pde
