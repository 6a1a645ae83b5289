// iga's deal.II peer (issue 17): -Δu = f with continuous Q_k elements on the problems of benchmarks/run_study,
// uniform refinement, UMFPACK, writing the JSON keys of iga-poisson. Built only by benchmarks/run_study.
//
//   dealii-poisson --problem square|square-neumann|annulus|l-shape --degree K --refine N [--json FILE]
//
// square:          [0,1]², u = sin πx sin πy + x y², Dirichlet everywhere
// square-neumann:  [0,1]², u = (cos πx − 1) sin 2πy, Neumann on x = 1 (∂u/∂n = 0 there), Dirichlet elsewhere
// annulus:         the quarter annulus 1 <= r <= 2 (a SphericalManifold, MappingQ(K)), u = eˣ sin y (harmonic)
// l-shape:         [0,2]² minus (1,2]², u = r^(2/3) sin(2φ/3) about the reflex corner (1,1), φ from the edge x = 1
//
// Errors by QGauss(K + 3) (L2 norm and H1 seminorm), as iga's error norms use a richer rule than the assembly.
// Seconds: set-up (grid, dofs, sparsity), assembly (cell loop and boundary values), solve (UMFPACK factorisation
// and solve); total_seconds is their sum (no error norms), all on one thread.
#include <deal.II/base/function.h>
#include <deal.II/base/multithread_info.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping_q.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/manifold_lib.h>
#include <deal.II/grid/tria.h>
#include <deal.II/grid/tria_description.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/sparse_direct.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/vector.h>
#include <deal.II/numerics/vector_tools.h>

#include <chrono>
#include <cstdlib>
#include <cmath>
#include <fstream>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

using namespace dealii;

namespace {

constexpr double kPi = 3.14159265358979323846;

// The exact solution of a problem and its source f = -Δu.
class Exact : public Function<2> {
 public:
  explicit Exact(std::string problem) : problem_(std::move(problem)) {}

  double value(const Point<2>& p, unsigned int = 0) const override {
    const double x = p[0], y = p[1];
    if (problem_ == "square") return std::sin(kPi * x) * std::sin(kPi * y) + x * y * y;
    if (problem_ == "square-neumann") return (std::cos(kPi * x) - 1.0) * std::sin(2 * kPi * y);
    if (problem_ == "annulus") return std::exp(x) * std::sin(y);
    double r, theta, phi;
    polar(p, r, theta, phi);
    return std::pow(r, 2.0 / 3.0) * std::sin(2.0 / 3.0 * phi);
  }

  Tensor<1, 2> gradient(const Point<2>& p, unsigned int = 0) const override {
    const double x = p[0], y = p[1];
    Tensor<1, 2> g;
    if (problem_ == "square") {
      g[0] = kPi * std::cos(kPi * x) * std::sin(kPi * y) + y * y;
      g[1] = kPi * std::sin(kPi * x) * std::cos(kPi * y) + 2 * x * y;
    } else if (problem_ == "square-neumann") {
      g[0] = -kPi * std::sin(kPi * x) * std::sin(2 * kPi * y);
      g[1] = 2 * kPi * (std::cos(kPi * x) - 1.0) * std::cos(2 * kPi * y);
    } else if (problem_ == "annulus") {
      g[0] = std::exp(x) * std::sin(y);
      g[1] = std::exp(x) * std::cos(y);
    } else {
      // ∇u = α r^(α−1) (sin(αφ − θ), cos(αφ − θ)), α = 2/3.
      double r, theta, phi;
      polar(p, r, theta, phi);
      const double a = 2.0 / 3.0, s = a * std::pow(r, a - 1.0);
      g[0] = s * std::sin(a * phi - theta);
      g[1] = s * std::cos(a * phi - theta);
    }
    return g;
  }

  double source(const Point<2>& p) const {
    const double x = p[0], y = p[1];
    if (problem_ == "square") return 2 * kPi * kPi * std::sin(kPi * x) * std::sin(kPi * y) - 2 * x;
    if (problem_ == "square-neumann") {
      return kPi * kPi * std::cos(kPi * x) * std::sin(2 * kPi * y) +
             4 * kPi * kPi * (std::cos(kPi * x) - 1.0) * std::sin(2 * kPi * y);
    }
    return 0.0;  // annulus and l-shape: harmonic
  }

 private:
  // Polar coordinates about (1, 1), φ = θ − π/2 in [0, 2π).
  static void polar(const Point<2>& p, double& r, double& theta, double& phi) {
    r = std::hypot(p[0] - 1, p[1] - 1);
    theta = std::atan2(p[1] - 1, p[0] - 1);
    phi = theta - kPi / 2;
    if (phi < 0) phi += 2 * kPi;
  }
  std::string problem_;
};

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

// "fan-N" (N = 3..12): the N of the regular N-gon; 0 otherwise.
int fan_valence(const std::string& problem) {
  if (problem.rfind("fan-", 0) != 0) return 0;
  const int n = std::atoi(problem.c_str() + 4);
  return n >= 3 && n <= 12 && problem == "fan-" + std::to_string(n) ? n : 0;
}

// The number of cells of the coarse mesh (reported as coarse_cells).
unsigned int coarse_cells = 0;

void make_grid(const std::string& problem, int refine, Triangulation<2>& tria) {
  if (problem == "square" || problem == "square-neumann") {
    GridGenerator::hyper_cube(tria, 0.0, 1.0, true);  // boundary ids: x = 0 → 0, x = 1 → 1, y = 0 → 2, y = 1 → 3
  } else if (problem == "annulus") {
    // deal.II's default coarse mesh (n_cells = 0: as many cells around as give the least aspect ratio, here 3 of
    // 1 × 0.79 at mid-radius), the best coarse mesh for this problem (issue 33: one cell of aspect 2.4 handicapped it).
    GridGenerator::quarter_hyper_shell(tria, Point<2>(), 1.0, 2.0);
    tria.set_all_manifold_ids(0);
    tria.set_manifold(0, SphericalManifold<2>(Point<2>()));
  } else if (problem == "l-shape") {
    GridGenerator::hyper_L(tria, 0.0, 2.0);
  } else if (const int n = fan_valence(problem); n > 0) {
    // data/meshes/fan_N.obj as a mesh (tools/make_meshes.py): the regular N-gon of circumradius 0.5 about (0.5, 0.5),
    // N quads (centre, edge midpoint k, corner k + 1, edge midpoint k + 1) around the centre.
    std::vector<Point<2>> vertices{Point<2>(0.5, 0.5)};
    for (int k = 0; k < n; ++k) {
      vertices.emplace_back(0.5 + 0.5 * std::cos(2 * kPi * k / n), 0.5 + 0.5 * std::sin(2 * kPi * k / n));
    }
    for (int k = 0; k < n; ++k) vertices.push_back(0.5 * (vertices[1 + k] + vertices[1 + (k + 1) % n]));
    std::vector<CellData<2>> cells(static_cast<std::size_t>(n));
    for (int k = 0; k < n; ++k) {
      // deal.II's vertex order is lexicographic: (a, b, d, c) for the counter-clockwise quad (a, b, c, d).
      const unsigned int a = 0, b = 1 + n + k, c = 1 + (k + 1) % n, d = 1 + n + (k + 1) % n;
      cells[static_cast<std::size_t>(k)].vertices = {a, b, d, c};
    }
    tria.create_triangulation(vertices, cells, SubCellData());
  } else {
    throw std::runtime_error("unknown --problem '" + problem + "' (square, square-neumann, annulus, l-shape, fan-N)");
  }
  coarse_cells = tria.n_active_cells();
  tria.refine_global(static_cast<unsigned int>(refine));
}

int run(const std::string& problem, int degree, int refine, const std::string& json) {
  MultithreadInfo::set_thread_limit(1);
  const auto start = std::chrono::steady_clock::now();
  Triangulation<2> tria;
  make_grid(problem, refine, tria);
  const FE_Q<2> fe(static_cast<unsigned int>(degree));
  const MappingQ<2> mapping(static_cast<unsigned int>(degree));
  DoFHandler<2> dofs(tria);
  dofs.distribute_dofs(fe);
  const Exact exact(fan_valence(problem) > 0 ? "square" : problem);  // fan-N: the square's u on the N-gon
  const double setup_dofs = seconds_since(start);
  // Dirichlet data by interpolation at the support points; square-neumann keeps x = 1 (id 1) natural.
  const auto t_boundary = std::chrono::steady_clock::now();
  AffineConstraints<double> constraints;
  for (const types::boundary_id id : tria.get_boundary_ids()) {
    if (problem == "square-neumann" && id == 1) continue;
    VectorTools::interpolate_boundary_values(mapping, dofs, id, exact, constraints);
  }
  constraints.close();
  const double boundary = seconds_since(t_boundary);
  const auto t_pattern = std::chrono::steady_clock::now();
  DynamicSparsityPattern dsp(dofs.n_dofs());
  DoFTools::make_sparsity_pattern(dofs, dsp, constraints, false);
  SparsityPattern pattern;
  pattern.copy_from(dsp);
  SparseMatrix<double> matrix(pattern);
  Vector<double> rhs(dofs.n_dofs()), solution(dofs.n_dofs());
  const double setup = setup_dofs + seconds_since(t_pattern);

  const auto t_cells = std::chrono::steady_clock::now();
  const QGauss<2> quadrature(static_cast<unsigned int>(degree + 1));
  FEValues<2> fv(mapping, fe, quadrature, update_values | update_gradients | update_quadrature_points | update_JxW_values);
  const unsigned int n = fe.n_dofs_per_cell(), nq = quadrature.size();
  FullMatrix<double> cell_matrix(n, n);
  Vector<double> cell_rhs(n);
  std::vector<types::global_dof_index> local(n);
  for (const auto& cell : dofs.active_cell_iterators()) {
    fv.reinit(cell);
    cell_matrix = 0;
    cell_rhs = 0;
    for (unsigned int q = 0; q < nq; ++q) {
      const double f = exact.source(fv.quadrature_point(q)) * fv.JxW(q);
      for (unsigned int i = 0; i < n; ++i) {
        const Tensor<1, 2> gi = fv.shape_grad(i, q) * fv.JxW(q);
        for (unsigned int j = 0; j < n; ++j) cell_matrix(i, j) += gi * fv.shape_grad(j, q);
        cell_rhs(i) += f * fv.shape_value(i, q);
      }
    }
    cell->get_dof_indices(local);
    constraints.distribute_local_to_global(cell_matrix, cell_rhs, local, matrix, rhs);
  }
  const double assembly = seconds_since(t_cells) + boundary;

  const auto t_solve = std::chrono::steady_clock::now();
  SparseDirectUMFPACK umfpack;
  umfpack.initialize(matrix);
  umfpack.vmult(solution, rhs);
  constraints.distribute(solution);
  const double solve = seconds_since(t_solve);
  const double total = seconds_since(start);

  Vector<double> cellwise(tria.n_active_cells());
  const QGauss<2> error_rule(static_cast<unsigned int>(degree + 3));
  VectorTools::integrate_difference(mapping, dofs, solution, exact, cellwise, error_rule, VectorTools::L2_norm);
  const double l2 = VectorTools::compute_global_error(tria, cellwise, VectorTools::L2_norm);
  VectorTools::integrate_difference(mapping, dofs, solution, exact, cellwise, error_rule, VectorTools::H1_seminorm);
  const double h1 = VectorTools::compute_global_error(tria, cellwise, VectorTools::H1_seminorm);

  std::ofstream out(json.empty() ? "/dev/stdout" : json);
  out.precision(17);
  out << "{\n \"program\": \"dealii-poisson\",\n \"basis\": \"dealii-Q" << degree << "\",\n \"problem\": \"" << problem
      << "\",\n \"degree\": " << degree << ",\n \"refine\": " << refine << ",\n \"dofs\": " << dofs.n_dofs()
      << ",\n \"elements\": " << tria.n_active_cells() << ",\n \"coarse_cells\": " << coarse_cells
      << ",\n \"quadrature_points\": " << tria.n_active_cells() * nq
      << ",\n \"nonzeros\": " << matrix.n_nonzero_elements() << ",\n \"l2_error\": " << l2 << ",\n \"h1_error\": " << h1
      << ",\n \"error_quadrature\": \"gauss:" << degree + 3 << "\",\n \"setup_seconds\": " << setup
      << ",\n \"assembly_seconds\": " << assembly << ",\n \"solve_seconds\": " << solve << ",\n \"total_seconds\": " << total
      << ",\n \"solver\": \"umfpack\",\n \"threads\": 1\n}\n";
  return out ? 0 : 1;
}

}  // namespace

int main(int argc, char** argv) {
  std::string problem = "square", json;
  int degree = 2, refine = 3;
  for (int i = 1; i + 1 < argc; i += 2) {
    const std::string key = argv[i], value = argv[i + 1];
    if (key == "--problem") {
      problem = value;
    } else if (key == "--degree") {
      degree = std::stoi(value);
    } else if (key == "--refine") {
      refine = std::stoi(value);
    } else if (key == "--json") {
      json = value;
    } else {
      std::cerr << "dealii-poisson: error: unknown option " << key << "\n";
      return 1;
    }
  }
  if (argc % 2 == 0) {
    std::cerr << "dealii-poisson: error: options come in pairs (--problem P --degree K --refine N --json FILE)\n";
    return 1;
  }
  try {
    if (degree < 1 || degree > 6 || refine < 0 || refine > 12) throw std::runtime_error("--degree 1..6, --refine 0..12");
    return run(problem, degree, refine, json);
  } catch (const std::exception& e) {
    std::cerr << "dealii-poisson: error: " << e.what() << "\n";
    return 1;
  }
}
