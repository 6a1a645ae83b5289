// iga's deal.II peer for plane elasticity (issue 31): Kirsch's infinite plate with a hole under tension T along x on
// the quarter plate [0, 4]² minus the disc r < 1, plane strain (E = 1e5, ν = 0.3, T = 10, as iga-elasticity's
// default), continuous Q_k × Q_k elements (FESystem), the hole exact (SphericalManifold on the hole, transfinite
// interpolation inside, MappingQ(k)), uniform refinement, UMFPACK; the JSON keys of iga-elasticity's report that the
// study reads. Built only by benchmarks/run_elasticity_study.
//
//   dealii-plate-with-hole --degree K --refine N [--json FILE]
//
// The coarse mesh has two cells (the hole's arcs 0 ≤ θ ≤ π/4 and π/4 ≤ θ ≤ π/2 joined to the sides x = 4 and y = 4),
// so level N has 2·4^N cells, as many as iga's NURBS plate at --refine N. Conditions as iga-elasticity's kirsch:
// u_y = 0 on y = 0, u_x = 0 on x = 0, Kirsch's traction σn on x = 4 and y = 4, the hole free.
// Errors by QGauss(K + 3): the L2 norm of the displacement error and the energy norm (∫ σ(e) : ε(e))^½, each also
// relative to the exact solution's norm; the exact strain from Kirsch's stresses through Hooke's law.
// Seconds: set-up (grid, dofs, sparsity), assembly (cells, tractions, constraints), solve (UMFPACK), one thread;
// total_seconds is their sum (no error norms).
#include <deal.II/base/function.h>
#include <deal.II/base/multithread_info.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping_q.h>
#include <deal.II/grid/manifold_lib.h>
#include <deal.II/grid/tria.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/sparse_direct.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/vector.h>
#include <deal.II/numerics/vector_tools.h>

#include <chrono>
#include <cmath>
#include <fstream>
#include <iostream>
#include <string>
#include <vector>

using namespace dealii;

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kYoung = 1e5, kNu = 0.3, kTension = 10.0, kRadius = 1.0, kSide = 4.0;
const double kLambda = kYoung * kNu / ((1 + kNu) * (1 - 2 * kNu)), kMu = kYoung / (2 * (1 + kNu));

// Kirsch's solution (pde/elasticity/kirsch.hpp gives the formulas): stresses and displacement at p, plane strain
// (κ = 3 − 4ν).
Tensor<2, 2> kirsch_stress(const Point<2>& p) {
  const double r = p.norm(), th = std::atan2(p[1], p[0]), a2 = kRadius * kRadius / (r * r), a4 = a2 * a2;
  Tensor<2, 2> s;
  s[0][0] = kTension * (1 - a2 * (1.5 * std::cos(2 * th) + std::cos(4 * th)) + 1.5 * a4 * std::cos(4 * th));
  s[1][1] = kTension * (-a2 * (0.5 * std::cos(2 * th) - std::cos(4 * th)) - 1.5 * a4 * std::cos(4 * th));
  s[0][1] = s[1][0] = kTension * (-a2 * (0.5 * std::sin(2 * th) + std::sin(4 * th)) + 1.5 * a4 * std::sin(4 * th));
  return s;
}

class KirschDisplacement : public Function<2> {
 public:
  KirschDisplacement() : Function<2>(2) {}
  double value(const Point<2>& p, unsigned int c) const override {
    const double r = p.norm(), th = std::atan2(p[1], p[0]), a = kRadius, kappa = 3 - 4 * kNu;
    const double f = kTension * a / (8 * kMu);
    if (c == 0) {
      return f * (r / a * (kappa + 1) * std::cos(th) + 2 * a / r * ((1 + kappa) * std::cos(th) + std::cos(3 * th)) -
                  2 * a * a * a / (r * r * r) * std::cos(3 * th));
    }
    return f * (r / a * (kappa - 3) * std::sin(th) + 2 * a / r * ((1 - kappa) * std::sin(th) + std::sin(3 * th)) -
                2 * a * a * a / (r * r * r) * std::sin(3 * th));
  }
};

// The strain of a stress (plane strain, in-plane): tr ε = tr σ / (2(λ + μ)), ε = (σ − λ tr ε I) / (2μ).
Tensor<2, 2> strain_of(const Tensor<2, 2>& s) {
  const double tr = (s[0][0] + s[1][1]) / (2 * (kLambda + kMu));
  Tensor<2, 2> e = s;
  e[0][0] -= kLambda * tr;
  e[1][1] -= kLambda * tr;
  return e / (2 * kMu);
}

double energy_density(const Tensor<2, 2>& e) {  // σ(e) : e
  const double tr = e[0][0] + e[1][1];
  return kLambda * tr * tr + 2 * kMu * scalar_product(e, e);
}

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

// Boundary ids: 0 y = 0, 1 x = 0, 2 the outer sides, 3 the hole. Manifold ids: 0 the hole (spherical), 1 the cells
// (transfinite interpolation between the hole and the straight sides).
void make_grid(int refine, Triangulation<2>& tria, SphericalManifold<2>& hole, TransfiniteInterpolationManifold<2>& inside) {
  const double c = kRadius * std::sqrt(0.5);
  const std::vector<Point<2>> vertices = {{kRadius, 0}, {kSide, 0}, {c, c}, {kSide, kSide}, {0, kRadius}, {0, kSide}};
  std::vector<CellData<2>> cells(2);
  cells[0].vertices = {0, 1, 2, 3};  // arc 0..π/4 (face 0) to x = 4 (face 1); y = 0 is face 2
  cells[1].vertices = {2, 3, 4, 5};  // arc π/4..π/2 (face 0) to y = 4 (face 1); x = 0 is face 3
  tria.create_triangulation(vertices, cells, SubCellData());
  for (const auto& cell : tria.active_cell_iterators()) {
    cell->set_all_manifold_ids(1);
    for (const unsigned int f : cell->face_indices()) {
      if (!cell->face(f)->at_boundary()) continue;
      const Point<2> m = cell->face(f)->center();
      if (std::abs(m[1]) < 1e-12) {
        cell->face(f)->set_boundary_id(0);
      } else if (std::abs(m[0]) < 1e-12) {
        cell->face(f)->set_boundary_id(1);
      } else if (std::abs(m[0] - kSide) < 1e-12 || std::abs(m[1] - kSide) < 1e-12) {
        cell->face(f)->set_boundary_id(2);
      } else {
        cell->face(f)->set_boundary_id(3);
        cell->face(f)->set_manifold_id(0);
      }
    }
  }
  tria.set_manifold(0, hole);
  inside.initialize(tria);
  tria.set_manifold(1, inside);
  tria.refine_global(static_cast<unsigned int>(refine));
}

int run(int degree, int refine, const std::string& json) {
  MultithreadInfo::set_thread_limit(1);
  const auto start = std::chrono::steady_clock::now();
  Triangulation<2> tria;
  SphericalManifold<2> hole(Point<2>(0, 0));
  TransfiniteInterpolationManifold<2> inside;
  make_grid(refine, tria, hole, inside);
  const FESystem<2> fe(FE_Q<2>(static_cast<unsigned int>(degree)), 2);
  const MappingQ<2> mapping(static_cast<unsigned int>(degree));
  DoFHandler<2> dofs(tria);
  dofs.distribute_dofs(fe);
  const double setup_dofs = seconds_since(start);

  const auto t_constraints = std::chrono::steady_clock::now();
  AffineConstraints<double> constraints;
  const FEValuesExtractors::Scalar ux(0), uy(1);
  VectorTools::interpolate_boundary_values(mapping, dofs, 0, Functions::ZeroFunction<2>(2), constraints, fe.component_mask(uy));
  VectorTools::interpolate_boundary_values(mapping, dofs, 1, Functions::ZeroFunction<2>(2), constraints, fe.component_mask(ux));
  constraints.close();
  const double constraint_seconds = seconds_since(t_constraints);

  const auto t_pattern = std::chrono::steady_clock::now();
  DynamicSparsityPattern dsp(dofs.n_dofs());
  DoFTools::make_sparsity_pattern(dofs, dsp, constraints, false);
  SparsityPattern pattern;
  pattern.copy_from(dsp);
  SparseMatrix<double> matrix(pattern);
  Vector<double> rhs(dofs.n_dofs()), solution(dofs.n_dofs());
  const double setup = setup_dofs + seconds_since(t_pattern);

  // a(u, v) = ∫ λ div u div v + 2μ ε(u) : ε(v); for φ_i e_a and φ_j e_b:
  // λ ∂_a φ_i ∂_b φ_j + μ ∂_b φ_i ∂_a φ_j + μ δ_ab ∇φ_i · ∇φ_j.
  const auto t_cells = std::chrono::steady_clock::now();
  const QGauss<2> quadrature(static_cast<unsigned int>(degree + 1));
  const QGauss<1> face_quadrature(static_cast<unsigned int>(degree + 1));
  FEValues<2> fv(mapping, fe, quadrature, update_gradients | update_JxW_values);
  FEFaceValues<2> ff(mapping, fe, face_quadrature, update_values | update_quadrature_points | update_normal_vectors | update_JxW_values);
  const unsigned int n = fe.n_dofs_per_cell(), nq = quadrature.size();
  FullMatrix<double> cell_matrix(n, n);
  Vector<double> cell_rhs(n);
  std::vector<types::global_dof_index> local(n);
  std::vector<unsigned int> component(n);
  for (unsigned int i = 0; i < n; ++i) component[i] = fe.system_to_component_index(i).first;
  for (const auto& cell : dofs.active_cell_iterators()) {
    fv.reinit(cell);
    cell_matrix = 0;
    cell_rhs = 0;
    for (unsigned int q = 0; q < nq; ++q) {
      const double w = fv.JxW(q);
      for (unsigned int i = 0; i < n; ++i) {
        const Tensor<1, 2> gi = fv.shape_grad(i, q) * w;
        const unsigned int a = component[i];
        for (unsigned int j = 0; j < n; ++j) {
          const Tensor<1, 2> gj = fv.shape_grad(j, q);
          const unsigned int b = component[j];
          cell_matrix(i, j) += kLambda * gi[a] * gj[b] + kMu * gi[b] * gj[a] + (a == b ? kMu * (gi * gj) : 0.0);
        }
      }
    }
    for (const unsigned int f : cell->face_indices()) {
      if (!cell->face(f)->at_boundary() || cell->face(f)->boundary_id() != 2) continue;
      ff.reinit(cell, f);
      for (unsigned int q = 0; q < ff.n_quadrature_points; ++q) {
        const Tensor<1, 2> t = kirsch_stress(ff.quadrature_point(q)) * ff.normal_vector(q);
        for (unsigned int i = 0; i < n; ++i) cell_rhs(i) += t[component[i]] * ff.shape_value(i, q) * ff.JxW(q);
      }
    }
    cell->get_dof_indices(local);
    constraints.distribute_local_to_global(cell_matrix, cell_rhs, local, matrix, rhs);
  }
  const double assembly = seconds_since(t_cells) + constraint_seconds;

  const auto t_solve = std::chrono::steady_clock::now();
  SparseDirectUMFPACK umfpack;
  umfpack.initialize(matrix);
  umfpack.vmult(solution, rhs);
  constraints.distribute(solution);
  const double solve = seconds_since(t_solve);
  const double total = seconds_since(start);

  // Errors: ‖u − u_h‖_L2 and (∫ σ(e) : ε(e))^½ with e = ε(u) − ε(u_h), and the exact solution's norms.
  const QGauss<2> error_rule(static_cast<unsigned int>(degree + 3));
  FEValues<2> fe_err(mapping, fe, error_rule, update_values | update_gradients | update_quadrature_points | update_JxW_values);
  const KirschDisplacement exact;
  std::vector<Tensor<1, 2>> values(error_rule.size());
  std::vector<Tensor<2, 2>> gradients(error_rule.size());
  const FEValuesExtractors::Vector u(0);
  double l2 = 0, l2_exact = 0, energy = 0, energy_exact = 0;
  for (const auto& cell : dofs.active_cell_iterators()) {
    fe_err.reinit(cell);
    fe_err[u].get_function_values(solution, values);
    fe_err[u].get_function_gradients(solution, gradients);
    for (unsigned int q = 0; q < error_rule.size(); ++q) {
      const Point<2>& x = fe_err.quadrature_point(q);
      const double w = fe_err.JxW(q);
      const Tensor<2, 2> eps = strain_of(kirsch_stress(x));
      const Tensor<2, 2> eps_h = 0.5 * (gradients[q] + transpose(gradients[q]));
      for (unsigned int c = 0; c < 2; ++c) {
        const double uc = exact.value(x, c);
        l2 += (uc - values[q][c]) * (uc - values[q][c]) * w;
        l2_exact += uc * uc * w;
      }
      energy += energy_density(eps - eps_h) * w;
      energy_exact += energy_density(eps) * w;
    }
  }
  l2 = std::sqrt(l2);
  energy = std::sqrt(energy);
  l2_exact = std::sqrt(l2_exact);
  energy_exact = std::sqrt(energy_exact);

  std::ofstream out(json.empty() ? "/dev/stdout" : json);
  out.precision(17);
  out << "{\n \"program\": \"dealii-plate-with-hole\",\n \"basis\": \"dealii-Q" << degree << "\",\n \"degree\": " << degree
      << ",\n \"refine\": " << refine << ",\n \"dofs\": " << dofs.n_dofs() << ",\n \"elements\": " << tria.n_active_cells()
      << ",\n \"quadrature_points\": " << tria.n_active_cells() * nq << ",\n \"nonzeros\": " << matrix.n_nonzero_elements()
      << ",\n \"errors\": {\"L2\": {\"error\": " << l2 << ", \"exact\": " << l2_exact << ", \"relative\": " << l2 / l2_exact
      << "}, \"energy\": {\"error\": " << energy << ", \"exact\": " << energy_exact << ", \"relative\": " << energy / energy_exact
      << "}},\n \"error_quadrature\": \"gauss:" << degree + 3 << "\",\n \"setup_seconds\": " << setup
      << ",\n \"assembly_seconds\": " << assembly << ",\n \"solve_seconds\": " << solve << ",\n \"total_seconds\": " << total
      << ",\n \"solver\": \"umfpack\",\n \"threads\": 1\n}\n";
  return out ? 0 : 1;
}

}  // namespace

int main(int argc, char** argv) {
  std::string json;
  int degree = 2, refine = 3;
  if (argc % 2 == 0) {
    std::cerr << "dealii-plate-with-hole: error: options come in pairs (--degree K --refine N --json FILE)\n";
    return 1;
  }
  for (int i = 1; i + 1 < argc; i += 2) {
    const std::string key = argv[i], value = argv[i + 1];
    if (key == "--degree") {
      degree = std::stoi(value);
    } else if (key == "--refine") {
      refine = std::stoi(value);
    } else if (key == "--json") {
      json = value;
    } else {
      std::cerr << "dealii-plate-with-hole: error: unknown option " << key << "\n";
      return 1;
    }
  }
  try {
    if (degree < 1 || degree > 6 || refine < 0 || refine > 10) throw std::runtime_error("--degree 1..6, --refine 0..10");
    return run(degree, refine, json);
  } catch (const std::exception& e) {
    std::cerr << "dealii-plate-with-hole: error: " << e.what() << "\n";
    return 1;
  }
}
