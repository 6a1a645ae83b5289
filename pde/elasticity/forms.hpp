#pragma once
// The forms of plane linear elasticity: a displacement field u = (u_x, u_y) of two components over one scalar space
// (fem::Assembler with components 2, dofs interleaved: local index 2a + c), σ = λ tr(ε) I + 2μ ε with
// ε = (∇u + ∇uᵀ)/2. Plane strain takes λ, μ of E, ν; plane stress the same law with λ* = 2λμ/(λ + 2μ).
#include <array>
#include <memory>

#include "fem/forms.hpp"
#include "fem/function.hpp"

namespace iga::pde {

/// The in-plane Lamé constants of a material and a plane model.
struct Lame {
  double lambda = 0.0, mu = 0.0;
};
enum class PlaneModel { kStrain, kStress };
/// From Young's modulus E and Poisson's ratio ν: μ = E / (2(1 + ν)); plane strain λ = E ν / ((1 + ν)(1 − 2ν)),
/// plane stress λ* = E ν / (1 − ν²). InputError for E <= 0 or not finite, ν outside (−1, 1/2).
Lame lame(double young, double poisson, PlaneModel model);

/// ∫ σ(φ_b e_j) : ε(φ_a e_i): entry (2a + i, 2b + j) = λ ∂_iφ_a ∂_jφ_b + μ (δ_ij ∇φ_a·∇φ_b + ∂_jφ_a ∂_iφ_b).
class ElasticityForm final : public fem::BilinearForm {
 public:
  explicit ElasticityForm(Lame lame) : lame_(lame) {}
  int components() const override { return 2; }
  void add(const fem::ElementContext& ctx, Eigen::MatrixXd& local) const override;

 private:
  Lame lame_;
};

/// ∫ b_i φ_a at 2a + i: a body force (null components are 0).
class BodyForceForm final : public fem::LinearForm {
 public:
  explicit BodyForceForm(std::array<std::shared_ptr<const fem::Function>, 2> b) : b_(std::move(b)) {}
  int components() const override { return 2; }
  std::vector<const fem::Function*> data() const override {
    std::vector<const fem::Function*> d;
    for (const auto& c : b_) {
      if (c) d.push_back(c.get());
    }
    return d;
  }
  void add(const fem::ElementContext& ctx, Eigen::VectorXd& local) const override;

 private:
  std::array<std::shared_ptr<const fem::Function>, 2> b_;
};

/// ∫_Γ t_i φ_a ds at 2a + i: a traction t(x, n) (n the outward normal; null components are 0).
class TractionForm final : public fem::BoundaryLinearForm {
 public:
  explicit TractionForm(std::array<std::shared_ptr<const fem::BoundaryFunction>, 2> t) : t_(std::move(t)) {}
  int components() const override { return 2; }
  void add(const fem::BoundaryContext& ctx, Eigen::VectorXd& local) const override;

 private:
  std::array<std::shared_ptr<const fem::BoundaryFunction>, 2> t_;
};

}  // namespace iga::pde
