#include "pde/shell/output.hpp"

#include <cmath>

#include "core/error.hpp"

namespace iga::pde {

namespace {

// The Cartesian tensor c¹¹ a_1⊗a_1 + c²² a_2⊗a_2 + c¹² (a_1⊗a_2 + a_2⊗a_1) in ParaView's order XX, YY, ZZ, XY, YZ, XZ.
Eigen::Matrix<double, 6, 1> cartesian(const Eigen::Vector3d& c, const Eigen::Vector3d& a1, const Eigen::Vector3d& a2) {
  const Eigen::Matrix3d t = c(0) * a1 * a1.transpose() + c(1) * a2 * a2.transpose() +
                            c(2) * (a1 * a2.transpose() + a2 * a1.transpose());
  Eigen::Matrix<double, 6, 1> out;
  out << t(0, 0), t(1, 1), t(2, 2), t(0, 1), t(1, 2), t(0, 2);
  return out;
}

double von_mises(const Eigen::Matrix<double, 6, 1>& s) {
  const double xx = s(0), yy = s(1), zz = s(2);
  return std::sqrt(0.5 * ((xx - yy) * (xx - yy) + (yy - zz) * (yy - zz) + (zz - xx) * (zz - xx)) +
                   3 * (s(3) * s(3) + s(4) * s(4) + s(5) * s(5)));
}

}  // namespace

void shell_resultants(const basis::Space& space, const Eigen::VectorXd& u, Index e, const basis::BasisValues& bv,
                      const basis::GeometryValues& gv, const ShellMaterial& material, ShellResultants& out) {
  const auto dofs = space.dofs(e);
  const Index q = bv.value.cols(), n = static_cast<Index>(dofs.size());
  if (bv.duu.cols() != q || gv.xuu.cols() != q) {
    throw Error("shell_resultants: the basis and the map need second derivatives at the points");
  }
  Eigen::MatrixXd local(n, 3);
  for (Index a = 0; a < n; ++a) local.row(a) = u.segment<3>(3 * dofs[static_cast<std::size_t>(a)]).transpose();
  out.displacement = (bv.value.transpose() * local).transpose();
  const Eigen::MatrixXd du = (bv.du.transpose() * local).transpose(), dv = (bv.dv.transpose() * local).transpose();
  const Eigen::MatrixXd duu = (bv.duu.transpose() * local).transpose(), duv = (bv.duv.transpose() * local).transpose(),
                        dvv = (bv.dvv.transpose() * local).transpose();
  out.forces.resize(6, q);
  out.moments.resize(6, q);
  out.von_mises.resize(2, q);
  const double t = material.thickness;
  for (Index k = 0; k < q; ++k) {
    const ShellStrains s = shell_strains(gv.xu.col(k), gv.xv.col(k), gv.xuu.col(k), gv.xuv.col(k), gv.xvv.col(k),
                                         du.col(k), dv.col(k), duu.col(k), duv.col(k), dvv.col(k), material);
    const Eigen::Vector3d nc = t * s.material * s.membrane, mc = -(t * t * t / 12) * s.material * s.bending;
    out.forces.col(k) = cartesian(nc, gv.xu.col(k), gv.xv.col(k));
    out.moments.col(k) = cartesian(mc, gv.xu.col(k), gv.xv.col(k));
    out.von_mises(0, k) = von_mises(out.forces.col(k) / t + 6 * out.moments.col(k) / (t * t));
    out.von_mises(1, k) = von_mises(out.forces.col(k) / t - 6 * out.moments.col(k) / (t * t));
  }
}

std::function<void(Index e, const basis::BasisValues& bv, const basis::GeometryValues& gv, Eigen::MatrixXd& out)>
shell_sampler(const basis::Space& space, const Eigen::VectorXd& u, ShellMaterial material, int which) {
  if (which < 0 || which > 3) throw InputError("shell_sampler: which must be 0, 1, 2 or 3");
  return [&space, &u, material, which](Index e, const basis::BasisValues& bv, const basis::GeometryValues& gv,
                                       Eigen::MatrixXd& out) {
    thread_local ShellResultants r;
    shell_resultants(space, u, e, bv, gv, material, r);
    out = which == 0 ? r.displacement : which == 1 ? r.forces : which == 2 ? r.moments : r.von_mises;
  };
}

ShellResultants shell_resultants_at(const basis::Geometry& geometry, const Eigen::VectorXd& u, Index e,
                                    const Eigen::Vector2d& uv, const ShellMaterial& material) {
  Eigen::Matrix2Xd at(2, 1);
  at.col(0) = uv;
  basis::BasisValues bv;
  basis::GeometryValues gv;
  geometry.space().evaluate(e, at, 2, bv);
  geometry.evaluate(e, bv, gv, false, 2);
  ShellResultants r;
  shell_resultants(geometry.space(), u, e, bv, gv, material, r);
  return r;
}

}  // namespace iga::pde
