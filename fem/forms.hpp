#pragma once
// Forms are small function objects that turn what the element loop evaluated into a local matrix or
// vector (DESIGN.md: "a new PDE is a new form, not a new loop").
#include <Eigen/Core>
#include <functional>
#include <memory>
#include <vector>

#include "basis/basis_values.hpp"
#include "basis/geometry.hpp"
#include "core/types.hpp"
#include "fem/function.hpp"
#include "quadrature/rule.hpp"

namespace iga::fem {

/// What the element loop has evaluated on one element at its quadrature points.
struct ElementContext {
  Index element = 0;
  const quadrature::Rule* rule = nullptr;
  basis::BasisValues basis;   ///< local functions (nloc × q) and parametric derivatives
  basis::GeometryValues geo;  ///< physical points, Jacobian, measure, normal
  Eigen::VectorXd weight;     ///< physical quadrature weights: rule weight × measure
  /// Physical (surface) gradients of the local functions, nloc × (dim·q): columns c·q .. c·q+q-1 hold
  /// component c at the q points (one block per component, so a stiffness matrix is one dense product).
  Eigen::MatrixXd grad;
  int dim = 2;  ///< number of gradient components stored: 2 (planar) or 3 (surface)
  int derivatives = 1;  ///< what was prepared: 1 (values, gradients) or 2 (also laplacian, hessian)
  /// derivatives 2: the Laplacian of each local function (nloc × q) through the map — on surfaces the
  /// Laplace–Beltrami operator Δ_Γ φ = g^{ij} (φ_{,ij} − Γ^k_{ij} φ_{,k}), Γ^k_{ij} = g^{kl} x_{,l} · x_{,ij}.
  Eigen::MatrixXd laplacian;
  /// derivatives 2, planar domains only: physical Hessians, nloc × (3q) as blocks xx, xy, yy (like grad),
  /// H_x φ = J^{-T} (H_u φ − Σ_k ∂φ/∂x_k H_u x_k) J^{-1}. Empty on surfaces (only Δ_Γ is supported there).
  Eigen::MatrixXd hessian;
  /// Block b of the Hessians (0 xx, 1 xy, 2 yy), nloc × q.
  auto hessian_block(int b) const { return hessian.middleCols(b * num_points(), num_points()); }

  Eigen::Index num_points() const { return weight.size(); }
  /// Component c of the gradients (nloc × q).
  auto grad_component(int c) const { return grad.middleCols(c * num_points(), num_points()); }
};

/// What the boundary loop has evaluated on one element side.
struct BoundaryContext {
  Index element = 0;
  int side = 0;
  basis::BasisValues basis;
  basis::GeometryValues geo;
  Eigen::VectorXd weight;     ///< rule weight × |dx/dt| (arc length)
  Eigen::Matrix3Xd conormal;  ///< outward unit conormal: unit tangent × unit normal
  int dim = 2;          ///< as ElementContext::dim
  int derivatives = 1;  ///< what was prepared: 1, or 2 (then also grad, laplacian and, planar, hessian)
  /// derivatives 2: the same blocks as ElementContext's, at the side's points.
  Eigen::MatrixXd grad, laplacian, hessian;
};

/// What a form needs from the element loop (deal.II's update flags): derivatives() 1 for values and gradients, 2 for
/// the Laplacians and (planar) Hessians through the map as well, the loop preparing the largest its forms ask for;
/// components() the number of components of the field it is written for (the local matrix is then
/// (components · nloc)², interleaved: local index components · a + c for function a and component c). The loop
/// refuses a form whose components differ from its own.
class FormNeeds {
 public:
  virtual ~FormNeeds() = default;
  virtual int derivatives() const { return 1; }
  /// With derivatives() 2: whether the form reads the (planar) Hessians, or the Laplacians only (cheaper: the loop
  /// then skips the Hessians unless another form asks for them).
  virtual bool hessian() const { return derivatives() >= 2; }
  virtual int components() const { return 1; }
  /// The functions the form integrates over the domain (a source, a coefficient): the assembler checks each over
  /// the whole domain after its element loop (fem/data_check.hpp). None by default.
  virtual std::vector<const Function*> data() const { return {}; }
};

class BilinearForm : public FormNeeds {
 public:
  /// local (nloc × nloc, zeroed by the caller) += the form's element matrix.
  virtual void add(const ElementContext& ctx, Eigen::MatrixXd& local) const = 0;
};

class LinearForm : public FormNeeds {
 public:
  virtual void add(const ElementContext& ctx, Eigen::VectorXd& local) const = 0;
};

class BoundaryBilinearForm : public FormNeeds {
 public:
  virtual void add(const BoundaryContext& ctx, Eigen::MatrixXd& local) const = 0;
};

class BoundaryLinearForm : public FormNeeds {
 public:
  virtual void add(const BoundaryContext& ctx, Eigen::VectorXd& local) const = 0;
};

/// ∫ a ∇φ_i · ∇φ_j (a = 1 without coefficient); on surfaces the surface gradient (Laplace–Beltrami).
class StiffnessForm final : public BilinearForm {
 public:
  explicit StiffnessForm(std::shared_ptr<const Function> coefficient = nullptr) : a_(std::move(coefficient)) {}
  void add(const ElementContext& ctx, Eigen::MatrixXd& local) const override;
  std::vector<const Function*> data() const override { return a_ ? std::vector<const Function*>{a_.get()} : std::vector<const Function*>{}; }

 private:
  std::shared_ptr<const Function> a_;
};

/// ∫ c φ_i φ_j with a constant c.
class MassForm final : public BilinearForm {
 public:
  explicit MassForm(double c = 1.0) : c_(c) {}
  void add(const ElementContext& ctx, Eigen::MatrixXd& local) const override;

 private:
  double c_;
};

/// ∫ f φ_i.
class SourceForm final : public LinearForm {
 public:
  explicit SourceForm(std::shared_ptr<const Function> f) : f_(std::move(f)) {}
  void add(const ElementContext& ctx, Eigen::VectorXd& local) const override;
  std::vector<const Function*> data() const override { return f_ ? std::vector<const Function*>{f_.get()} : std::vector<const Function*>{}; }

 private:
  std::shared_ptr<const Function> f_;
};

/// ∫_Γ φ_i φ_j ds.
class BoundaryMassForm final : public BoundaryBilinearForm {
 public:
  void add(const BoundaryContext& ctx, Eigen::MatrixXd& local) const override;
};

/// ∫_Γ g φ_i ds with g(x) (Dirichlet projection) or g(x, n) (Neumann flux, n the outward conormal).
class BoundaryLoadForm final : public BoundaryLinearForm {
 public:
  explicit BoundaryLoadForm(std::shared_ptr<const Function> g) : g_(std::move(g)) {}
  explicit BoundaryLoadForm(std::shared_ptr<const BoundaryFunction> g) : gn_(std::move(g)) {}
  void add(const BoundaryContext& ctx, Eigen::VectorXd& local) const override;

 private:
  std::shared_ptr<const Function> g_;
  std::shared_ptr<const BoundaryFunction> gn_;
};

/// Nitsche's method for u = g on Γ_D (Nitsche 1971; the symmetric variant, as in IgA by Embar, Dolbow and
/// Harari 2010): ∫_Γ −(∂_n φ_j) φ_i − φ_j (∂_n φ_i) + β φ_i φ_j ds, ∂_n the derivative along the outward
/// conormal and β = penalty(side) per element side (γ / h with a fixed γ, or a local estimate: see
/// fem/poisson.hpp). Consistent (the exact solution satisfies the weak form) and coercive when β exceeds twice
/// the side's inverse-estimate constant. For spaces whose traces cannot carry strong conditions.
using NitschePenalty = std::function<double(const BoundaryContext&)>;

/// ∂_n φ_i at the side's points (nloc × q): the physical gradient tu φ_u + tv φ_v against the conormal.
void conormal_derivatives(const BoundaryContext& ctx, Eigen::MatrixXd& dn);

class NitscheForm final : public BoundaryBilinearForm {
 public:
  explicit NitscheForm(NitschePenalty penalty) : penalty_(std::move(penalty)) {}
  void add(const BoundaryContext& ctx, Eigen::MatrixXd& local) const override;

 private:
  NitschePenalty penalty_;
};

/// Its right-hand side: ∫_Γ g (−∂_n φ_i + β φ_i) ds.
class NitscheLoadForm final : public BoundaryLinearForm {
 public:
  NitscheLoadForm(std::shared_ptr<const Function> g, NitschePenalty penalty) : g_(std::move(g)), penalty_(std::move(penalty)) {}
  void add(const BoundaryContext& ctx, Eigen::VectorXd& local) const override;

 private:
  std::shared_ptr<const Function> g_;
  NitschePenalty penalty_;
};

}  // namespace iga::fem
