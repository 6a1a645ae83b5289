#include "pde/elasticity/elasticity.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <sstream>

#include "core/error.hpp"
#include "fem/dirichlet.hpp"
#include "fem/linear_system.hpp"

namespace iga::pde {

namespace {

// σ = (σ_xx, σ_yy, σ_xy) of the displacement gradient g[c][j] = ∂_j u_c: λ tr(ε) I + 2μ ε.
Eigen::Vector3d stress_of(const double (&g)[2][2], Lame lame) {
  const double exx = g[0][0], eyy = g[1][1], exy = 0.5 * (g[0][1] + g[1][0]);
  const double tr = lame.lambda * (exx + eyy);
  return {tr + 2 * lame.mu * exx, tr + 2 * lame.mu * eyy, 2 * lame.mu * exy};
}

class Traction final : public fem::BoundaryFunction {
 public:
  Traction(std::array<std::shared_ptr<const fem::Function>, 2> u, Lame lame, int component)
      : u_(std::move(u)), lame_(lame), c_(component) {}
  void values(const Eigen::Matrix3Xd& x, const Eigen::Matrix3Xd& n, Eigen::VectorXd& out) const override {
    Eigen::Matrix3Xd gx, gy;
    u_[0]->partial_gradients(x, 2, gx);
    u_[1]->partial_gradients(x, 2, gy);
    out.resize(x.cols());
    for (Eigen::Index k = 0; k < x.cols(); ++k) {
      const double g[2][2] = {{gx(0, k), gx(1, k)}, {gy(0, k), gy(1, k)}};
      const Eigen::Vector3d sigma = stress_of(g, lame_);
      out(k) = c_ == 0 ? sigma(0) * n(0, k) + sigma(2) * n(1, k) : sigma(2) * n(0, k) + sigma(1) * n(1, k);
    }
  }

 private:
  std::array<std::shared_ptr<const fem::Function>, 2> u_;
  Lame lame_;
  int c_;
};

class Elasticity final : public fem::Problem {
 public:
  explicit Elasticity(ElasticityData data) : d_(std::move(data)) {
    lame_ = lame(d_.young, d_.poisson, d_.model);  // InputError for E, ν out of range
    form_ = std::make_unique<ElasticityForm>(lame_);
    if (d_.body_force[0] || d_.body_force[1]) body_ = std::make_unique<BodyForceForm>(d_.body_force);
  }
  std::string name() const override { return "elasticity"; }
  int components() const override { return 2; }

  void check(const basis::Geometry& geometry) const override {
    if (geometry.dim() != 2) throw UnsupportedError("elasticity: planar domains only (this geometry is a surface)");
    names_ = geometry.space().boundary_part_names();
    const int parts = static_cast<int>(names_.size());
    auto check_parts = [&](const std::vector<int>& list, const std::string& what) {
      if (list.empty()) throw InputError("elasticity: " + what + " names no boundary part");
      for (int p : list) {
        if (p < 0 || p >= parts) {
          throw InputError("elasticity: " + what + ": boundary part " + std::to_string(p) + " does not exist (" +
                           std::to_string(parts) + " parts)");
        }
      }
    };
    bool seen[2] = {false, false};
    for (const DisplacementCondition& c : d_.displacement) {
      if (c.component < 0 || c.component > 1) {
        throw InputError("elasticity: displacement component " + std::to_string(c.component) + " (0 is x, 1 is y)");
      }
      const std::string what = std::string("displacement u_") + (c.component ? "y" : "x");
      check_parts(c.parts, what);
      if (seen[c.component]) {
        throw InputError("elasticity: " + what + " is prescribed twice: give it one condition over all its parts");
      }
      seen[c.component] = true;
    }
    for (const TractionCondition& t : d_.traction) check_parts(t.parts, "traction");
    edges_ = geometry.space().boundary_edges();
  }

  std::vector<const fem::BilinearForm*> bilinear_forms() const override { return {form_.get()}; }
  std::vector<const fem::LinearForm*> linear_forms() const override {
    if (body_) return {body_.get()};
    return {};
  }

  void add_boundary_terms(const fem::Assembler& assembler, fem::LinearSystem& system,
                          fem::Choices& choices) const override {
    std::ostringstream material;
    material << (d_.model == PlaneModel::kStrain ? "plane strain" : "plane stress") << ", E = " << d_.young
             << ", nu = " << d_.poisson << " (lambda = " << lame_.lambda << ", mu = " << lame_.mu << ")";
    choices.emplace_back("material", material.str());
    const Eigen::SparseMatrix<double> none;
    for (const TractionCondition& t : d_.traction) {
      const TractionForm form(t.traction);
      Eigen::VectorXd b;
      assembler.assemble_boundary(on(t.parts), nullptr, &form, nullptr, &b);
      system.add(none, b);
      choices.emplace_back("traction", fem::part_names(t.parts, names_));
    }
  }

  fem::DirichletConditions constraints(const fem::Assembler& assembler, fem::Choices& choices) const override {
    // Each component's condition projected with a scalar assembler on the same geometry and rules.
    const fem::Assembler scalar(assembler.geometry(), assembler.rules());
    std::vector<fem::DirichletConditions> sets;
    for (const DisplacementCondition& c : d_.displacement) {
      const fem::DirichletConditions s =
          fem::project_dirichlet(scalar, on(c.parts), c.value ? c.value : fem::constant_function(0.0));
      sets.push_back(fem::component_conditions(s, c.component, 2));
      choices.emplace_back(std::string("displacement u_") + (c.component ? "y" : "x"),
                           fem::part_names(c.parts, names_) + ": strong (L2 projection)");
    }
    fem::DirichletConditions bc = fem::merge_conditions(sets, assembler.num_dofs());
    refuse_rigid_modes(assembler.geometry(), bc);
    return bc;
  }

  std::vector<std::string> error_names() const override {
    if (!d_.exact[0] || !d_.exact[1]) return {};
    return {"L2", "L2 x", "L2 y", "H1", "H1 x", "H1 y", "energy"};
  }
  std::vector<std::string> error_derivatives() const override {
    if (!d_.exact[0] || !d_.exact[1]) return {};
    const std::string x = d_.exact[0]->derivative_method(1), y = d_.exact[1]->derivative_method(1);
    const std::string both = x == y ? x : "x: " + x + "; y: " + y;
    return {"values", "values", "values", both, x, y, both};
  }
  Eigen::VectorXd error_squares(const fem::Assembler& by, const Eigen::VectorXd& u,
                                const fem::LinearSystem& system) const override {
    return fem::summed_squares(system, [&](const std::vector<char>* only) { return squares(by, u, only); });
  }

 private:
  std::vector<basis::BoundaryEdge> on(const std::vector<int>& parts) const { return fem::edges_on(edges_, parts); }
  void refuse_rigid_modes(const basis::Geometry& geometry, const fem::DirichletConditions& bc) const;
  Eigen::VectorXd squares(const fem::Assembler& by, const Eigen::VectorXd& u, const std::vector<char>* only) const;

  ElasticityData d_;
  Lame lame_;
  std::unique_ptr<ElasticityForm> form_;
  std::unique_ptr<BodyForceForm> body_;
  mutable std::vector<std::string> names_;
  mutable std::vector<basis::BoundaryEdge> edges_;
};

// The rigid-body modes of the plane, in the space: translations (1, 0) and (0, 1) at every function (partition of
// unity) and the rotation (−y, x), whose coefficients are the control points' (the isoparametric map reproduces
// x and y). A combination that every condition leaves unchanged (C r = 0 for the homogeneous conditions
// u_S + coupling u = 0) is a free mode: the stiffness matrix is singular on it.
void Elasticity::refuse_rigid_modes(const basis::Geometry& geometry, const fem::DirichletConditions& bc) const {
  if (bc.dofs.empty()) {
    throw InputError("elasticity: no displacement condition: the rigid-body modes (translations and the rotation) "
                     "are free; prescribe u_x and u_y on some boundary part");
  }
  const Eigen::MatrixXd& p = geometry.control_points();
  const Index n = p.rows();
  Eigen::MatrixXd modes = Eigen::MatrixXd::Zero(2 * n, 3);
  for (Index i = 0; i < n; ++i) {
    modes(2 * i, 0) = 1.0;
    modes(2 * i + 1, 1) = 1.0;
    modes(2 * i, 2) = -p(i, 1);
    modes(2 * i + 1, 2) = p(i, 0);
  }
  Eigen::Vector3d scale = modes.colwise().norm().transpose();
  Eigen::MatrixXd c(static_cast<Index>(bc.dofs.size()), 3);
  for (std::size_t k = 0; k < bc.dofs.size(); ++k) c.row(static_cast<Index>(k)) = modes.row(bc.dofs[k]);
  if (bc.coupling.nonZeros() > 0) c += bc.coupling * modes;
  for (int j = 0; j < 3; ++j) c.col(j) /= scale(j);
  const Eigen::JacobiSVD<Eigen::MatrixXd> svd(c, Eigen::ComputeFullV);
  const Eigen::Vector3d s = svd.singularValues();
  if (s(2) > 1e-9 * std::max(s(0), 1e-300) && s(0) > 0) return;
  const Eigen::Vector3d v = svd.matrixV().col(2).cwiseQuotient(scale);  // the free combination, unscaled
  const double extent = p.cwiseAbs().maxCoeff();
  auto clean = [](double x, double unit) { return std::abs(x) < 1e-9 * unit ? 0.0 : x; };  // no "-1e-17" in a message
  std::ostringstream msg;
  msg << "elasticity: the displacement conditions leave a rigid-body mode free (";
  if (std::abs(v(2)) * scale(2) < 1e-6 * v.cwiseProduct(scale).norm()) {
    Eigen::Vector2d t = v.head<2>().normalized();
    if (t(std::abs(t(0)) >= std::abs(t(1)) ? 0 : 1) < 0) t = -t;
    msg << "the translation along (" << clean(t(0), 1.0) << ", " << clean(t(1), 1.0) << ")";
  } else {
    // v0 t_x + v1 t_y + v2 (−y, x) is the rotation about (x0, y0) with v0 = v2 y0, v1 = −v2 x0.
    msg << "the rotation about (" << clean(-v(1) / v(2), extent) << ", " << clean(v(0) / v(2), extent) << ")";
  }
  msg << "): the stiffness matrix is singular; prescribe more components or parts";
  throw InputError(msg.str());
}

Eigen::VectorXd Elasticity::squares(const fem::Assembler& by, const Eigen::VectorXd& u,
                                    const std::vector<char>* only) const {
  const basis::Space& space = by.geometry().space();
  const Lame l = lame_;
  // 7 figures: error² and exact² each (0..13), then the estimates² of finite-difference derivatives (14..20).
  return by.integrate(21, [&](const fem::ElementContext& ctx, Eigen::Ref<Eigen::VectorXd> out) {
    const auto dofs = space.dofs(ctx.element);
    const Index nloc = static_cast<Index>(dofs.size()), q = ctx.num_points();
    Eigen::MatrixXd local(nloc, 2);
    for (Index a = 0; a < nloc; ++a) {
      local(a, 0) = u(2 * dofs[static_cast<std::size_t>(a)]);
      local(a, 1) = u(2 * dofs[static_cast<std::size_t>(a)] + 1);
    }
    Eigen::VectorXd ue[2];
    Eigen::Matrix3Xd ge[2];
    Eigen::MatrixXd uh = ctx.basis.value.transpose() * local;  // q × 2
    Eigen::MatrixXd gh[2];                                     // per component: q × 2 (∂x, ∂y)
    for (int c = 0; c < 2; ++c) {
      d_.exact[static_cast<std::size_t>(c)]->values(ctx.geo.x, ue[c]);
      d_.exact[static_cast<std::size_t>(c)]->partial_gradients(ctx.geo.x, 2, ge[c]);
      gh[c].resize(q, 2);
      for (int k = 0; k < 2; ++k) gh[c].col(k) = ctx.grad_component(k).transpose() * local.col(c);
    }
    const Eigen::VectorXd& w = ctx.weight;
    for (int c = 0; c < 2; ++c) {
      const double l2e = ((ue[c] - uh.col(c)).array().square() * w.array()).sum();
      const double l2x = (ue[c].array().square() * w.array()).sum();
      const Eigen::MatrixXd de = ge[c].topRows(2).transpose() - gh[c];
      const double h1e = (de.rowwise().squaredNorm().array() * w.array()).sum();
      const double h1x = (ge[c].topRows(2).colwise().squaredNorm().transpose().array() * w.array()).sum();
      out(2 + 2 * c) = l2e;  // "L2 x", "L2 y"
      out(3 + 2 * c) = l2x;
      out(8 + 2 * c) = h1e;  // "H1 x", "H1 y"
      out(9 + 2 * c) = h1x;
      out(0) += l2e;
      out(1) += l2x;
      out(6) += h1e;
      out(7) += h1x;
      const fem::Function& exact = *d_.exact[static_cast<std::size_t>(c)];
      if (!exact.exact_gradient()) {  // "H1 x"/"H1 y", H1; energy ≤ (2λ + 2μ) |δ∇u|² pointwise
        Eigen::Matrix3Xd g2;
        exact.difference_gradients(ctx.geo.x, 2 * exact.fd_step(), 2, g2);
        const double est = ((ge[c] - g2).colwise().squaredNorm().transpose().array() * w.array()).sum();
        out(18 + c) += est;
        out(17) += est;
        out(20) += 2 * (l.lambda + l.mu) * est;
      }
    }
    // Energy: λ (tr ε)² + 2μ ε:ε of the error and of the exact field.
    for (Index k = 0; k < q; ++k) {
      const double ex[4] = {ge[0](0, k), ge[0](1, k), ge[1](0, k), ge[1](1, k)};  // ∂x ux, ∂y ux, ∂x uy, ∂y uy
      const double eh[4] = {gh[0](k, 0), gh[0](k, 1), gh[1](k, 0), gh[1](k, 1)};
      auto density = [&](const double* g) {
        const double exx = g[0], eyy = g[3], exy = 0.5 * (g[1] + g[2]);
        return l.lambda * (exx + eyy) * (exx + eyy) + 2 * l.mu * (exx * exx + eyy * eyy + 2 * exy * exy);
      };
      double diff[4];
      for (int i = 0; i < 4; ++i) diff[i] = ex[i] - eh[i];
      out(12) += w(k) * density(diff);
      out(13) += w(k) * density(ex);
    }
  }, 1, only);
}

}  // namespace

std::array<std::shared_ptr<const fem::BoundaryFunction>, 2> traction_of(
    std::array<std::shared_ptr<const fem::Function>, 2> u, Lame lame) {
  return {std::make_shared<Traction>(u, lame, 0), std::make_shared<Traction>(u, lame, 1)};
}

std::shared_ptr<const fem::Problem> make_elasticity(ElasticityData data) {
  return std::make_shared<Elasticity>(std::move(data));
}

Eigen::Vector3d stress_at(const basis::Geometry& geometry, const Eigen::VectorXd& u, Index e,
                          const Eigen::Vector2d& uv, Lame lame) {
  Eigen::Matrix2Xd pts(2, 1);
  pts.col(0) = uv;
  basis::BasisValues bv;
  basis::GeometryValues gv;
  geometry.space().evaluate(e, pts, 1, bv);
  geometry.evaluate(e, bv, gv);
  Eigen::MatrixXd displacement, stress;
  Eigen::VectorXd von_mises;
  displacement_and_stress(geometry.space(), u, e, bv, gv, lame, 0.0, displacement, stress, von_mises);
  return {stress(0, 0), stress(1, 0), stress(3, 0)};
}

void displacement_and_stress(const basis::Space& space, const Eigen::VectorXd& u, Index e,
                             const basis::BasisValues& bv, const basis::GeometryValues& gv, Lame lame, double nu_zz,
                             Eigen::MatrixXd& displacement, Eigen::MatrixXd& stress, Eigen::VectorXd& von_mises) {
  const auto dofs = space.dofs(e);
  const Index q = bv.value.cols();
  Eigen::MatrixXd local(static_cast<Index>(dofs.size()), 2);
  for (std::size_t a = 0; a < dofs.size(); ++a) {
    local(static_cast<Index>(a), 0) = u(2 * dofs[a]);
    local(static_cast<Index>(a), 1) = u(2 * dofs[a] + 1);
  }
  displacement.setZero(3, q);
  displacement.topRows(2) = (bv.value.transpose() * local).transpose();
  const Eigen::MatrixXd du = bv.du.transpose() * local, dv = bv.dv.transpose() * local;  // q × 2
  stress.setZero(6, q);
  von_mises.resize(q);
  for (Index k = 0; k < q; ++k) {
    double g[2][2];  // g[c][j] = ∂_j u_c
    for (int c = 0; c < 2; ++c) {
      for (int j = 0; j < 2; ++j) g[c][j] = gv.tu(j, k) * du(k, c) + gv.tv(j, k) * dv(k, c);
    }
    const Eigen::Vector3d sigma = stress_of(g, lame);
    const double sxx = sigma(0), syy = sigma(1), sxy = sigma(2);
    const double szz = nu_zz * (sxx + syy);
    stress(0, k) = sxx;
    stress(1, k) = syy;
    stress(2, k) = szz;
    stress(3, k) = sxy;
    von_mises(k) = std::sqrt(0.5 * ((sxx - syy) * (sxx - syy) + (syy - szz) * (syy - szz) + (szz - sxx) * (szz - sxx)) +
                             3 * sxy * sxy);
  }
}

std::function<void(Index e, const basis::BasisValues& bv, const basis::GeometryValues& gv, Eigen::MatrixXd& out)>
elasticity_sampler(const basis::Space& space, const Eigen::VectorXd& u, Lame lame, double nu_zz, int which) {
  if (which < 0 || which > 2) throw InputError("elasticity_sampler: which must be 0, 1 or 2");
  return [&space, &u, lame, nu_zz, which](Index e, const basis::BasisValues& bv, const basis::GeometryValues& gv,
                                           Eigen::MatrixXd& out) {
    Eigen::MatrixXd displacement, stress;
    Eigen::VectorXd von_mises;
    displacement_and_stress(space, u, e, bv, gv, lame, nu_zz, displacement, stress, von_mises);
    if (which == 0) out = displacement;
    if (which == 1) out = stress;
    if (which == 2) out = von_mises.transpose();
  };
}

}  // namespace iga::pde
