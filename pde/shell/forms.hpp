#pragma once
// The forms of the linear Kirchhoff–Love shell (Kiendl, Bletzinger, Linhard and Wüchner 2009, "Isogeometric shell
// analysis with Kirchhoff–Love elements", CMAME 198, §2–3): a displacement u of three components over one scalar
// C1 space on a surface x(θ¹, θ²) in 3D (fem::Assembler with components 3, local index 3a + c), no rotational
// dofs. With the covariant base a_α = x_,α, the unit normal a_3 = a_1 × a_2 / ā (ā = |a_1 × a_2|) and the
// curvature b_αβ = x_,αβ · a_3, the linearised strains are
//   membrane  ε_αβ = ½ (a_α · u_,β + a_β · u_,α),
//   bending   κ_αβ = u_,αβ · a_3 + x_,αβ · δa_3,  δa_3 = (I − a_3 a_3ᵀ)(u_,1 × a_2 + a_1 × u_,2) / ā,
// so x_,αβ · δa_3 = [u_,1 · (a_2 × p_αβ) + u_,2 · (p_αβ × a_1)] / ā with p_αβ = x_,αβ − b_αβ a_3 (the tangential
// part of x_,αβ). The energy is ½ ∫ (t εᵀ D ε + t³/12 κᵀ D κ) dA in Voigt order (11, 22, 2·12) with the
// isotropic law in the contravariant metric a^αβ:
//   D = E/(1 − ν²) [ (a¹¹)²                 ν a¹¹a²² + (1 − ν)(a¹²)²   a¹¹a¹²
//                    ·                      (a²²)²                     a²²a¹²
//                    ·                      ·                          ½ ((1 − ν) a¹¹a²² + (1 + ν)(a¹²)²) ].
// Both strains vanish on the rigid motions u = c + ω × x (tests/pde/test_shell.cpp checks the assembled matrix on
// them), and on a plane the bending part is the Kirchhoff plate's D_p Δ²w with D_p = E t³ / (12 (1 − ν²)).
#include <array>
#include <memory>

#include "fem/forms.hpp"
#include "fem/function.hpp"

namespace iga::pde {

/// A linear isotropic shell material: Young's modulus E, Poisson's ratio ν, thickness t.
struct ShellMaterial {
  double young = 1.0, poisson = 0.0, thickness = 1.0;
};

/// ∫ t ε(φ_b e_j)ᵀ D ε(φ_a e_i) + t³/12 κ(φ_b e_j)ᵀ D κ(φ_a e_i) dA at (3a + i, 3b + j).
class KirchhoffLoveForm final : public fem::BilinearForm {
 public:
  explicit KirchhoffLoveForm(ShellMaterial material) : m_(material) {}
  int components() const override { return 3; }
  int derivatives() const override { return 2; }
  bool hessian() const override { return false; }
  void add(const fem::ElementContext& ctx, Eigen::MatrixXd& local) const override;

 private:
  ShellMaterial m_;
};

/// ∫ f_i φ_a dA at 3a + i: a load per unit area f(x) (self-weight: (0, 0, −g ρ t)), null components 0; plus
/// ∫ p n_i φ_a dA for a pressure p(x) along the unit normal a_3 (null: none).
class ShellLoadForm final : public fem::LinearForm {
 public:
  ShellLoadForm(std::array<std::shared_ptr<const fem::Function>, 3> area, std::shared_ptr<const fem::Function> pressure)
      : f_(std::move(area)), p_(std::move(pressure)) {}
  int components() const override { return 3; }
  std::vector<const fem::Function*> data() const override;
  void add(const fem::ElementContext& ctx, Eigen::VectorXd& local) const override;

 private:
  std::array<std::shared_ptr<const fem::Function>, 3> f_;
  std::shared_ptr<const fem::Function> p_;
};

/// ∫_Γ q_i φ_a ds at 3a + i: a load per unit length q(x, n) on boundary parts (n the outward conormal), null
/// components 0.
class ShellLineLoadForm final : public fem::BoundaryLinearForm {
 public:
  explicit ShellLineLoadForm(std::array<std::shared_ptr<const fem::BoundaryFunction>, 3> q) : q_(std::move(q)) {}
  int components() const override { return 3; }
  void add(const fem::BoundaryContext& ctx, Eigen::VectorXd& local) const override;

 private:
  std::array<std::shared_ptr<const fem::BoundaryFunction>, 3> q_;
};

/// The membrane strains (ε_11, ε_22, 2ε_12) and curvature changes (κ_11, κ_22, 2κ_12) of a displacement at one point,
/// from its parametric derivatives (du = u_,1, dv = u_,2, duu, duv, dvv, each a 3-vector) and the map's (xu, xv,
/// xuu, xuv, xvv): the definitions above, for the output of forces and moments.
struct ShellStrains {
  Eigen::Vector3d membrane, bending;
  Eigen::Matrix3d material;  ///< D at the point (without t)
  Eigen::Vector3d normal;    ///< a_3
};
ShellStrains shell_strains(const Eigen::Vector3d& xu, const Eigen::Vector3d& xv, const Eigen::Vector3d& xuu,
                           const Eigen::Vector3d& xuv, const Eigen::Vector3d& xvv, const Eigen::Vector3d& du,
                           const Eigen::Vector3d& dv, const Eigen::Vector3d& duu, const Eigen::Vector3d& duv,
                           const Eigen::Vector3d& dvv, const ShellMaterial& material);

}  // namespace iga::pde
