#include "pde/shell/forms.hpp"

#include <Eigen/Dense>
#include <cmath>

namespace iga::pde {

namespace {

// What the strains at one point need from the map: a_1, a_2, a_3, ā, D (without t) and, per second derivative
// j = 11, 22, 12, the vectors r1_j = (a_2 × p_j)/ā and r2_j = (p_j × a_1)/ā of the bending strain.
struct PointFrame {
  Eigen::Vector3d a1, a2, a3;
  Eigen::Matrix3d d;
  Eigen::Vector3d r1[3], r2[3];
};

PointFrame frame(const Eigen::Vector3d& xu, const Eigen::Vector3d& xv, const Eigen::Vector3d& xuu,
                 const Eigen::Vector3d& xuv, const Eigen::Vector3d& xvv, const ShellMaterial& m) {
  PointFrame f;
  f.a1 = xu;
  f.a2 = xv;
  const Eigen::Vector3d c = xu.cross(xv);
  const double abar = c.norm();
  f.a3 = c / abar;
  // Contravariant metric a^αβ: the inverse of a_αβ = a_α · a_β.
  const double g11 = xu.dot(xu), g12 = xu.dot(xv), g22 = xv.dot(xv), det = g11 * g22 - g12 * g12;
  const double h11 = g22 / det, h12 = -g12 / det, h22 = g11 / det;
  const double nu = m.poisson, s = m.young / (1 - nu * nu);
  f.d << h11 * h11, nu * h11 * h22 + (1 - nu) * h12 * h12, h11 * h12,  //
      0.0, h22 * h22, h22 * h12,                                        //
      0.0, 0.0, 0.5 * ((1 - nu) * h11 * h22 + (1 + nu) * h12 * h12);
  f.d(1, 0) = f.d(0, 1);
  f.d(2, 0) = f.d(0, 2);
  f.d(2, 1) = f.d(1, 2);
  f.d *= s;
  const Eigen::Vector3d* second[3] = {&xuu, &xvv, &xuv};
  for (int j = 0; j < 3; ++j) {
    const Eigen::Vector3d p = *second[j] - second[j]->dot(f.a3) * f.a3;
    f.r1[j] = xv.cross(p) / abar;
    f.r2[j] = p.cross(xu) / abar;
  }
  return f;
}

}  // namespace

void KirchhoffLoveForm::add(const fem::ElementContext& ctx, Eigen::MatrixXd& local) const {
  const Eigen::Index n = ctx.basis.value.rows(), q = ctx.num_points();
  const basis::BasisValues& b = ctx.basis;
  const basis::GeometryValues& g = ctx.geo;
  // Rows 6k..6k+2: √(w t) Lᵀ B_m, rows 6k+3..6k+5: √(w t³/12) Lᵀ B_b at point k (D = L Lᵀ), so that the element
  // matrix is one product SᵀS.
  thread_local Eigen::MatrixXd s;
  s.resize(6 * q, 3 * n);
  const double t = m_.thickness;
  for (Eigen::Index k = 0; k < q; ++k) {
    const PointFrame f = frame(g.xu.col(k), g.xv.col(k), g.xuu.col(k), g.xuv.col(k), g.xvv.col(k), m_);
    const Eigen::Matrix3d lt = f.d.llt().matrixU();  // Lᵀ
    const Eigen::Matrix3d sm = std::sqrt(ctx.weight(k) * t) * lt, sb = std::sqrt(ctx.weight(k) * t * t * t / 12) * lt;
    for (Eigen::Index a = 0; a < n; ++a) {
      const double p1 = b.du(a, k), p2 = b.dv(a, k);
      const double pp[3] = {b.duu(a, k), b.dvv(a, k), b.duv(a, k)};
      for (int i = 0; i < 3; ++i) {
        const Eigen::Vector3d bm(p1 * f.a1(i), p2 * f.a2(i), p2 * f.a1(i) + p1 * f.a2(i));
        Eigen::Vector3d bb;
        for (int j = 0; j < 3; ++j) bb(j) = pp[j] * f.a3(i) + p1 * f.r1[j](i) + p2 * f.r2[j](i);
        bb(2) *= 2;
        s.block<3, 1>(6 * k, 3 * a + i) = sm * bm;
        s.block<3, 1>(6 * k + 3, 3 * a + i) = sb * bb;
      }
    }
  }
  // SᵀS is symmetric: its lower triangle by a rank update (half the products of a full one), then both halves.
  thread_local Eigen::MatrixXd k;
  k.setZero(3 * n, 3 * n);
  k.selfadjointView<Eigen::Lower>().rankUpdate(s.transpose());
  local += k.selfadjointView<Eigen::Lower>();
}

std::vector<const fem::Function*> ShellLoadForm::data() const {
  std::vector<const fem::Function*> d;
  for (const auto& c : f_) {
    if (c) d.push_back(c.get());
  }
  if (p_) d.push_back(p_.get());
  return d;
}

void ShellLoadForm::add(const fem::ElementContext& ctx, Eigen::VectorXd& local) const {
  thread_local Eigen::VectorXd f, p, gi;
  if (p_) p_->values(ctx.geo.x, p);
  for (int c = 0; c < 3; ++c) {
    const auto& fc = f_[static_cast<std::size_t>(c)];
    if (!fc && !p_) continue;
    if (fc) {
      fc->values(ctx.geo.x, f);
    } else {
      f.setZero(ctx.num_points());
    }
    if (p_) f += p.cwiseProduct(ctx.geo.normal.row(c).transpose());
    gi.noalias() = ctx.basis.value * f.cwiseProduct(ctx.weight);
    for (Eigen::Index a = 0; a < gi.size(); ++a) local(3 * a + c) += gi(a);
  }
}

void ShellLineLoadForm::add(const fem::BoundaryContext& ctx, Eigen::VectorXd& local) const {
  Eigen::VectorXd q, gi;
  for (int c = 0; c < 3; ++c) {
    if (!q_[static_cast<std::size_t>(c)]) continue;
    q_[static_cast<std::size_t>(c)]->values(ctx.geo.x, ctx.conormal, q);
    gi.noalias() = ctx.basis.value * q.cwiseProduct(ctx.weight);
    for (Eigen::Index a = 0; a < gi.size(); ++a) local(3 * a + c) += gi(a);
  }
}

ShellStrains shell_strains(const Eigen::Vector3d& xu, const Eigen::Vector3d& xv, const Eigen::Vector3d& xuu,
                           const Eigen::Vector3d& xuv, const Eigen::Vector3d& xvv, const Eigen::Vector3d& du,
                           const Eigen::Vector3d& dv, const Eigen::Vector3d& duu, const Eigen::Vector3d& duv,
                           const Eigen::Vector3d& dvv, const ShellMaterial& material) {
  const PointFrame f = frame(xu, xv, xuu, xuv, xvv, material);
  ShellStrains s;
  s.membrane = {f.a1.dot(du), f.a2.dot(dv), f.a1.dot(dv) + f.a2.dot(du)};
  const Eigen::Vector3d* second[3] = {&duu, &dvv, &duv};
  for (int j = 0; j < 3; ++j) s.bending(j) = second[j]->dot(f.a3) + du.dot(f.r1[j]) + dv.dot(f.r2[j]);
  s.bending(2) *= 2;
  s.material = f.d;
  s.normal = f.a3;
  return s;
}

}  // namespace iga::pde
