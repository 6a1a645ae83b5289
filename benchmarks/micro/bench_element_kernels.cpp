// Element kernels of every backend (issue 17), Google Benchmark: one element's Poisson work as the assembler does it
// (Assembler::prepare: basis, map, physical gradients; then the stiffness and load forms), cycling over the elements
// of a mid-sized mesh, and the whole assembly with its scatter, per element. Counters:
//   ns/element   the kernel's time per element;
//   GFLOP/s      flops counted from the loop structure (below) per second;
//   scatter_GB/s for BM_Assembly: bytes of the scatter (8 bytes read + 8 written per matrix entry, 4 per row index
//                read) per second of (assembly − kernel) time, the scatter's achieved bandwidth.
// Flops per element with n local functions, q points, planar (dim 2), counted from the loop structure of what runs:
// basis tensor products 3nq (none for an element whose reference values are a twin's, copied), the map's x, x_u, x_v
// 12nq (two rows), physical gradients 6nq, weighted copies 2nq, load 2nq, and the stiffness G W G^T 4n²q, or 3n²q
// on the compile-time bicubic path (16 × 16, symmetric: the upper right quarter is mirrored). A bicubic twin
// element: 3n²q + 22nq = 17,920. Rational (NURBS) and subdivision elements do more than counted.
//
//   build/benchmarks/micro/bench-element-kernels --benchmark_min_time=0.5
#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "basis/bspline/patches.hpp"
#include "basis/registry.hpp"
#include "fem/assembler.hpp"
#include "fem/forms.hpp"
#include "fem/function.hpp"
#include "fem/threads.hpp"
#include "mesh/obj_reader.hpp"
#include "mesh/three_valent.hpp"
#include "pde/biharmonic/forms.hpp"
#include "pde/elasticity/forms.hpp"
#include "pde/shell/forms.hpp"
#include "quadrature/rule_provider.hpp"
#include "refine/uniform.hpp"

using namespace iga;

namespace {

struct Case {
  basis::Geometry geometry;
  std::unique_ptr<quadrature::RuleProvider> rules;
};

std::string data(const std::string& name) { return std::string(IGA_SOURCE_DIR) + "/data/meshes/" + name; }

Case make_case(const std::string& name) {
  basis::BackendFacts facts;
  basis::BackendOptions o;
  auto build = [&](const std::string& backend, const mesh::PolyMesh* net, int steps, const std::string& rule) {
    const basis::Backend& b = basis::backend(backend);
    basis::Geometry g = basis::make_refined_geometry(b, net, o, steps, facts).geometry;
    return Case{std::move(g), quadrature::make_rule_provider(rule.empty() ? b.default_quadrature(basis::degree(b, o)) : rule,
                                                                basis::degree(b, o) + 1)};
  };
  if (name == "bspline3") {
    o.degree = 3;
    o.geometry = "square";
    return build("bspline", nullptr, 6, "");
  }
  if (name == "nurbs3") {
    o.degree = 3;
    return build("bspline", nullptr, 6, "");
  }
  if (name == "roof3") {  // a surface: the Scordelis-Lo roof, a NURBS cylinder patch in 3D
    o.degree = 3;
    o.geometry = "scordelis-lo-roof";
    return build("bspline", nullptr, 6, "");
  }
  if (name == "cc_torus") {  // a closed Catmull-Clark surface with EVs of valence 3 and 5
    const mesh::PolyMesh net = mesh::read_obj(data("torus_evs.obj"));
    return build("cc", &net, 3, "tiles:4:8");
  }
  if (name == "bspline5") {
    o.degree = 5;
    o.geometry = "square";
    return build("bspline", nullptr, 5, "");
  }
  if (name == "cc_regular") {
    const mesh::PolyMesh net = mesh::read_obj(data("square_6x6.obj"));
    return build("cc", &net, 4, "gauss:4");
  }
  if (name == "cc_evs") {
    const mesh::PolyMesh net = mesh::read_obj(data("square_evs.obj"));
    return build("cc", &net, 3, "tiles:4:8");
  }
  if (name == "polyhedral") {
    const mesh::PolyMesh net = mesh::read_obj(data("square_evs.obj"));
    return build("polyhedral", &net, 3, "");
  }
  const mesh::PolyMesh net = mesh::dual_net(mesh::read_obj(data("tri_square.obj")));
  return build("halfbox", &net, 2, "");
}

const Case& cached(const std::string& name) {
  static std::map<std::string, Case> cases;
  auto it = cases.find(name);
  if (it == cases.end()) it = cases.emplace(name, make_case(name)).first;
  return it->second;
}

double flops_per_element(const basis::Space& space, const fem::ElementContext& ctx) {
  const double n = static_cast<double>(ctx.basis.value.rows()), q = static_cast<double>(ctx.num_points());
  const bool bicubic = ctx.basis.value.rows() == 16 && ctx.grad.cols() == 32;
  const bool twin = space.reference_element(ctx.element) != ctx.element;
  return (bicubic ? 3 : 4) * n * n * q + (twin ? 0 : 3) * n * q + 22 * n * q;
}

void element_kernel(benchmark::State& state, const std::string& name) {
  fem::set_num_threads(1);
  const Case& c = cached(name);
  const fem::Assembler assembler(c.geometry, *c.rules);
  const fem::StiffnessForm stiffness;
  const fem::SourceForm load(fem::make_function([](const Eigen::Vector3d& x) { return x(0) * x(1) + 1.0; }));
  fem::ElementContext ctx;
  Eigen::MatrixXd k;
  Eigen::VectorXd f;
  const Index ne = c.geometry.space().num_elements();
  Index e = 0;
  double flops = 0.0;
  for (auto _ : state) {
    assembler.prepare(e, ctx);
    const Index n = ctx.basis.value.rows();
    k.setZero(n, n);
    f.setZero(n);
    stiffness.add(ctx, k);
    load.add(ctx, f);
    benchmark::DoNotOptimize(k.data());
    benchmark::DoNotOptimize(f.data());
    flops += flops_per_element(c.geometry.space(), ctx);
    e = (e + 1) % ne;
  }
  state.counters["ns/element"] = benchmark::Counter(static_cast<double>(state.iterations()) * 1e-9,
                                                    benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
  state.counters["GFLOP/s"] = benchmark::Counter(flops * 1e-9, benchmark::Counter::kIsRate);
  state.counters["elements"] = static_cast<double>(ne);
  state.counters["points"] = static_cast<double>(ctx.num_points());
  state.counters["local_dofs"] = static_cast<double>(ctx.basis.value.rows());
}

// The whole assembly (one thread) per element, and the scatter's bandwidth from its time beyond the kernels'.
void assembly(benchmark::State& state, const std::string& name) {
  fem::set_num_threads(1);
  const Case& c = cached(name);
  const fem::Assembler assembler(c.geometry, *c.rules);
  const fem::StiffnessForm stiffness;
  const fem::SourceForm load(fem::make_function([](const Eigen::Vector3d& x) { return x(0) * x(1) + 1.0; }));
  const std::vector<const fem::BilinearForm*> bf{&stiffness};
  const std::vector<const fem::LinearForm*> lf{&load};
  Eigen::SparseMatrix<double> a;
  Eigen::VectorXd b;
  assembler.plan();  // the pattern and colouring once, outside the timing
  const Index ne = c.geometry.space().num_elements();
  double entries = 0.0;
  for (Index e = 0; e < ne; ++e) {
    const double n = static_cast<double>(c.geometry.space().dofs(e).size());
    entries += n * n;
  }
  // The kernels alone over all elements, timed once before, for the scatter's share.
  fem::ElementContext ctx;
  Eigen::MatrixXd k;
  Eigen::VectorXd f;
  const auto t0 = std::chrono::steady_clock::now();
  for (Index e = 0; e < ne; ++e) {
    assembler.prepare(e, ctx);
    k.setZero(ctx.basis.value.rows(), ctx.basis.value.rows());
    f.setZero(ctx.basis.value.rows());
    stiffness.add(ctx, k);
    load.add(ctx, f);
    benchmark::DoNotOptimize(k.data());
  }
  const double kernels = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  double total = 0.0;
  for (auto _ : state) {
    const auto t = std::chrono::steady_clock::now();
    assembler.assemble(bf, lf, a, b);
    total += std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
    benchmark::DoNotOptimize(a.valuePtr());
  }
  const double runs = static_cast<double>(state.iterations());
  const double scatter = std::max(total / runs - kernels, 1e-12);
  state.counters["ns/element"] = total / runs / static_cast<double>(ne) * 1e9;
  state.counters["kernel_share"] = kernels / (total / runs);
  state.counters["scatter_GB/s"] = entries * 20.0 / scatter * 1e-9;
  state.counters["elements"] = static_cast<double>(ne);
}

// One element's work for each PDE as the assembler does it (issue 31): prepare() to the order the forms ask for,
// then the forms. "poisson": stiffness + load (the element_kernel above); "biharmonic": ∫ Δφ Δφ (second
// derivatives through the map) + load; "elasticity": the two-component σ:ε matrix + a body force. The goal is
// biharmonic ≤ 2 ×, elasticity ≤ 4 × Poisson's µs per element on bicubic elements.
void pde_kernel(benchmark::State& state, const std::string& name, const std::string& pde) {
  fem::set_num_threads(1);
  const Case& c = cached(name);
  const auto f = fem::make_function([](const Eigen::Vector3d& x) { return x(0) * x(1) + 1.0; });
  const fem::StiffnessForm stiffness;
  const pde::BiharmonicForm biharmonic;
  const pde::ElasticityForm elasticity(pde::lame(1.0, 0.3, pde::PlaneModel::kStrain));
  const pde::KirchhoffLoveForm shell({1.0, 0.3, 0.01});
  const pde::ShellLoadForm area({nullptr, nullptr, f}, nullptr);
  const fem::SourceForm load(f);
  const pde::BodyForceForm body({f, f});
  const fem::BilinearForm* a = pde == "poisson" ? static_cast<const fem::BilinearForm*>(&stiffness)
                               : pde == "biharmonic" ? static_cast<const fem::BilinearForm*>(&biharmonic)
                               : pde == "shell"      ? static_cast<const fem::BilinearForm*>(&shell)
                                                     : static_cast<const fem::BilinearForm*>(&elasticity);
  const fem::LinearForm* l = pde == "elasticity" ? static_cast<const fem::LinearForm*>(&body)
                             : pde == "shell"    ? static_cast<const fem::LinearForm*>(&area)
                                                 : static_cast<const fem::LinearForm*>(&load);
  const fem::Assembler assembler(c.geometry, *c.rules, a->components());
  const int derivatives = std::max(a->derivatives(), l->derivatives());
  const bool hessian = a->derivatives() >= 2 && a->hessian();
  fem::ElementContext ctx;
  Eigen::MatrixXd k;
  Eigen::VectorXd v;
  const Index ne = c.geometry.space().num_elements();
  Index e = 0;
  for (auto _ : state) {
    assembler.prepare(e, ctx, derivatives, hessian);
    const Index n = a->components() * ctx.basis.value.rows();
    k.setZero(n, n);
    v.setZero(n);
    a->add(ctx, k);
    l->add(ctx, v);
    benchmark::DoNotOptimize(k.data());
    benchmark::DoNotOptimize(v.data());
    e = (e + 1) % ne;
  }
  state.counters["ns/element"] = benchmark::Counter(static_cast<double>(state.iterations()) * 1e-9,
                                                    benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
  state.counters["local_dofs"] = static_cast<double>(a->components() * ctx.basis.value.rows());
}

}  // namespace

BENCHMARK_CAPTURE(pde_kernel, bspline3_poisson, std::string("bspline3"), std::string("poisson"));
BENCHMARK_CAPTURE(pde_kernel, bspline3_biharmonic, std::string("bspline3"), std::string("biharmonic"));
BENCHMARK_CAPTURE(pde_kernel, bspline3_elasticity, std::string("bspline3"), std::string("elasticity"));
BENCHMARK_CAPTURE(pde_kernel, nurbs3_poisson, std::string("nurbs3"), std::string("poisson"));
BENCHMARK_CAPTURE(pde_kernel, nurbs3_biharmonic, std::string("nurbs3"), std::string("biharmonic"));
BENCHMARK_CAPTURE(pde_kernel, nurbs3_elasticity, std::string("nurbs3"), std::string("elasticity"));
BENCHMARK_CAPTURE(pde_kernel, roof3_poisson, std::string("roof3"), std::string("poisson"));
BENCHMARK_CAPTURE(pde_kernel, roof3_shell, std::string("roof3"), std::string("shell"));
BENCHMARK_CAPTURE(pde_kernel, cc_torus_poisson, std::string("cc_torus"), std::string("poisson"));
BENCHMARK_CAPTURE(pde_kernel, cc_torus_shell, std::string("cc_torus"), std::string("shell"));
BENCHMARK_CAPTURE(element_kernel, bspline3, std::string("bspline3"));
BENCHMARK_CAPTURE(element_kernel, bspline5, std::string("bspline5"));
BENCHMARK_CAPTURE(element_kernel, nurbs3, std::string("nurbs3"));
BENCHMARK_CAPTURE(element_kernel, cc_regular, std::string("cc_regular"));
BENCHMARK_CAPTURE(element_kernel, cc_evs, std::string("cc_evs"));
BENCHMARK_CAPTURE(element_kernel, polyhedral, std::string("polyhedral"));
BENCHMARK_CAPTURE(element_kernel, halfbox, std::string("halfbox"));
BENCHMARK_CAPTURE(assembly, bspline3, std::string("bspline3"))->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(assembly, nurbs3, std::string("nurbs3"))->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(assembly, cc_evs, std::string("cc_evs"))->Unit(benchmark::kMillisecond);

BENCHMARK_MAIN();
