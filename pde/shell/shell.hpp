#pragma once
// The linear Kirchhoff–Love shell as a fem::Problem: a displacement of three components over any scalar C1 space on a
// surface in 3D or a planar domain (a plate) (the forms: pde/shell/forms.hpp), loads per unit area, pressure, line loads on boundary parts and
// point loads, supports per displacement component on boundary parts (strongly, the L2 projection onto the traces,
// as elasticity's), free edges elsewhere.
#include <array>
#include <memory>
#include <string>
#include <vector>

#include "fem/function.hpp"
#include "fem/problem.hpp"
#include "pde/shell/forms.hpp"

namespace iga::pde {

/// What a support holds of component c on its parts.
enum class Hold {
  kValue,          ///< u_c = value
  kValueAndSlope,  ///< u_c = 0 and ∂u_c/∂n = 0: the three components so held are a clamped edge
  kSlope,          ///< ∂u_c/∂n = 0 alone: with kValue on the plane's normal component, a symmetry plane
};

/// A support of component c (0 is x, 1 y, 2 z) on boundary parts (Space::boundary_part_names() indices). A rigid
/// diaphragm in the plane y = const holds the values of u_x and u_z; a symmetry plane normal to axis c holds the value
/// of u_c and the slopes of the other two (they are even across the plane), which fixes the rotation about the edge; a
/// clamped edge holds value and slope of all three. Slopes are held as ∫_Γ ∂_n u ∂_n φ_s = 0 for every function φ_s
/// with a slope on Γ (exactly ∂_n u = 0 on Γ when the slopes' traces span ∂_n u's, as on B-spline and NURBS patches),
/// eliminated together with the other conditions of the component (fem::linear_conditions). A component may have
/// several supports holding 0; one with a value must be its only one.
struct ShellSupport {
  int component = 0;
  std::vector<int> parts;
  std::shared_ptr<const fem::Function> value;  ///< null: 0 (kValue only)
  Hold hold = Hold::kValue;
};

/// q = (q_x, q_y, q_z)(x, n) per unit length on the parts; null components 0.
struct ShellLineLoad {
  std::vector<int> parts;
  std::array<std::shared_ptr<const fem::BoundaryFunction>, 3> load;
};

/// A force at a point of the surface (located to 1e-6 of the net's extent, or ShellData::point_allowance:
/// basis::locate_point).
struct ShellPointLoad {
  Eigen::Vector3d at = Eigen::Vector3d::Zero();
  Eigen::Vector3d force = Eigen::Vector3d::Zero();
};

/// u_c = 0 at one point of the surface (located as a point load): Σ_a φ_a(x) u_{a,c} = 0, one coupled condition (a
/// bearing that holds the shell in one direction, e.g. the axial direction of a roof on two diaphragms).
struct ShellPointSupport {
  Eigen::Vector3d at = Eigen::Vector3d::Zero();
  int component = 0;
};

struct ShellData {
  ShellMaterial material;
  std::array<std::shared_ptr<const fem::Function>, 3> area_load;  ///< per unit area; null components 0
  std::shared_ptr<const fem::Function> pressure;                  ///< along the unit normal a_3; null: none
  std::vector<ShellLineLoad> line_loads;
  std::vector<ShellPointLoad> point_loads;
  /// At most one support per component (one condition over all its parts).
  std::vector<ShellSupport> supports;
  std::vector<ShellPointSupport> point_supports;
  /// How far the points of point loads and supports may lie from the surface besides 1e-6 of the net's extent: for
  /// a geometry fitted to an exact shape whose points are given on the shape (iga-shell: twice --fit-to's distance).
  double point_allowance = 0.0;
};

/// The problem for the pipeline, on a surface in 3D or a planar domain (a plate in the plane z = 0, its normal
/// ±e_z as the map's orientation gives it). check() refuses, with one line: a space that is not C1, E ≤ 0, ν outside (−1, 1/2], t ≤ 0, a part that does not exist, a component outside
/// 0..2 or supported twice, a point load off the surface; constraints() refuses supports that leave a rigid-body mode
/// free (a translation or a rotation about an axis), naming it.
std::shared_ptr<const fem::Problem> make_shell(ShellData data);

/// The displacement of coefficients u (interleaved, 3 per function) at reference point uv of element e.
Eigen::Vector3d shell_displacement(const basis::Space& space, const Eigen::VectorXd& u, Index e,
                                   const Eigen::Vector2d& uv);

}  // namespace iga::pde
