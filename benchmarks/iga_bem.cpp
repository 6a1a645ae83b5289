// iga-bem: Laplace on a planar domain by collocation IgA-BEM on the boundary of the same geometry iga-poisson
// takes (thesis §4.3), with Dirichlet, Neumann or mixed data; --compare-fem solves the same problem with the FEM
// on that geometry. Thin: parses options and calls the library.
#include <CLI/CLI.hpp>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <iomanip>
#include <iostream>
#include <nlohmann/json.hpp>
#include <optional>
#include <set>
#include <sstream>

#include "basis/curve/trace_space.hpp"
#include "basis/registry.hpp"
#include "bem/errors.hpp"
#include "bem/interior.hpp"
#include "bem/sampling.hpp"
#include "bem/solve.hpp"
#include "core/error.hpp"
#include "fem/expression.hpp"
#include "fem/memory.hpp"
#include "fem/poisson.hpp"
#include "fem/threads.hpp"
#include "io/program.hpp"
#include "io/option_rules.hpp"
#include "io/progress.hpp"
#include "io/report.hpp"
#include "io/sampled_writer.hpp"
#include "io/vtu_writer.hpp"
#include "mesh/obj_reader.hpp"
#include "quadrature/rule_provider.hpp"

namespace {

using namespace iga;

struct Options {
  std::string mesh, basis = "bspline", geometry, dirichlet, neumann, neumann_boundary, neumann_where, exact;
  std::string collocation = "greville", joints = "smooth", solver = "auto", vtu = "bem.vtu", boundary_vtu = "bem_boundary.vtu";
  std::string json = "bem.json";
  double gmres_tolerance = 1e-12;
  double max_memory = 0.0;  // GiB; 0: what the system has available
  double max_seconds = 600.0;  // the predicted time of --grid's interior evaluation
  int degree = 2, refine = 2, geometry_refine = -1, grid = 0, samples = 4, threads = 0;
  bool compare_fem = false, quiet = false;
  std::vector<std::string> given;
  nlohmann::json run_info;  ///< io::run_info: version, revision, every effective setting
  bool count(const std::string& option) const { return std::find(given.begin(), given.end(), option) != given.end(); }
};

// The data as a PoissonProblem (f = 0), so that the boundary split and the FEM comparison are iga-poisson's.
fem::PoissonProblem make_problem(const Options& o, const basis::Geometry& geometry, std::string& exact_text) {
  const std::vector<std::string> names = geometry.space().boundary_part_names();
  fem::PoissonProblem p;
  exact_text = o.exact;
  if (exact_text.empty() && o.dirichlet.empty() && o.neumann.empty()) exact_text = "exp(x)*cos(y)";
  if (!exact_text.empty()) {
    auto exact = std::make_shared<fem::Expression>(exact_text, "--exact");
    exact->set_fd_step(fem::finite_difference_step(geometry));  // the exact flux ∇u·n, relative to the domain's size
    p.exact = exact;
    p.dirichlet = p.exact;
  }
  if (!o.dirichlet.empty()) p.dirichlet = std::make_shared<fem::Expression>(o.dirichlet, "--dirichlet");
  fem::select_neumann(p, o.neumann, o.neumann_boundary, o.neumann_where, names);
  return p;
}

// Boundary condition of each trace element: Neumann where the split says so.
std::vector<int> conditions(const basis::TraceSpace& trace, const fem::BoundarySplit& split) {
  std::set<std::pair<Index, int>> neumann;
  for (const basis::BoundaryEdge& b : split.neumann) neumann.insert({b.element, b.side});
  std::vector<int> c(static_cast<std::size_t>(trace.num_elements()));
  for (Index k = 0; k < trace.num_elements(); ++k) {
    c[static_cast<std::size_t>(k)] = neumann.count({trace.edge(k).element, trace.edge(k).side}) ? bem::kNeumann : bem::kDirichlet;
  }
  return c;
}

// The boundary with u_h, q_h (and the exact values) as polylines, one per BEM element.
void write_boundary(const std::string& path, const bem::BoundaryDiscretization& d, const bem::Solution& s,
                    const fem::Function* exact, int samples) {
  io::CurveData c;
  const Index ne = d.num_elements(), np = ne * samples;
  c.points.resize(2, np);
  Eigen::VectorXd u(np), q(np), ue(np), qe(np), element(ne), curve_element(ne), condition(ne);
  Eigen::Matrix2Xd normal(2, np);
  basis::CurvePoints pts;
  const Eigen::VectorXd t = Eigen::VectorXd::LinSpaced(samples, 0.0, 1.0);
  for (Index e = 0; e < ne; ++e) {
    const bem::BemElement& be = d.element(e);
    d.curve().evaluate(be.curve_element, (be.a + (be.b - be.a) * t.array()).matrix(), pts);
    for (Index k = 0; k < samples; ++k) {
      const Index g = e * samples + k;
      c.points.col(g) = pts.x.col(k);
      normal.col(g) = pts.normal.col(k);
      u(g) = bem::evaluate_u(d, s, e, t(k));
      q(g) = bem::evaluate_q(d, s, e, t(k));
    }
    if (exact) {
      Eigen::Matrix3Xd x = Eigen::Matrix3Xd::Zero(3, samples), grad;
      x.topRows<2>() = pts.x;
      Eigen::VectorXd v;
      exact->values(x, v);
      exact->gradients(x, grad);
      ue.segment(e * samples, samples) = v;
      for (Index k = 0; k < samples; ++k) qe(e * samples + k) = grad.col(k).head<2>().dot(pts.normal.col(k));
    }
    c.offsets.push_back((e + 1) * samples);
    element(e) = static_cast<double>(e);
    curve_element(e) = static_cast<double>(be.curve_element);
    condition(e) = d.dof_condition(d.space().dofs(e)[0]);
  }
  c.point_scalars = {{"u", u}, {"q", q}};
  if (exact) {
    c.point_scalars.insert(c.point_scalars.end(), {{"exact_u", ue}, {"exact_q", qe}, {"error_u", u - ue}, {"error_q", q - qe}});
  }
  c.point_vectors = {{"normal", normal}};
  c.cell_scalars = {{"element", element}, {"curve_element", curve_element}, {"condition", condition}};
  io::write_curves_vtu(path, c);
}

}  // namespace

namespace {

std::string fmt(double v) {
  std::ostringstream s;
  s << std::setprecision(4) << v;
  return s.str();
}

// u_h of the FEM at the sample points of every element (the points sample_on_geometry used).
std::vector<Eigen::VectorXd> fem_samples(const basis::Geometry& g, const Eigen::VectorXd& u, int samples) {
  const basis::Space& space = g.space();
  std::vector<Eigen::VectorXd> out(static_cast<std::size_t>(space.num_elements()));
  basis::BasisValues bv;
  for (Index e = 0; e < space.num_elements(); ++e) {
    space.evaluate(e, io::sample_points(space.kind(e).shape, samples), 0, bv);
    const auto dofs = space.dofs(e);
    Eigen::VectorXd local(static_cast<Index>(dofs.size()));
    for (std::size_t a = 0; a < dofs.size(); ++a) local(static_cast<Index>(a)) = u(dofs[a]);
    out[static_cast<std::size_t>(e)] = bv.value.transpose() * local;
  }
  return out;
}

// Exact values at the sample points (physical points of the reference samples).
std::vector<Eigen::VectorXd> exact_samples(const basis::Geometry& g, const fem::Function& exact, int samples) {
  const basis::Space& space = g.space();
  std::vector<Eigen::VectorXd> out(static_cast<std::size_t>(space.num_elements()));
  basis::BasisValues bv;
  basis::GeometryValues gv;
  for (Index e = 0; e < space.num_elements(); ++e) {
    space.evaluate(e, io::sample_points(space.kind(e).shape, samples), 1, bv);
    g.evaluate(e, bv, gv, /*check=*/false);
    exact.values(gv.x, out[static_cast<std::size_t>(e)]);
  }
  return out;
}

// max |a − b − shift| over the sample points (interior ones only when mask is given).
double max_difference(const std::vector<Eigen::VectorXd>& a, const std::vector<Eigen::VectorXd>& b, double shift = 0.0,
                      const std::vector<std::vector<char>>* boundary = nullptr, bool interior = true) {
  double m = 0.0;
  for (std::size_t e = 0; e < a.size(); ++e) {
    for (Index k = 0; k < a[e].size(); ++k) {
      if (boundary && ((*boundary)[e][static_cast<std::size_t>(k)] != 0) == interior) continue;
      m = std::max(m, std::abs(a[e](k) - b[e](k) - shift));
    }
  }
  return m;
}

double mean_difference(const std::vector<Eigen::VectorXd>& a, const std::vector<Eigen::VectorXd>& b) {
  double s = 0.0;
  Index n = 0;
  for (std::size_t e = 0; e < a.size(); ++e) {
    s += (a[e] - b[e]).sum();
    n += a[e].size();
  }
  return n ? s / static_cast<double>(n) : 0.0;
}

// The centres of an N × N grid over the boundary's bounding box.
Eigen::Matrix2Xd grid_points(const bem::BoundaryDiscretization& d, Index n) {
  Eigen::Vector2d lo = Eigen::Vector2d::Constant(1e300), hi = -lo;
  for (Index e = 0; e < d.curve().num_elements(); ++e) {
    for (double t : {0.0, 0.25, 0.5, 0.75}) {
      const Eigen::Vector2d x = d.curve().point(e, t);
      lo = lo.cwiseMin(x);
      hi = hi.cwiseMax(x);
    }
  }
  Eigen::Matrix2Xd points(2, n * n);
  for (Index j = 0; j < n; ++j) {
    for (Index i = 0; i < n; ++i) {
      points.col(i + n * j) = lo + Eigen::Vector2d((i + 0.5) / n * (hi - lo).x(), (j + 0.5) / n * (hi - lo).y());
    }
  }
  return points;
}

// Time before work: the grid's interior evaluation (two per point: u and "inside") predicted from timing 64 of its
// points spread over the grid (every point integrates over the whole boundary, so the cost per point varies little),
// before the BEM is solved; refused above --max-seconds.
void check_grid_time(const Options& o, const bem::BoundaryDiscretization& d) {
  if (o.grid == 0) return;
  const Index n = o.grid, total = n * n;
  const Eigen::Matrix2Xd all = grid_points(d, n);
  const Index m = std::min<Index>(64, total);
  Eigen::Matrix2Xd sample(2, m);
  for (Index k = 0; k < m; ++k) sample.col(k) = all.col(k * total / m);
  bem::Solution zero;
  zero.u = Eigen::VectorXd::Zero(d.num_dofs());
  zero.q = Eigen::VectorXd::Zero(d.num_dofs());
  const auto t0 = std::chrono::steady_clock::now();
  try {
    bem::evaluate_interior(d, zero, sample);
  } catch (const InputError& e) {
    throw InputError("--grid " + std::to_string(n) + ": " + e.what() + "; choose another N");
  }
  const double per_point = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count() / m;
  const double predicted = 2.0 * per_point * static_cast<double>(total);
  if (predicted > o.max_seconds) {
    std::ostringstream msg;
    msg << std::setprecision(3) << "--grid " << n << ": the interior evaluation of its " << static_cast<double>(total)
        << " points would take about " << predicted << " s (" << per_point * 1e3 << " ms per point and evaluation on "
        << fem::num_threads() << " threads, measured on " << m << " of them), more than --max-seconds " << o.max_seconds
        << "; choose a smaller N or raise --max-seconds";
    throw InputError(msg.str());
  }
}

// --grid N: the solution at the centres of an N × N grid over the boundary's bounding box; "inside" is the
// representation formula of u = 1, q = 0 (1 inside, 0 outside).
nlohmann::json write_grid(const Options& o, const bem::BoundaryDiscretization& d, const bem::Solution& s,
                          const fem::Function* exact) {
  const Index n = o.grid;
  io::GridData g;
  g.nx = g.ny = n;
  g.points = grid_points(d, n);
  Eigen::VectorXd u;
  try {
    u = bem::evaluate_interior(d, s, g.points);
  } catch (const InputError& e) {
    // A cell centre exactly on the boundary curve (the representation formula does not hold there).
    throw InputError("--grid " + std::to_string(n) + ": " + e.what() + "; choose another N");
  }
  bem::Solution one = s;
  one.u.setOnes();
  one.q.setZero();
  const Eigen::VectorXd inside = bem::evaluate_interior(d, one, g.points).array().round();
  g.point_scalars = {{"u", u}, {"inside", inside}};
  nlohmann::json j = {{"grid", n}, {"points", n * n}, {"inside_points", static_cast<Index>(inside.sum())}};
  if (exact) {
    // The exact solution only where it is defined: at the grid points inside the domain (0 outside).
    std::vector<Index> in;
    for (Index k = 0; k < n * n; ++k) {
      if (inside(k) > 0.5) in.push_back(k);
    }
    Eigen::Matrix3Xd x = Eigen::Matrix3Xd::Zero(3, static_cast<Index>(in.size()));
    for (std::size_t k = 0; k < in.size(); ++k) x.col(static_cast<Index>(k)).head<2>() = g.points.col(in[k]);
    Eigen::VectorXd ue_in, ue = Eigen::VectorXd::Zero(n * n);
    exact->values(x, ue_in);
    for (std::size_t k = 0; k < in.size(); ++k) ue(in[k]) = ue_in(static_cast<Index>(k));
    const Eigen::VectorXd err = ((u - ue).array() * inside.array()).matrix();
    g.point_scalars.insert(g.point_scalars.end(), {{"exact", ue}, {"error", err}});
    j["max_interior_error"] = err.cwiseAbs().maxCoeff();
  }
  if (o.vtu != "none") io::write_grid_vtu(o.vtu, g);
  return j;
}

bem::SolveOptions::Solver parse_solver(const std::string& s) {
  if (s == "lu") return bem::SolveOptions::Solver::LU;
  if (s == "gmres") return bem::SolveOptions::Solver::GMRES;
  return bem::SolveOptions::Solver::Auto;
}

int run(const Options& o) {
  const auto t_start = std::chrono::steady_clock::now();
  auto log = [&](const std::string& s) {
    if (!o.quiet) std::cerr << "iga-bem: " << s << std::endl;
  };
  if (o.threads > 0) fem::set_num_threads(o.threads);
  for (const std::string* path : {&o.json, &o.vtu, &o.boundary_vtu}) io::check_writable(*path);  // before the work
  io::Progress progress("iga-bem", o.quiet);
  const basis::Backend& backend = basis::backend(o.basis);
  basis::check_options(backend, o.given);
  basis::BackendOptions bo;
  if (o.count("geometry")) bo.geometry = o.geometry;
  bo.net_name = o.mesh;
  const int steps = o.geometry_refine >= 0 ? o.geometry_refine : backend.default_refine;
  basis::BackendFacts facts;
  std::optional<mesh::PolyMesh> net;
  if (!o.mesh.empty()) net = mesh::read_obj(o.mesh);
  {
    // Size before work: the geometry's elements after --geometry-refine (each step splits every element in four),
    // the FEM of --compare-fem on them and the interior output.
    const double elements = (net ? static_cast<double>(net->num_faces()) : 1.0) * std::pow(4.0, steps);
    const double bytes = (o.compare_fem ? fem::poisson_memory(elements, 16) : 1000.0 * elements) +
                         (o.grid == 0 && o.vtu != "none" ? fem::vtu_memory(elements, o.samples) : 0.0);
    std::ostringstream what;
    what << "the geometry (about " << std::setprecision(3) << elements << " elements after --geometry-refine " << steps << ")";
    fem::check_memory(bytes, o.max_memory * 1024.0 * 1024.0 * 1024.0, what.str(),
                      "each --geometry-refine step needs four times more");
  }
  const basis::Refinement refined = basis::make_refined_geometry(backend, net ? &*net : nullptr, bo, steps, facts);
  for (const std::string& note : facts.notes) log(note);
  const basis::Geometry& geometry = refined.geometry;
  if (geometry.dim() != 2) throw UnsupportedError("the net is a surface in 3D; the BEM here is for planar domains");
  std::string exact_text;
  fem::PoissonProblem problem = make_problem(o, geometry, exact_text);
  const fem::BoundarySplit split = fem::split_boundary(geometry, problem);
  if (!split.neumann.empty() && !problem.neumann) throw InputError("Neumann boundary edges are selected but no Neumann data given");
  const basis::BoundaryTrace trace = basis::trace_geometry(geometry);
  {
    // Size before work: H, G, the system matrix and its LU are dense (4 × 8 bytes per entry), and the dofs are at
    // least the BEM elements (every curve element split into 2^K); the grid output.
    const double n = static_cast<double>(trace.curve.num_elements()) * std::pow(2.0, o.refine);
    const double grid = static_cast<double>(o.grid) * o.grid;
    std::ostringstream what;
    what << "the BEM (about " << std::setprecision(3) << n << " dofs, dense matrices)";
    fem::check_memory(32.0 * n * n + 100.0 * grid, o.max_memory * 1024.0 * 1024.0 * 1024.0, what.str(),
                      "each --refine step doubles the dofs and quadruples the memory");
  }
  bem::DiscretizationOptions dopt;
  dopt.degree = o.degree;
  dopt.refine = o.refine;
  dopt.collocation = o.collocation == "maxima" ? bem::Collocation::Maxima : bem::Collocation::Greville;
  dopt.joints = o.joints == "split" ? bem::Joints::Split : bem::Joints::Smooth;
  const bem::BoundaryDiscretization d(trace.curve, conditions(*trace.space, split), dopt);
  log("BEM on " + std::to_string(d.num_dofs()) + " dofs, " + std::to_string(d.num_elements()) + " elements on " +
      std::to_string(trace.curve.loops().size()) + " boundary loop(s), " + std::to_string(d.segments().size()) +
      " segment(s); " + std::to_string(fem::num_threads()) + " threads");
  check_grid_time(o, d);
  bem::SolveOptions so;
  so.solver = parse_solver(o.solver);
  so.gmres_tolerance = o.gmres_tolerance;
  const bem::Solution s = progress.phase("BEM assembly and solve", [&] {
    return bem::solve(d, bem::Problem{problem.dirichlet, problem.neumann, problem.exact}, so);
  });
  log("assembly " + fmt(s.assembly_seconds) + " s, solve " + fmt(s.solve_seconds) + " s (" + s.solver +
      "), condition estimate " + fmt(s.condition_estimate));

  nlohmann::json j = o.run_info;
  j["basis"] = o.basis;
  j["mesh"] = o.mesh.empty() ? "default:" + (o.geometry.empty() ? std::string("quarter-annulus") : o.geometry) : o.mesh;
  j["geometry_refine"] = steps;
  j["degree"] = o.degree;
  j["refine"] = o.refine;
  j["collocation"] = o.collocation;
  j["joints"] = o.joints;
  j["problem"] = {{"dirichlet", o.dirichlet}, {"neumann", o.neumann}, {"neumann_boundary", o.neumann_boundary},
                  {"neumann_where", o.neumann_where}, {"exact", exact_text},
                  {"exact_is_default", o.exact.empty() && !exact_text.empty()}};
  Index corners = 0;
  for (Index e = 0; e < trace.curve.num_elements(); ++e) corners += trace.curve.corner_at_end(e) ? 1 : 0;
  j["boundary"] = {{"loops", trace.curve.loops().size()}, {"curve_elements", trace.curve.num_elements()},
                   {"corners", corners}, {"segments", d.segments().size()},
                   {"dirichlet_edges", split.dirichlet.size()}, {"neumann_edges", split.neumann.size()}};
  j["dofs"] = d.num_dofs();
  j["elements"] = d.num_elements();
  j["collocation_points"] = s.collocation_points;
  j["scale"] = s.scale;
  j["threads"] = fem::num_threads();
  j["assembly_seconds"] = s.assembly_seconds;
  j["solve_seconds"] = s.solve_seconds;
  j["solver"] = s.solver;
  j["gmres_iterations"] = s.gmres_iterations;
  j["gmres_tolerance"] = o.gmres_tolerance;
  j["condition_estimate"] = s.condition_estimate;
  if (s.pure_neumann) {  // the solvability ∫g = 0 (fem/compatibility.hpp): what was judged and what was done
    const fem::Compatibility& c = s.compatibility;
    j["compatibility"] = c.word();
    j["compatibility_defect"] = c.defect();
    j["compatibility_relative"] = c.relative();
    j["compatibility_integrals"] = {{"neumann", c.finer.neumann}, {"neumann_abs", c.finer.neumann_abs},
                                    {"quadrature_error", c.quadrature_error()}};
    if (c.verdict() == fem::Compatibility::Verdict::kWarned) std::cerr << "iga-bem: warning: " << c.warning() << std::endl;
  }
  j["flux_l2_error"] = nullptr;
  j["u_l2_error"] = nullptr;
  j["max_interior_error"] = nullptr;
  const fem::Function* exact = problem.exact.get();
  if (exact) {
    j["flux_l2_error"] = bem::flux_l2_error(d, s, *exact);
    // Relative to the exact flux's norm, when it has one (a constant solution has none: no relative error).
    if (const double norm = bem::flux_l2_norm(d, *exact); norm > 0.0) {
      j["flux_l2_error_relative"] = j["flux_l2_error"].get<double>() / norm;
    }
    j["u_l2_error"] = bem::u_l2_error(d, s, *exact);
    log("boundary flux L2 error " + fmt(j["flux_l2_error"].get<double>()) + ", boundary u L2 error " + fmt(j["u_l2_error"].get<double>()));
  }
  if (o.boundary_vtu != "none") {
    write_boundary(o.boundary_vtu, d, s, exact, o.samples);
    j["boundary_vtu"] = o.boundary_vtu;
  }
  // Interior: on the FEM geometry's sampling (or a grid), and the FEM on the same geometry for comparison.
  if (o.grid > 0) {
    j["interior"] = write_grid(o, d, s, exact);
    if (exact) j["max_interior_error"] = j["interior"]["max_interior_error"];
  }
  if (o.grid == 0 || o.compare_fem) {
    const auto ref = [&](basis::Shape shape) { return io::sample_points(shape, o.samples); };
    std::vector<std::vector<char>> on_boundary;
    const std::vector<Eigen::VectorXd> bem_u = progress.phase("interior evaluation", [&] {
      return bem::sample_on_geometry(geometry, *trace.space, d, s, ref, &on_boundary);
    });
    Index points = 0;
    for (const auto& v : bem_u) points += v.size();
    std::optional<std::vector<Eigen::VectorXd>> ex;
    if (exact) ex = exact_samples(geometry, *exact, o.samples);
    if (o.grid == 0) {
      j["interior"] = {{"samples", o.samples}, {"points", points}};
      if (exact) {
        j["max_interior_error"] = max_difference(bem_u, *ex, 0.0, &on_boundary, true);
        j["interior"]["max_boundary_point_error"] = max_difference(bem_u, *ex, 0.0, &on_boundary, false);
      }
      if (o.vtu != "none") {
        io::VtuOptions vo;
        vo.samples = o.samples;
        vo.exact = problem.exact;
        const io::ElementField field = [&](Index e, const Eigen::Matrix2Xd&, const Eigen::Matrix3Xd&, Eigen::VectorXd& out) {
          out = bem_u[static_cast<std::size_t>(e)];
        };
        progress.phase("output", [&] { io::write_vtu(o.vtu, geometry, field, vo); });
      }
    }
    if (o.compare_fem) {
      const int fem_degree = basis::degree(backend, bo);
      const auto rules = quadrature::make_rule_provider(backend.default_quadrature(fem_degree), fem_degree + 1);
      problem.mean_zero = split.dirichlet.empty();
      const fem::PoissonResult r = progress.phase("FEM comparison", [&] { return fem::solve_poisson(geometry, *rules, problem); });
      const std::vector<Eigen::VectorXd> fem_u = fem_samples(geometry, r.u, o.samples);
      const double shift = problem.mean_zero ? mean_difference(bem_u, fem_u) : 0.0;
      j["compare_fem"] = {{"dofs", r.dofs}, {"elements", r.elements}, {"points", points},
                          {"assembly_seconds", r.assembly_seconds}, {"solve_seconds", r.solve_seconds},
                          {"max_difference", max_difference(bem_u, fem_u, shift)},
                          {"constant_removed", problem.mean_zero ? nlohmann::json(shift) : nlohmann::json(nullptr)}};
      if (exact && r.errors) {
        j["compare_fem"]["fem_l2_error"] = r.errors->l2;
        j["compare_fem"]["fem_max_error"] = max_difference(fem_u, *ex, problem.mean_zero ? mean_difference(fem_u, *ex) : 0.0);
      }
      log("FEM on the same geometry (" + std::to_string(r.dofs) + " dofs): max |u_BEM − u_FEM| = " +
          fmt(j["compare_fem"]["max_difference"].get<double>()) + " at " + std::to_string(points) + " points");
    }
  }
  if (o.vtu != "none") j["vtu"] = o.vtu;
  j["total_seconds"] = std::chrono::duration<double>(std::chrono::steady_clock::now() - t_start).count();
  j["phase_seconds"] = progress.json();
  if (io::writes(o.json)) io::write_json(o.json, j);
  progress.print_table();
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"iga-bem: Laplace's equation by collocation IgA-BEM on the boundary of an isogeometric geometry"};
  Options o;
  app.add_option("--mesh", o.mesh, "Wavefront OBJ control net (planar); default: the embedded bspline geometry")->check(iga::io::input_file());
  std::vector<std::string> backend_list;
  for (const auto& b : basis::backends()) backend_list.push_back(b.name);
  app.add_option("--basis", o.basis, "geometry backend (as iga-poisson): " + basis::backend_names())->check(CLI::IsMember(backend_list))->capture_default_str();
  app.add_option("--geometry", o.geometry, "bspline without --mesh: quarter-annulus (default, exact: NURBS), l-shape, square, or a patch file FILE.json")->check(iga::io::non_blank());
  app.add_option("--geometry-refine", o.geometry_refine, "uniform refinement steps of the geometry (its map is unchanged; the BEM takes the boundary sides as curve elements, the FEM of --compare-fem and the interior sampling use its elements); default: the backend's")->check(iga::io::whole_number(0, 10));
  app.add_option("--degree", o.degree, "degree p of the splines for u and q on the boundary")->check(iga::io::whole_number(1, 8))->capture_default_str();
  app.add_option("--refine", o.refine, "each boundary curve element is split into 2^K BEM elements")->check(iga::io::whole_number(0, 16))->capture_default_str();
  app.add_option("--collocation", o.collocation, "greville or maxima (of the B-splines)")->check(CLI::IsMember({"greville", "maxima"}))->capture_default_str();
  app.add_option("--joints", o.joints, "BEM splines across the joints of the boundary curve's elements: smooth (C^(p-1)) or split (discontinuous: full order on curves that are only C2 there, e.g. Catmull–Clark and cubic B-spline boundaries)")->check(CLI::IsMember({"smooth", "split"}))->capture_default_str();
  app.add_option("--solver", o.solver, "auto (LU up to 4000 unknowns, else GMRES), lu or gmres")->check(CLI::IsMember({"auto", "lu", "gmres"}))->capture_default_str();
  app.add_option("--gmres-tolerance", o.gmres_tolerance, "GMRES: relative residual to reach (beyond ~1000 dofs 1e-12 can leave an error above the discretisation error; 1e-14 is reachable)")->check(iga::io::finite_number(1e-16, 1e-2))->capture_default_str();
  app.add_option("--exact", o.exact, "exact (harmonic) solution u(x,y): default Dirichlet data and errors; default exp(x)*cos(y) when no data are given")->check(iga::io::non_blank());
  app.add_option("--dirichlet", o.dirichlet, "u on the Dirichlet boundary, g(x,y,z); default: --exact")->check(iga::io::non_blank());
  app.add_option("--neumann", o.neumann, "∂u/∂n on the Neumann parts, g(x,y,z,nx,ny,nz)")->check(iga::io::non_blank());
  app.add_option("--neumann-boundary", o.neumann_boundary, "comma-separated boundary parts with Neumann data (as iga-poisson)")->check(iga::io::non_blank());
  app.add_option("--neumann-where", o.neumann_where, "boundary edges whose midpoint makes this expression > 0 get Neumann data")->check(iga::io::non_blank());
  app.add_flag("--compare-fem", o.compare_fem, "also solve with the FEM on the same geometry and report the difference at the sample points");
  app.add_option("--grid", o.grid, "interior output on an N × N grid over the bounding box instead of the geometry's sampling")->check(iga::io::whole_number(2, 4000));
  app.add_option("--vtu-samples", o.samples, "sample points per direction per element (interior) and per BEM element (boundary)")->check(iga::io::whole_number(2, 64))->capture_default_str();
  app.add_option("--vtu", o.vtu, "interior solution for ParaView ('none' to skip)")->capture_default_str();
  app.add_option("--boundary-vtu", o.boundary_vtu, "boundary u and q as polylines ('none' to skip)")->capture_default_str();
  app.add_option("--json", o.json, "JSON report file ('none' to skip)")->capture_default_str();
  app.add_option("--threads", o.threads, "threads for assembly (default: OpenMP's)")->check(iga::io::thread_count());
  app.add_option("--max-seconds", o.max_seconds, "seconds the --grid interior evaluation may take: predicted before the solve from 64 of its points, a longer one is refused")->check(io::finite_number(1e-3, 1e9))->capture_default_str();
  app.add_option("--max-memory", o.max_memory, "GiB this run may use (default: what the system has available); a run predicted to need more is refused before it starts")->check(io::finite_number(0.001, 1e6));
  io::CommonOptions common{"iga-bem"};
  io::add_common_options(app, common);
  if (const auto code = io::parse_command_line(app, argc, argv, common)) return *code;
  if (const auto code = io::check_option_rules(app, common.program)) return *code;
  o.quiet = common.quiet;
  o.run_info = io::run_info(app, common.program);
  if (app.count("--geometry") > 0) o.given.emplace_back("geometry");
  return io::run_program("iga-bem", [&] { return run(o); });
}
