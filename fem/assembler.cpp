#include "fem/assembler.hpp"

#include <omp.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <atomic>
#include <exception>
#include <mutex>

#include "core/error.hpp"

namespace iga::fem {

namespace {
// Runs body(i) for i in [0, n) with OpenMP; the first exception thrown is rethrown after the loop.
template <class Body>
void parallel_for(Index n, Body&& body) {
  std::exception_ptr error;
  std::atomic<bool> failed{false};
  std::mutex m;
#pragma omp parallel for schedule(static)
  for (Index i = 0; i < n; ++i) {
    if (failed.load(std::memory_order_relaxed)) continue;
    try {
      body(i);
    } catch (...) {
      std::lock_guard<std::mutex> lock(m);
      if (!error) error = std::current_exception();
      failed = true;
    }
  }
  if (error) std::rethrow_exception(error);
}
}  // namespace

Assembler::Assembler(const basis::Geometry& geometry, const quadrature::RuleProvider& rules)
    : geometry_(geometry), rules_(rules) {}

const AssemblyPlan& Assembler::plan() const {
  if (!plan_) {
    // Swap, not move: Eigen 3.4's SparseMatrix has no move constructor and would be copied.
    AssemblyPlan made = make_assembly_plan(geometry_.space());
    plan_ = std::make_unique<AssemblyPlan>();
    plan_->pattern.swap(made.pattern);
    plan_->colors.swap(made.colors);
  }
  return *plan_;
}

void Assembler::prepare(Index e, ElementContext& ctx) const {
  const basis::Space& space = geometry_.space();
  ctx.element = e;
  ctx.rule = &rules_.rule(space.kind(e));
  ctx.dim = geometry_.dim();
  space.evaluate(e, ctx.rule->points, 1, ctx.basis);
  geometry_.evaluate(e, ctx.basis, ctx.geo);
  ctx.weight = ctx.rule->weights.cwiseProduct(ctx.geo.measure);
  const Eigen::Index q = ctx.rule->size();
  ctx.grad.resize(ctx.basis.value.rows(), ctx.dim * q);
  for (int c = 0; c < ctx.dim; ++c) {
    ctx.grad.middleCols(c * q, q) = ctx.basis.du.array().rowwise() * ctx.geo.tu.row(c).array() +
                                    ctx.basis.dv.array().rowwise() * ctx.geo.tv.row(c).array();
  }
}

AssemblyStats Assembler::assemble(std::span<const BilinearForm* const> bilinear,
                                  std::span<const LinearForm* const> linear, Eigen::SparseMatrix<double>& a,
                                  Eigen::VectorXd& b) const {
  const AssemblyPlan& p = plan();
  const basis::Space& space = geometry_.space();
  a = p.pattern;
  b = Eigen::VectorXd::Zero(space.num_dofs());
  const int* outer = a.outerIndexPtr();
  const int* inner = a.innerIndexPtr();
  double* values = a.valuePtr();
  const Index ne = space.num_elements();
  std::vector<double> measure(static_cast<std::size_t>(ne), 0.0);
  std::vector<Index> points(static_cast<std::size_t>(ne), 0);
  std::vector<ElementContext> contexts(static_cast<std::size_t>(omp_get_max_threads()));
  std::vector<Eigen::MatrixXd> mats(contexts.size());
  std::vector<Eigen::VectorXd> vecs(contexts.size());
  std::vector<std::vector<Index>> orders(contexts.size());
  for (const std::vector<Index>& colour : p.colors) {
    parallel_for(static_cast<Index>(colour.size()), [&](Index i) {
      const std::size_t t = static_cast<std::size_t>(omp_get_thread_num());
      ElementContext& ctx = contexts[t];
      const Index e = colour[static_cast<std::size_t>(i)];
      prepare(e, ctx);
      const auto dofs = space.dofs(e);
      const Index nloc = static_cast<Index>(dofs.size());
      Eigen::MatrixXd& k = mats[t];
      Eigen::VectorXd& f = vecs[t];
      k.setZero(nloc, nloc);
      f.setZero(nloc);
      for (const BilinearForm* form : bilinear) form->add(ctx, k);
      for (const LinearForm* form : linear) form->add(ctx, f);
      measure[static_cast<std::size_t>(e)] = ctx.weight.sum();
      points[static_cast<std::size_t>(e)] = ctx.rule->size();
      // Scatter: no other element of this colour touches these rows or columns. Rows are visited in
      // ascending dof order, so each column is one forward walk through its sorted row indices.
      std::vector<Index>& order = orders[t];
      order.resize(static_cast<std::size_t>(nloc));
      for (Index al = 0; al < nloc; ++al) order[static_cast<std::size_t>(al)] = al;
      if (!std::is_sorted(dofs.begin(), dofs.end())) {
        std::sort(order.begin(), order.end(), [&](Index x, Index y) { return dofs[x] < dofs[y]; });
      }
      const int first_row = static_cast<int>(dofs[order[0]]);
      for (Index bl = 0; bl < nloc; ++bl) {
        const Index j = dofs[bl];
        const int* pos = std::lower_bound(inner + outer[j], inner + outer[j + 1], first_row);
        for (Index al : order) {
          const int row = static_cast<int>(dofs[al]);
          while (*pos < row) ++pos;
          values[pos - inner] += k(al, bl);
        }
        b(j) += f(bl);
      }
    });
  }
  AssemblyStats stats;
  for (Index e = 0; e < ne; ++e) {
    stats.measure += measure[static_cast<std::size_t>(e)];
    stats.quadrature_points += points[static_cast<std::size_t>(e)];
  }
  return stats;
}

void Assembler::assemble_boundary(std::span<const basis::BoundaryEdge> edges, const BoundaryBilinearForm* bilinear,
                                  const BoundaryLinearForm* linear, Eigen::SparseMatrix<double>* a,
                                  Eigen::VectorXd* b) const {
  const basis::Space& space = geometry_.space();
  const Index n = space.num_dofs();
  std::vector<Eigen::Triplet<double>> entries;
  if (b) *b = Eigen::VectorXd::Zero(n);
  BoundaryContext ctx;
  Eigen::Matrix2Xd pts;
  Eigen::MatrixXd k;
  Eigen::VectorXd f;
  for (const basis::BoundaryEdge& edge : edges) {
    const basis::ElementKind kind = space.kind(edge.element);
    const basis::Shape shape = kind.shape;
    const quadrature::Rule1D& line = rules_.side_rule(kind, edge.side);
    const Index q = line.size();
    pts.resize(2, q);
    for (Index i = 0; i < q; ++i) pts.col(i) = basis::side_point(shape, edge.side, line.points(i));
    const Eigen::Vector2d dt = basis::side_tangent(shape, edge.side);
    ctx.element = edge.element;
    ctx.side = edge.side;
    space.evaluate(edge.element, pts, 1, ctx.basis);
    geometry_.evaluate(edge.element, ctx.basis, ctx.geo, false);
    ctx.weight.resize(q);
    ctx.conormal.resize(3, q);
    for (Index i = 0; i < q; ++i) {
      const Eigen::Vector3d tangent = dt(0) * ctx.geo.xu.col(i) + dt(1) * ctx.geo.xv.col(i);
      const double len = tangent.norm();
      ctx.weight(i) = line.weights(i) * len;
      ctx.conormal.col(i) = len > 0 ? Eigen::Vector3d((tangent / len).cross(ctx.geo.normal.col(i)))
                                    : Eigen::Vector3d::Zero();
    }
    const auto dofs = space.dofs(edge.element);
    const Index nloc = static_cast<Index>(dofs.size());
    if (bilinear && a) {
      k.setZero(nloc, nloc);
      bilinear->add(ctx, k);
      for (Index bl = 0; bl < nloc; ++bl) {
        for (Index al = 0; al < nloc; ++al) {
          if (k(al, bl) != 0.0) entries.emplace_back(dofs[al], dofs[bl], k(al, bl));
        }
      }
    }
    if (linear && b) {
      f.setZero(nloc);
      linear->add(ctx, f);
      for (Index al = 0; al < nloc; ++al) (*b)(dofs[al]) += f(al);
    }
  }
  if (a) {
    a->resize(n, n);
    a->setFromTriplets(entries.begin(), entries.end());
  }
}

Eigen::MatrixXd Assembler::integrate_per_element(
    int n, const std::function<void(const ElementContext&, Eigen::Ref<Eigen::VectorXd>)>& f) const {
  const Index ne = geometry_.space().num_elements();
  Eigen::MatrixXd partial = Eigen::MatrixXd::Zero(n, ne);
  std::vector<ElementContext> contexts(static_cast<std::size_t>(omp_get_max_threads()));
  parallel_for(ne, [&](Index e) {
    ElementContext& ctx = contexts[static_cast<std::size_t>(omp_get_thread_num())];
    prepare(e, ctx);
    f(ctx, partial.col(e));
  });
  return partial;
}

Eigen::VectorXd Assembler::integrate(int n,
                                     const std::function<void(const ElementContext&, Eigen::Ref<Eigen::VectorXd>)>& f) const {
  const Eigen::MatrixXd partial = integrate_per_element(n, f);
  Eigen::VectorXd sum = Eigen::VectorXd::Zero(n);
  for (Index e = 0; e < partial.cols(); ++e) sum += partial.col(e);
  return sum;
}

}  // namespace iga::fem
