#pragma once
// The forms of the biharmonic equation Δ²u = f on planar domains, from Green's formula twice:
//   ∫ Δ²u v = ∫ Δu Δv + ∫_Γ ∂_n(Δu) v − ∫_Γ Δu ∂_n v.
// With u = g imposed strongly (v = 0 on Γ) two conditions remain per boundary part:
// - clamped, ∂_n u = h: by Nitsche's method (Nitsche 1971; for fourth-order problems in IgA, Embar, Dolbow and
//   Harari 2010), symmetric, a(u, v) = ∫ Δu Δv − ∫_Γ (Δu ∂_n v + ∂_n u Δv) + β ∫_Γ ∂_n u ∂_n v and
//   l(v) = ∫ f v − ∫_Γ h Δv + β ∫_Γ h ∂_n v: consistent, and coercive when β exceeds twice the side's inverse
//   constant of ‖Δv‖_Γ ≤ C ‖Δv‖_K (fem::local_penalties gives β_K = 4 λ_max);
// - simply supported (Navier), Δu = m: natural, l(v) += ∫_Γ m ∂_n v.
// Forms ask for second derivatives (FormNeeds::derivatives() = 2); the loop prepares them.
#include <memory>

#include "fem/forms.hpp"
#include "fem/function.hpp"

namespace iga::pde {

/// ∫ Δφ_i Δφ_j.
class BiharmonicForm final : public fem::BilinearForm {
 public:
  int derivatives() const override { return 2; }
  bool hessian() const override { return false; }
  void add(const fem::ElementContext& ctx, Eigen::MatrixXd& local) const override;
};

/// Nitsche's terms of ∂_n u = h: −∫_Γ (Δφ_j ∂_n φ_i + ∂_n φ_j Δφ_i) + β ∫_Γ ∂_n φ_i ∂_n φ_j.
class ClampedNitscheForm final : public fem::BoundaryBilinearForm {
 public:
  explicit ClampedNitscheForm(fem::NitschePenalty penalty) : penalty_(std::move(penalty)) {}
  int derivatives() const override { return 2; }
  bool hessian() const override { return false; }
  void add(const fem::BoundaryContext& ctx, Eigen::MatrixXd& local) const override;

 private:
  fem::NitschePenalty penalty_;
};

/// Their load: ∫_Γ h (−Δφ_i + β ∂_n φ_i), h = slope(x, n).
class ClampedNitscheLoad final : public fem::BoundaryLinearForm {
 public:
  ClampedNitscheLoad(std::shared_ptr<const fem::BoundaryFunction> slope, fem::NitschePenalty penalty)
      : slope_(std::move(slope)), penalty_(std::move(penalty)) {}
  int derivatives() const override { return 2; }
  bool hessian() const override { return false; }
  void add(const fem::BoundaryContext& ctx, Eigen::VectorXd& local) const override;

 private:
  std::shared_ptr<const fem::BoundaryFunction> slope_;
  fem::NitschePenalty penalty_;
};

/// The natural load of a simply supported part: ∫_Γ m ∂_n φ_i, m = Δu there.
class MomentLoad final : public fem::BoundaryLinearForm {
 public:
  explicit MomentLoad(std::shared_ptr<const fem::Function> m) : m_(std::move(m)) {}
  void add(const fem::BoundaryContext& ctx, Eigen::VectorXd& local) const override;

 private:
  std::shared_ptr<const fem::Function> m_;
};

}  // namespace iga::pde
