#include "bem/solve.hpp"

#include <Eigen/LU>
#include <chrono>
#include <string>

#include "bem/assembly.hpp"
#include "bem/gmres.hpp"
#include "core/error.hpp"
#include "quadrature/gauss_legendre.hpp"

namespace iga::bem {

namespace {

// ∫_Γ φ_j dΓ per dof and ∫_Γ f dΓ (user units) by Gauss with p + 4 points per BEM element.
void boundary_weights(const BoundaryDiscretization& d, const fem::Function* f, Eigen::VectorXd& w, double& integral) {
  const quadrature::Rule1D g = quadrature::gauss_legendre(d.space().degree() + 4);
  w.setZero(d.num_dofs());
  integral = 0.0;
  basis::CurvePoints pts;
  basis::CurveBasisValues v;
  Eigen::VectorXd fv;
  for (Index e = 0; e < d.num_elements(); ++e) {
    const BemElement& el = d.element(e);
    d.curve().evaluate(el.curve_element, (el.a + (el.b - el.a) * g.points.array()).matrix(), pts);
    d.space().evaluate(e, g.points, 0, v);
    const Eigen::VectorXd ws = ((el.b - el.a) * g.weights.array() * pts.speed.array()).matrix();
    const std::span<const Index> dofs = d.space().dofs(e);
    for (std::size_t j = 0; j < dofs.size(); ++j) w(dofs[j]) += v.value.row(static_cast<Index>(j)).dot(ws);
    if (f != nullptr) {
      Eigen::Matrix3Xd x = Eigen::Matrix3Xd::Zero(3, pts.x.cols());
      x.topRows<2>() = pts.x;
      f->values(x, fv);
      integral += fv.dot(ws);
    }
  }
}

// ∫_Γ g dΓ and ∫_Γ |g| dΓ of Neumann data over the Neumann dofs' elements (user units), Gauss with `points` per
// BEM element: the solvability condition of the pure-Neumann problem (fem/compatibility.hpp).
fem::DataIntegrals neumann_integrals(const BoundaryDiscretization& d, const fem::BoundaryFunction& g, int points) {
  const quadrature::Rule1D rule = quadrature::gauss_legendre(points);
  fem::DataIntegrals out;
  basis::CurvePoints pts;
  Eigen::VectorXd gv;
  for (Index e = 0; e < d.num_elements(); ++e) {
    const BemElement& el = d.element(e);
    d.curve().evaluate(el.curve_element, (el.a + (el.b - el.a) * rule.points.array()).matrix(), pts);
    const Eigen::VectorXd ws = ((el.b - el.a) * rule.weights.array() * pts.speed.array()).matrix();
    Eigen::Matrix3Xd x = Eigen::Matrix3Xd::Zero(3, pts.x.cols()), n = Eigen::Matrix3Xd::Zero(3, pts.x.cols());
    x.topRows<2>() = pts.x;
    n.topRows<2>() = pts.normal;
    g.values(x, n, gv);
    out.neumann += gv.dot(ws);
    out.neumann_abs += gv.cwiseAbs().dot(ws);
  }
  return out;
}

struct LinearResult {
  Eigen::VectorXd x;
  double condition = 0.0;
  int iterations = 0;
  std::string solver;
};

// Block-Jacobi blocks: runs of at most o.gmres_block consecutive dofs inside each segment; a border row
// (pure Neumann) joins the last block.
std::vector<Eigen::Index> preconditioner_blocks(const BoundaryDiscretization& d, const SolveOptions& o) {
  std::vector<Eigen::Index> starts;
  if (o.gmres_block <= 0) return starts;
  for (Index k = 0; k < d.space().num_segments(); ++k) {
    const Index first = d.space().first_dof(k), nd = d.space().segment_dofs(k);
    const Index pieces = (nd + o.gmres_block - 1) / o.gmres_block;
    for (Index i = 0; i < pieces; ++i) starts.push_back(first + i * nd / pieces);
  }
  return starts;
}

LinearResult solve_linear(const Eigen::MatrixXd& a, const Eigen::VectorXd& b, const SolveOptions& o,
                          const std::vector<Eigen::Index>& blocks) {
  LinearResult r;
  const bool lu = o.solver == SolveOptions::Solver::LU ||
                  (o.solver == SolveOptions::Solver::Auto && a.rows() <= o.lu_limit);
  if (lu) {
    const Eigen::PartialPivLU<Eigen::MatrixXd> f(a);
    r.x = f.solve(b);
    const double rc = f.rcond();
    r.condition = rc > 0.0 ? 1.0 / rc : std::numeric_limits<double>::infinity();
    r.solver = "lu";
    // A singular or nearly singular system leaves LU with a solution that does not solve it: refuse it.
    const double bn = b.norm();
    const double residual = (a * r.x - b).norm() / (bn > 0.0 ? bn : 1.0);
    if (!(residual <= 1e-6)) {
      throw NumericalError("bem solve: LU's solution has relative residual " + std::to_string(residual) +
                           " (condition estimate " + std::to_string(r.condition) + "): the system is singular to working precision");
    }
    return r;
  }
  const GmresResult g = gmres(a, b, o.gmres_tolerance, o.gmres_restart, o.gmres_max_iterations, blocks);
  if (!g.converged) {
    throw NumericalError("bem solve: GMRES stopped at relative residual " + std::to_string(g.residual) + " after " +
                         std::to_string(g.iterations) + " iterations (tolerance " +
                         std::to_string(o.gmres_tolerance) + ")");
  }
  r.x = g.x;
  r.condition = g.condition_estimate;
  r.iterations = g.iterations;
  r.solver = "gmres";
  return r;
}

}  // namespace

Eigen::MatrixXd system_matrix(const BoundaryDiscretization& d, const BemMatrices& m) {
  Eigen::MatrixXd a(d.num_dofs(), d.num_dofs());
  for (Index j = 0; j < d.num_dofs(); ++j) {
    if (d.dof_condition(j) == kDirichlet) a.col(j) = -m.G.col(j);
    else a.col(j) = m.H.col(j);
  }
  return a;
}

Eigen::VectorXd interpolate_at_collocation(const BoundaryDiscretization& d, const Eigen::VectorXd& values) {
  const basis::SplineCurveSpace& space = d.space();
  Eigen::VectorXd c(d.num_dofs());
  basis::CurveBasisValues v;
  for (Index k = 0; k < space.num_segments(); ++k) {
    const Index first = space.first_dof(k), nd = space.segment_dofs(k);
    Eigen::MatrixXd b = Eigen::MatrixXd::Zero(nd, nd);
    for (Index i = first; i < first + nd; ++i) {
      const CollocationPoint& p = d.collocation_points()[static_cast<std::size_t>(i)];
      space.evaluate(p.element, Eigen::VectorXd::Constant(1, p.t), 0, v);
      const std::span<const Index> dofs = space.dofs(p.element);
      for (std::size_t j = 0; j < dofs.size(); ++j) b(i - first, dofs[j] - first) += v.value(static_cast<Index>(j), 0);
    }
    c.segment(first, nd) = Eigen::PartialPivLU<Eigen::MatrixXd>(b).solve(values.segment(first, nd));
  }
  return c;
}

Solution solve(const BoundaryDiscretization& d, const Problem& problem, const SolveOptions& options) {
  const Index n = d.num_dofs();
  const std::vector<CollocationPoint>& points = d.collocation_points();
  bool has_d = false, has_n = false;
  for (int c : d.dof_conditions()) (c == kDirichlet ? has_d : has_n) = true;
  if (has_d && !problem.dirichlet) throw InputError("bem solve: Dirichlet segments but no Dirichlet data");
  if (has_n && !problem.neumann) throw InputError("bem solve: Neumann segments but no Neumann data");
  fem::Compatibility compatibility;
  if (!has_d) {  // pure Neumann: ∫g = 0 by the border's rule (p + 4 points) and a finer one (p + 6)
    compatibility.has_source = false;
    compatibility.assembly = neumann_integrals(d, *problem.neumann, d.space().degree() + 4);
    compatibility.finer = neumann_integrals(d, *problem.neumann, d.space().degree() + 6);
    if (!options.remove_incompatible) {
      fem::check_compatibility(compatibility, "make the data compatible, or give a Dirichlet part");
    }
  }
  // Data at the collocation points, then the known coefficients (q in internal units: q_user / scale).
  Eigen::Matrix3Xd x = Eigen::Matrix3Xd::Zero(3, n), normal = Eigen::Matrix3Xd::Zero(3, n);
  basis::CurvePoints pts;
  for (Index i = 0; i < n; ++i) {
    const CollocationPoint& c = points[static_cast<std::size_t>(i)];
    d.curve().evaluate(c.curve_element, Eigen::VectorXd::Constant(1, c.curve_t), pts);
    x.col(i).head<2>() = pts.x.col(0);
    normal.col(i).head<2>() = pts.normal.col(0);
  }
  Eigen::VectorXd uval = Eigen::VectorXd::Zero(n), qval = Eigen::VectorXd::Zero(n);
  if (has_d) problem.dirichlet->values(x, uval);
  if (has_n) problem.neumann->values(x, normal, qval);
  for (Index i = 0; i < n; ++i) (d.dof_condition(i) == kDirichlet ? qval(i) : uval(i)) = 0.0;
  const Eigen::VectorXd u_known = interpolate_at_collocation(d, uval);
  const Eigen::VectorXd q_known = interpolate_at_collocation(d, qval) / d.scale();

  const BemMatrices m = assemble(d);
  const auto start = std::chrono::steady_clock::now();
  const Index size = has_d ? n : n + 1;
  Eigen::MatrixXd a = Eigen::MatrixXd::Zero(size, size);
  a.topLeftCorner(n, n) = system_matrix(d, m);
  Eigen::VectorXd b = Eigen::VectorXd::Zero(size);
  for (Index j = 0; j < n; ++j) {
    if (d.dof_condition(j) == kDirichlet) b.head(n) -= m.H.col(j) * u_known(j);
    else b.head(n) += m.G.col(j) * q_known(j);
  }
  if (!has_d) {  // bordered: ∫ u_h = ∫ exact (or 0)
    Eigen::VectorXd w;
    double target = 0.0;
    boundary_weights(d, problem.exact.get(), w, target);
    const double wscale = w.cwiseAbs().maxCoeff();  // keep the border's entries O(1)
    a.col(n).head(n).setOnes();
    a.row(n).head(n) = w.transpose() / wscale;
    b(n) = target / wscale;
  }
  const LinearResult r = solve_linear(a, b, options, preconditioner_blocks(d, options));
  if (!r.x.allFinite()) throw NumericalError("bem solve: the solution is not finite (singular system?)");

  Solution s;
  s.u = u_known;
  s.q = q_known;
  for (Index j = 0; j < n; ++j) (d.dof_condition(j) == kDirichlet ? s.q(j) : s.u(j)) = r.x(j);
  s.q *= d.scale();
  s.assembly_seconds = m.seconds;
  s.solve_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  s.condition_estimate = r.condition;
  s.scale = d.scale();
  s.gmres_iterations = r.iterations;
  s.solver = r.solver;
  s.collocation_points = n;
  s.pure_neumann = !has_d;
  s.compatibility = compatibility;
  return s;
}

}  // namespace iga::bem
