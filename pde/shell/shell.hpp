#pragma once
// The linear Kirchhoff–Love shell as a fem::Problem: a displacement of three components over any scalar C1 space on a
// surface in 3D (the forms: pde/shell/forms.hpp), loads per unit area, pressure, line loads on boundary parts and
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

/// u_c = value on the boundary parts (Space::boundary_part_names() indices); component 0 is x, 1 y, 2 z. A rigid
/// diaphragm in the plane x = const is {1, ...} and {2, ...}: the displacements in its plane are held.
struct ShellSupport {
  int component = 0;
  std::vector<int> parts;
  std::shared_ptr<const fem::Function> value;  ///< null: 0
};

/// q = (q_x, q_y, q_z)(x, n) per unit length on the parts; null components 0.
struct ShellLineLoad {
  std::vector<int> parts;
  std::array<std::shared_ptr<const fem::BoundaryFunction>, 3> load;
};

/// A force at a point of the surface (located to 1e-6 of the net's extent: basis::locate_point).
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
};

/// The problem for the pipeline. check() refuses, with one line: a planar geometry (give the surface's three
/// coordinates, z = 0 for a plate), E ≤ 0, ν outside (−1, 1/2], t ≤ 0, a part that does not exist, a component outside
/// 0..2 or supported twice, a point load off the surface; constraints() refuses supports that leave a rigid-body mode
/// free (a translation or a rotation about an axis), naming it.
std::shared_ptr<const fem::Problem> make_shell(ShellData data);

/// The displacement of coefficients u (interleaved, 3 per function) at reference point uv of element e.
Eigen::Vector3d shell_displacement(const basis::Space& space, const Eigen::VectorXd& u, Index e,
                                   const Eigen::Vector2d& uv);

}  // namespace iga::pde
