#include "pde/shell/shell.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include "basis/locate.hpp"
#include "core/error.hpp"
#include "fem/dirichlet.hpp"
#include "fem/linear_system.hpp"
#include "fem/smoothness.hpp"
#include "quadrature/gauss_legendre.hpp"

namespace iga::pde {

namespace {

std::string shortest(double v) {
  std::ostringstream out;
  out << v;
  return out.str();
}

std::string point_text(const Eigen::Vector3d& x) {
  std::ostringstream out;
  out << "(" << x(0) << ", " << x(1) << ", " << x(2) << ")";
  return out.str();
}

const char* axis(int c) { return c == 0 ? "x" : c == 1 ? "y" : "z"; }

void check_material(const ShellMaterial& m) {
  if (!(m.young > 0.0) || !std::isfinite(m.young)) {
    throw InputError("shell: Young's modulus E must be a finite number > 0, got " + shortest(m.young));
  }
  if (!(m.poisson > -1.0 && m.poisson <= 0.5)) {
    throw InputError("shell: Poisson's ratio must lie in (-1, 0.5], got " + shortest(m.poisson));
  }
  if (!(m.thickness > 0.0) || !std::isfinite(m.thickness)) {
    throw InputError("shell: the thickness t must be a finite number > 0, got " + shortest(m.thickness));
  }
}

// Whether the shell is thin where it is curved and against its elements, from the centre of every element: the smallest
// radius of curvature R (the principal curvatures: the eigenvalues of the shape operator a^αβ b_βγ) and the smallest
// element size h (√ of the element's area). Kirchhoff–Love neglects transverse shear, which takes t ≪ R; an element
// smaller than t resolves what the model leaves out. A warning for t > R/10 and for t > h, else none.
std::vector<std::pair<std::string, std::string>> thinness(const basis::Geometry& geometry, double t) {
  const basis::Space& space = geometry.space();
  double r_min = std::numeric_limits<double>::infinity(), h_min = r_min;
  Eigen::Vector3d r_at = Eigen::Vector3d::Zero();
  Index h_element = 0;
  Eigen::Matrix2Xd centre(2, 1);
  basis::BasisValues bv;
  basis::GeometryValues gv;
  for (Index e = 0; e < space.num_elements(); ++e) {
    const bool triangle = space.kind(e).shape == basis::Shape::Triangle;
    centre.col(0) = triangle ? Eigen::Vector2d(1.0 / 3, 1.0 / 3) : Eigen::Vector2d(0.5, 0.5);
    space.evaluate(e, centre, 2, bv);
    geometry.evaluate(e, bv, gv, false, 2);
    const Eigen::Vector3d xu = gv.xu.col(0), xv = gv.xv.col(0), n = xu.cross(xv);
    const double area = n.norm() * (triangle ? 0.5 : 1.0);
    if (!(area > 0)) continue;
    Eigen::Matrix2d g, b;
    g << xu.dot(xu), xu.dot(xv), xu.dot(xv), xv.dot(xv);
    b << gv.xuu.col(0).dot(n), gv.xuv.col(0).dot(n), gv.xuv.col(0).dot(n), gv.xvv.col(0).dot(n);
    b /= n.norm();
    const Eigen::Vector2cd k = (g.inverse() * b).eigenvalues();
    const double kmax = std::max(std::abs(k(0)), std::abs(k(1)));
    if (kmax > 0 && 1 / kmax < r_min) {
      r_min = 1 / kmax;
      r_at = gv.x.col(0);
    }
    if (std::sqrt(area) < h_min) {
      h_min = std::sqrt(area);
      h_element = e;
    }
  }
  std::vector<std::pair<std::string, std::string>> out;
  std::ostringstream w;
  if (t > 0.1 * r_min) {
    w << "the shell is not thin where it is most curved: t = " << t << " against the radius of curvature " << r_min
      << " at " << point_text(r_at) << " (t/R = " << t / r_min << "; Kirchhoff-Love neglects transverse shear, which "
      << "takes t/R well below 1/10)";
    out.emplace_back("curvature", w.str());
    w.str("");
  }
  if (t > h_min) {
    w << "elements smaller than the thickness: element " << h_element << " has size " << h_min << " < t = " << t
      << " (a thin-shell model does not resolve the stresses across the thickness that such elements would)";
    out.emplace_back("element size", w.str());
  }
  return out;
}

class Shell final : public fem::Problem {
 public:
  explicit Shell(ShellData data) : d_(std::move(data)) {
    check_material(d_.material);
    form_ = std::make_unique<KirchhoffLoveForm>(d_.material);
    const bool area = d_.area_load[0] || d_.area_load[1] || d_.area_load[2];
    if (area || d_.pressure) load_ = std::make_unique<ShellLoadForm>(d_.area_load, d_.pressure);
  }
  std::string name() const override { return "shell"; }
  int components() const override { return 3; }

  void check(const basis::Geometry& geometry) const override;
  std::vector<const fem::BilinearForm*> bilinear_forms() const override { return {form_.get()}; }
  std::vector<const fem::LinearForm*> linear_forms() const override {
    if (load_) return {load_.get()};
    return {};
  }
  void add_boundary_terms(const fem::Assembler& assembler, fem::LinearSystem& system,
                          fem::Choices& choices) const override;
  fem::DirichletConditions constraints(const fem::Assembler& assembler, fem::Choices& choices) const override;
  std::vector<std::string> error_names() const override { return {}; }
  std::vector<std::pair<std::string, double>> quantities(const fem::Assembler& assembler,
                                                         const Eigen::VectorXd& u) const override;
  Eigen::VectorXd error_squares(const fem::Assembler&, const Eigen::VectorXd&,
                                const fem::LinearSystem&) const override {
    return {};
  }

 private:
  std::vector<basis::BoundaryEdge> on(const std::vector<int>& parts) const { return fem::edges_on(edges_, parts); }
  void refuse_rigid_modes(const basis::Geometry& geometry, const fem::DirichletConditions& bc) const;
  void add_slope_equations(const fem::Assembler& scalar, const std::vector<int>& parts,
                           std::vector<Eigen::Triplet<double>>& rows, std::vector<Index>& prefer) const;
  fem::DirichletConditions zero_union(const std::vector<fem::DirichletConditions>& held, int c) const;
  fem::DirichletConditions point_support(const basis::Space& space, std::size_t k, const fem::DirichletConditions& bc,
                                         const std::vector<Index>& taken) const;

  ShellData d_;
  std::unique_ptr<KirchhoffLoveForm> form_;
  std::unique_ptr<ShellLoadForm> load_;
  mutable std::vector<std::string> names_;
  mutable std::string smoothness_;
  mutable std::vector<std::pair<std::string, std::string>> thinness_;  ///< warnings of thinness()
  mutable std::vector<basis::BoundaryEdge> edges_;
  mutable std::vector<basis::LocatedPoint> points_;    ///< of d_.point_loads, by check()
  mutable std::vector<basis::LocatedPoint> supports_;  ///< of d_.point_supports, by check()
};

void Shell::check(const basis::Geometry& geometry) const {
  smoothness_ = fem::check_c1(geometry, "shell", "the Kirchhoff-Love shell");
  thinness_ = thinness(geometry, d_.material.thickness);
  names_ = geometry.space().boundary_part_names();
  const int parts = static_cast<int>(names_.size());
  auto check_parts = [&](const std::vector<int>& list, const std::string& what) {
    if (list.empty()) throw InputError("shell: " + what + " names no boundary part");
    for (int p : list) {
      if (p < 0 || p >= parts) {
        throw InputError("shell: " + what + ": boundary part " + std::to_string(p) + " does not exist (" +
                         std::to_string(parts) + " parts)");
      }
    }
  };
  int count[3] = {0, 0, 0};
  bool valued[3] = {false, false, false};
  for (const ShellSupport& s : d_.supports) {
    if (s.component < 0 || s.component > 2) {
      throw InputError("shell: support component " + std::to_string(s.component) + " (0 is x, 1 is y, 2 is z)");
    }
    const std::string what = std::string("support u_") + axis(s.component);
    check_parts(s.parts, what);
    if (s.hold != Hold::kValue && s.value) {
      throw InputError("shell: " + what + ": a support that holds the slope holds the value 0 (or none); give the "
                       "value in a support of its own");
    }
    ++count[s.component];
    valued[s.component] = valued[s.component] || s.value;
  }
  for (int c = 0; c < 3; ++c) {
    if (valued[c] && count[c] > 1) {
      throw InputError(std::string("shell: support u_") + axis(c) +
                       " has a value and another support: give it one condition over all its parts");
    }
  }
  for (const ShellLineLoad& l : d_.line_loads) check_parts(l.parts, "line load");
  points_.clear();
  for (std::size_t k = 0; k < d_.point_loads.size(); ++k) {
    points_.push_back(basis::locate_point(geometry, d_.point_loads[k].at, "shell: point load " + std::to_string(k + 1), 1e-6,
                                          d_.point_allowance));
  }
  supports_.clear();
  for (std::size_t k = 0; k < d_.point_supports.size(); ++k) {
    const ShellPointSupport& s = d_.point_supports[k];
    if (s.component < 0 || s.component > 2) {
      throw InputError("shell: point support " + std::to_string(k + 1) + ": component " + std::to_string(s.component) +
                       " (0 is x, 1 is y, 2 is z)");
    }
    supports_.push_back(basis::locate_point(geometry, s.at, "shell: point support " + std::to_string(k + 1), 1e-6,
                                            d_.point_allowance));
  }
  edges_ = geometry.space().boundary_edges();
}

void Shell::add_boundary_terms(const fem::Assembler& assembler, fem::LinearSystem& system,
                               fem::Choices& choices) const {
  const ShellMaterial& m = d_.material;
  choices.emplace_back("material", "linear isotropic, E = " + shortest(m.young) + ", nu = " + shortest(m.poisson) +
                                       ", t = " + shortest(m.thickness));
  choices.emplace_back("formulation", "Kirchhoff-Love, membrane + bending (Kiendl et al. 2009)");
  choices.emplace_back("smoothness", smoothness_);
  for (const auto& [what, w] : thinness_) choices.emplace_back("warning (" + what + ")", w);
  const Eigen::SparseMatrix<double> none;
  for (const ShellLineLoad& l : d_.line_loads) {
    const ShellLineLoadForm form(l.load);
    Eigen::VectorXd b;
    assembler.assemble_boundary(on(l.parts), nullptr, &form, nullptr, &b);
    system.add(none, b);
    choices.emplace_back("line load", fem::part_names(l.parts, names_));
  }
  if (d_.point_loads.empty()) return;
  const basis::Space& space = assembler.geometry().space();
  Eigen::VectorXd b = Eigen::VectorXd::Zero(assembler.num_dofs());
  basis::BasisValues bv;
  Eigen::Matrix2Xd at(2, 1);
  std::string where;
  for (std::size_t k = 0; k < points_.size(); ++k) {
    at.col(0) = points_[k].uv;
    space.evaluate(points_[k].element, at, 0, bv);
    const auto dofs = space.dofs(points_[k].element);
    for (std::size_t a = 0; a < dofs.size(); ++a) {
      for (int c = 0; c < 3; ++c) b(3 * dofs[a] + c) += d_.point_loads[k].force(c) * bv.value(static_cast<Index>(a), 0);
    }
    if (!where.empty()) where += "; ";
    where += point_text(d_.point_loads[k].at) + " element " + std::to_string(points_[k].element);
  }
  system.add(none, b);
  choices.emplace_back("point loads", where);
}

fem::DirichletConditions Shell::constraints(const fem::Assembler& assembler, fem::Choices& choices) const {
  const fem::Assembler scalar(assembler.geometry(), assembler.rules());
  const Index n = assembler.geometry().space().num_dofs();
  std::vector<fem::DirichletConditions> sets;
  for (int c = 0; c < 3; ++c) {
    std::vector<fem::DirichletConditions> held;  // values, on the scalar space
    std::vector<Eigen::Triplet<double>> slopes;  // the slope equations' rows
    std::vector<Index> prefer;
    for (const ShellSupport& s : d_.supports) {
      if (s.component != c) continue;
      if (s.hold != Hold::kSlope) {
        held.push_back(fem::project_dirichlet(scalar, on(s.parts), s.value ? s.value : fem::constant_function(0.0)));
      }
      if (s.hold != Hold::kValue) add_slope_equations(scalar, s.parts, slopes, prefer);
      const char* how = s.hold == Hold::kValue ? ": value, strong (L2 projection)"
                        : s.hold == Hold::kSlope ? ": slope"
                                                 : ": value and slope";
      choices.emplace_back(std::string("support u_") + axis(c), fem::part_names(s.parts, names_) + how);
    }
    if (held.empty() && slopes.empty()) continue;
    fem::DirichletConditions values = held.size() == 1 ? held[0] : zero_union(held, c);
    if (!slopes.empty()) {
      if (values.coupling.nonZeros() > 0) {
        throw UnsupportedError(std::string("shell: support u_") + axis(c) +
                               ": a slope held together with values on a space whose traces are coupled");
      }
      // The values' dofs leave the slope equations (their values are 0: one valued support is alone).
      std::vector<char> fixed(static_cast<std::size_t>(n), 0);
      for (Index d : values.dofs) fixed[static_cast<std::size_t>(d)] = 1;
      std::erase_if(slopes, [&](const Eigen::Triplet<double>& t) { return fixed[static_cast<std::size_t>(t.col())] != 0; });
      Eigen::SparseMatrix<double, Eigen::RowMajor> rows(n, n);
      rows.setFromTriplets(slopes.begin(), slopes.end());
      values = fem::merge_conditions({values, fem::linear_conditions(rows, prefer)}, n);
    }
    sets.push_back(fem::component_conditions(values, c, 3));
  }
  fem::DirichletConditions bc = fem::merge_conditions(sets, assembler.num_dofs());
  if (!d_.point_supports.empty()) {
    std::vector<fem::DirichletConditions> with{bc};
    std::vector<Index> taken;  // the dofs the conditions so far couple
    for (Index r = 0; r < bc.coupling.outerSize(); ++r) {
      for (Eigen::SparseMatrix<double, Eigen::RowMajor>::InnerIterator it(bc.coupling, r); it; ++it) {
        taken.push_back(it.col());
      }
    }
    for (std::size_t k = 0; k < d_.point_supports.size(); ++k) {
      with.push_back(point_support(assembler.geometry().space(), k, bc, taken));
      const fem::DirichletConditions& p = with.back();
      taken.insert(taken.end(), p.dofs.begin(), p.dofs.end());
      if (p.coupling.rows() > 0) {
        for (Eigen::SparseMatrix<double, Eigen::RowMajor>::InnerIterator it(p.coupling, 0); it; ++it) {
          taken.push_back(it.col());
        }
      }
      std::string what = point_text(d_.point_supports[k].at);
      if (p.dofs.empty()) what += ": implied by the supports";
      choices.emplace_back(std::string("point support u_") + axis(d_.point_supports[k].component), what);
    }
    bc = fem::merge_conditions(with, assembler.num_dofs());
  }
  refuse_rigid_modes(assembler.geometry(), bc);
  return bc;
}

// The rows ∫_Γ ∂_n u ∂_n φ_s = 0 of ∂_n u = 0 on the parts, one per function φ_s with a slope there (Gauss points of
// the sides, ∂_n along the outward conormal); `prefer` gets those whose value vanishes on the parts (the second row of
// a patch), the dofs the elimination should solve for.
void Shell::add_slope_equations(const fem::Assembler& scalar, const std::vector<int>& parts,
                                std::vector<Eigen::Triplet<double>>& rows, std::vector<Index>& prefer) const {
  const basis::Space& space = scalar.geometry().space();
  const int degree = std::max(space.polynomial_degree(0).value_or(3), 1);
  const quadrature::Rule1D line = quadrature::gauss_legendre(degree + 3);
  fem::BoundaryContext ctx;
  std::vector<char> valued(static_cast<std::size_t>(space.num_dofs()), 0), sloped = valued;
  Eigen::VectorXd slope;
  for (const basis::BoundaryEdge& edge : on(parts)) {
    scalar.prepare_side(edge.element, edge.side, 0.0, 1.0, line, ctx);
    const auto dofs = space.dofs(edge.element);
    const Index m = static_cast<Index>(dofs.size()), q = ctx.basis.value.cols();
    Eigen::MatrixXd dn(m, q);
    for (Index k = 0; k < q; ++k) {
      for (Index a = 0; a < m; ++a) {
        const Eigen::Vector3d grad = ctx.geo.tu.col(k) * ctx.basis.du(a, k) + ctx.geo.tv.col(k) * ctx.basis.dv(a, k);
        dn(a, k) = grad.dot(ctx.conormal.col(k));
      }
    }
    const Eigen::MatrixXd mass = dn * ctx.weight.asDiagonal() * dn.transpose();
    const double scale = mass.cwiseAbs().maxCoeff();
    for (Index a = 0; a < m; ++a) {
      const std::size_t da = static_cast<std::size_t>(dofs[static_cast<std::size_t>(a)]);
      if (ctx.basis.value.row(a).cwiseAbs().maxCoeff() > 1e-13) valued[da] = 1;
      if (mass(a, a) <= 1e-14 * scale) continue;
      sloped[da] = 1;
      for (Index b = 0; b < m; ++b) {
        if (mass(a, b) != 0.0) rows.emplace_back(dofs[static_cast<std::size_t>(a)], dofs[static_cast<std::size_t>(b)], mass(a, b));
      }
    }
  }
  for (std::size_t i = 0; i < sloped.size(); ++i) {
    if (sloped[i] && !valued[i]) prefer.push_back(static_cast<Index>(i));
  }
}

// Several zero conditions on one component as one: the union of their dofs (coupled ones cannot be joined).
fem::DirichletConditions Shell::zero_union(const std::vector<fem::DirichletConditions>& held, int c) const {
  fem::DirichletConditions out;
  for (const fem::DirichletConditions& h : held) {
    if (h.coupling.nonZeros() > 0) {
      throw UnsupportedError(std::string("shell: support u_") + axis(c) +
                             " on several parts of a space whose traces are coupled: give it one support over all "
                             "its parts");
    }
    out.dofs.insert(out.dofs.end(), h.dofs.begin(), h.dofs.end());
  }
  std::sort(out.dofs.begin(), out.dofs.end());
  out.dofs.erase(std::unique(out.dofs.begin(), out.dofs.end()), out.dofs.end());
  out.values = Eigen::VectorXd::Zero(static_cast<Index>(out.dofs.size()));
  return out;
}

// Σ_a φ_a(x) u_{a,c} = 0 as u_s = −Σ_{a≠s} (φ_a/φ_s) u_a − Σ_{a supported} (φ_a/φ_s) g_a, s the free dof of the
// largest φ_a(x); dofs the part supports already hold enter with their values. Empty when every dof is held.
fem::DirichletConditions Shell::point_support(const basis::Space& space, std::size_t k,
                                              const fem::DirichletConditions& bc,
                                              const std::vector<Index>& taken) const {
  const int c = d_.point_supports[k].component;
  Eigen::Matrix2Xd at(2, 1);
  at.col(0) = supports_[k].uv;
  basis::BasisValues bv;
  space.evaluate(supports_[k].element, at, 0, bv);
  const auto dofs = space.dofs(supports_[k].element);
  double rhs = 0.0;
  std::vector<std::pair<Index, double>> free;
  for (std::size_t a = 0; a < dofs.size(); ++a) {
    const double phi = bv.value(static_cast<Index>(a), 0);
    if (phi == 0.0) continue;
    const Index dof = 3 * dofs[a] + c;
    const auto held = std::lower_bound(bc.dofs.begin(), bc.dofs.end(), dof);
    if (held != bc.dofs.end() && *held == dof) {
      const Index row = held - bc.dofs.begin();
      if (bc.coupling.nonZeros() > 0 && bc.coupling.row(row).nonZeros() > 0) {
        throw UnsupportedError("shell: point support " + std::to_string(k + 1) +
                               " lies on functions of a coupled boundary condition; move it off that part");
      }
      rhs -= phi * bc.values(row);
    } else if (std::find(taken.begin(), taken.end(), dof) != taken.end()) {
      throw InputError("shell: point support " + std::to_string(k + 1) + " of u_" + axis(c) +
                       " lies on functions another condition couples (a held slope or another point support) at this "
                       "refinement; move it or refine");
    } else {
      free.emplace_back(dof, phi);
    }
  }
  fem::DirichletConditions out;
  if (free.empty()) return out;
  const auto s = std::max_element(free.begin(), free.end(), [](const auto& a, const auto& b) {
    return std::abs(a.second) < std::abs(b.second);
  });
  out.dofs = {s->first};
  out.values = Eigen::VectorXd::Constant(1, rhs / s->second);
  out.coupling.resize(1, 3 * space.num_dofs());
  std::vector<Eigen::Triplet<double>> t;
  for (const auto& [dof, phi] : free) {
    if (dof != s->first) t.emplace_back(0, dof, phi / s->second);
  }
  out.coupling.setFromTriplets(t.begin(), t.end());
  return out;
}

// The rigid motions c + ω × x in the space: the translations at every function (partition of unity) and the
// rotations ω = e_k, whose coefficients are e_k × the control points (the map reproduces x). A combination every
// condition leaves unchanged (C r = 0 for the homogeneous conditions) is free: the stiffness is singular on it.
void Shell::refuse_rigid_modes(const basis::Geometry& geometry, const fem::DirichletConditions& bc) const {
  if (bc.dofs.empty()) {
    throw InputError("shell: no support: the rigid-body modes (three translations, three rotations) are free; "
                     "support some displacement components on boundary parts");
  }
  Eigen::MatrixXd p = Eigen::MatrixXd::Zero(geometry.control_points().rows(), 3);  // a planar domain: z = 0
  p.leftCols(geometry.dim()) = geometry.control_points();
  const Index n = p.rows();
  Eigen::MatrixXd modes = Eigen::MatrixXd::Zero(3 * n, 6);
  for (Index i = 0; i < n; ++i) {
    const Eigen::Vector3d x = p.row(i).transpose();
    for (int c = 0; c < 3; ++c) {
      modes(3 * i + c, c) = 1.0;
      const Eigen::Vector3d r = Eigen::Vector3d::Unit(c).cross(x);
      for (int j = 0; j < 3; ++j) modes(3 * i + j, 3 + c) = r(j);
    }
  }
  const Eigen::Matrix<double, 6, 1> scale = modes.colwise().norm().transpose().cwiseMax(1e-300);
  Eigen::MatrixXd c(static_cast<Index>(bc.dofs.size()), 6);
  for (std::size_t k = 0; k < bc.dofs.size(); ++k) c.row(static_cast<Index>(k)) = modes.row(bc.dofs[k]);
  if (bc.coupling.nonZeros() > 0) c += bc.coupling * modes;
  for (int j = 0; j < 6; ++j) c.col(j) /= scale(j);
  const Eigen::JacobiSVD<Eigen::MatrixXd> svd(c, Eigen::ComputeFullV);
  const Eigen::VectorXd s = svd.singularValues();
  if (s.size() == 6 && s(5) > 1e-9 * std::max(s(0), 1e-300)) return;
  const Eigen::Matrix<double, 6, 1> v = svd.matrixV().col(5).cwiseQuotient(scale);
  const Eigen::Vector3d t = v.head<3>(), w = v.tail<3>();
  const double extent = p.cwiseAbs().maxCoeff();
  auto clean = [](double x, double unit) { return std::abs(x) < 1e-9 * unit ? 0.0 : x; };
  std::ostringstream msg;
  msg << "shell: the supports leave a rigid-body mode free (";
  if (w.norm() * extent < 1e-6 * t.norm()) {
    const Eigen::Vector3d d = t.normalized();
    msg << "the translation along (" << clean(d(0), 1.0) << ", " << clean(d(1), 1.0) << ", " << clean(d(2), 1.0) << ")";
  } else {
    const Eigen::Vector3d d = w.normalized(), x0 = w.cross(t) / w.squaredNorm();  // t + ω × x = ω × (x − x0)
    msg << "the rotation about the axis along (" << clean(d(0), 1.0) << ", " << clean(d(1), 1.0) << ", "
        << clean(d(2), 1.0) << ") through (" << clean(x0(0), extent) << ", " << clean(x0(1), extent) << ", "
        << clean(x0(2), extent) << ")";
  }
  msg << "): the stiffness matrix is singular; support more components or parts";
  throw InputError(msg.str());
}

// ½ ∫ t εᵀDε and ½ ∫ t³/12 κᵀDκ of the solution, at the assembly's rules.
std::vector<std::pair<std::string, double>> Shell::quantities(const fem::Assembler& assembler,
                                                              const Eigen::VectorXd& u) const {
  const basis::Space& space = assembler.geometry().space();
  const ShellMaterial& m = d_.material;
  const Eigen::VectorXd e = assembler.integrate(2, [&](const fem::ElementContext& ctx, Eigen::Ref<Eigen::VectorXd> out) {
    const auto dofs = space.dofs(ctx.element);
    Eigen::MatrixXd local(static_cast<Index>(dofs.size()), 3);
    for (std::size_t a = 0; a < dofs.size(); ++a) local.row(static_cast<Index>(a)) = u.segment<3>(3 * dofs[a]).transpose();
    const basis::BasisValues& b = ctx.basis;
    const basis::GeometryValues& g = ctx.geo;
    const Eigen::MatrixXd du = local.transpose() * b.du, dv = local.transpose() * b.dv, duu = local.transpose() * b.duu,
                          duv = local.transpose() * b.duv, dvv = local.transpose() * b.dvv;
    for (Index k = 0; k < ctx.num_points(); ++k) {
      const ShellStrains s = shell_strains(g.xu.col(k), g.xv.col(k), g.xuu.col(k), g.xuv.col(k), g.xvv.col(k), du.col(k),
                                           dv.col(k), duu.col(k), duv.col(k), dvv.col(k), m);
      out(0) += 0.5 * ctx.weight(k) * m.thickness * s.membrane.dot(s.material * s.membrane);
      out(1) += 0.5 * ctx.weight(k) * m.thickness * m.thickness * m.thickness / 12 * s.bending.dot(s.material * s.bending);
    }
  }, 2);
  return {{"strain energy", e(0) + e(1)}, {"membrane energy", e(0)}, {"bending energy", e(1)}};
}

}  // namespace

std::shared_ptr<const fem::Problem> make_shell(ShellData data) { return std::make_shared<Shell>(std::move(data)); }

Eigen::Vector3d shell_displacement(const basis::Space& space, const Eigen::VectorXd& u, Index e,
                                   const Eigen::Vector2d& uv) {
  Eigen::Matrix2Xd at(2, 1);
  at.col(0) = uv;
  basis::BasisValues bv;
  space.evaluate(e, at, 0, bv);
  const auto dofs = space.dofs(e);
  Eigen::Vector3d out = Eigen::Vector3d::Zero();
  for (std::size_t a = 0; a < dofs.size(); ++a) out += bv.value(static_cast<Index>(a), 0) * u.segment<3>(3 * dofs[a]);
  return out;
}

}  // namespace iga::pde
