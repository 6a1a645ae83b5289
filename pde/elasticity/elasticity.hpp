#pragma once
// Plane linear elasticity −div σ(u) = b as a fem::Problem: a displacement field of two components over any scalar
// space (C0 suffices), displacement conditions per component on named boundary parts (strongly, the L2 projection
// onto the traces, coupled where the traces are: polyhedral and half-box boundaries), tractions t(x, n) on named
// parts (natural), traction-free elsewhere. The forms: pde/elasticity/forms.hpp.
#include <array>
#include <functional>
#include <memory>
#include <vector>

#include "fem/function.hpp"
#include "fem/problem.hpp"
#include "pde/elasticity/forms.hpp"

namespace iga::pde {

/// u_c = value on the boundary parts `parts` (Space::boundary_part_names() indices); component 0 is x, 1 is y.
struct DisplacementCondition {
  int component = 0;
  std::vector<int> parts;
  std::shared_ptr<const fem::Function> value;  ///< null: 0 (a symmetry plane or a fixed edge)
};

/// t = (t_x, t_y)(x, n) on the parts (n the outward unit normal); null components are 0.
struct TractionCondition {
  std::vector<int> parts;
  std::array<std::shared_ptr<const fem::BoundaryFunction>, 2> traction;
};

struct ElasticityData {
  double young = 1.0, poisson = 0.3;
  PlaneModel model = PlaneModel::kStrain;
  std::array<std::shared_ptr<const fem::Function>, 2> body_force;  ///< b; null components 0
  /// At most one condition per component (one expression over all its parts).
  std::vector<DisplacementCondition> displacement;
  std::vector<TractionCondition> traction;
  /// Optional: the exact displacement (with gradients, exact or differenced) for the error figures L2, H1 (the two
  /// components together and each), and energy (∫ (σ − σ_h) : (ε − ε_h))^½.
  std::array<std::shared_ptr<const fem::Function>, 2> exact;
};

/// The traction σ(u) n of a displacement with gradients, per component: manufactured or exact Neumann data.
std::array<std::shared_ptr<const fem::BoundaryFunction>, 2> traction_of(
    std::array<std::shared_ptr<const fem::Function>, 2> u, Lame lame);

/// The problem for the pipeline. check() refuses, with one line: a surface (planar only), E or ν out of range, a part
/// that does not exist, a component outside 0..1 or prescribed twice; constraints() refuses conditions that leave a
/// rigid-body mode free (a translation or a rotation about a named point), the solve being singular otherwise.
std::shared_ptr<const fem::Problem> make_elasticity(ElasticityData data);

/// Stress (σ_xx, σ_yy, σ_xy) of the discrete displacement at reference point `uv` of element e (u the field's
/// coefficients, interleaved); plane stress σ_zz = 0, plane strain σ_zz = ν(σ_xx + σ_yy) is not included.
Eigen::Vector3d stress_at(const basis::Geometry& geometry, const Eigen::VectorXd& u, Index e,
                          const Eigen::Vector2d& uv, Lame lame);

/// What a writer shows of a displacement at the points where the basis (with first derivatives) and the map were
/// evaluated on element e: displacement 3 × q (z = 0), stress 6 × q in ParaView's symmetric-tensor order XX, YY, ZZ,
/// XY, YZ, XZ (σ_zz = 0 in plane stress, ν (σ_xx + σ_yy) in plane strain: pass nu_zz = ν there, 0 otherwise), and
/// von Mises' stress (q) of that three-dimensional state.
void displacement_and_stress(const basis::Space& space, const Eigen::VectorXd& u, Index e,
                             const basis::BasisValues& bv, const basis::GeometryValues& gv, Lame lame, double nu_zz,
                             Eigen::MatrixXd& displacement, Eigen::MatrixXd& stress, Eigen::VectorXd& von_mises);

/// One of displacement_and_stress's outputs as a sampled writer's field values (io::SampledField::values): which 0 the
/// displacement (3 × q), 1 the stress (6 × q), 2 von Mises' stress (1 × q). Keeps references to space and u.
std::function<void(Index e, const basis::BasisValues& bv, const basis::GeometryValues& gv, Eigen::MatrixXd& out)>
elasticity_sampler(const basis::Space& space, const Eigen::VectorXd& u, Lame lame, double nu_zz, int which);

}  // namespace iga::pde
