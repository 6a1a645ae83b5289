#include "fem/assembler.hpp"

#include <omp.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <atomic>
#include <exception>
#include <mutex>
#include <sstream>
#include <iomanip>

#include "core/error.hpp"
#include "fem/data_check.hpp"
#include "fem/parallel_for.hpp"

namespace iga::fem {

namespace {
// Physical gradients (nloc × dim·q, blocks per component) from the parametric ones and the gradient transform.
void physical_gradients(const basis::BasisValues& b, const basis::GeometryValues& g, int dim, Eigen::MatrixXd& grad) {
  const Eigen::Index q = b.value.cols();
  grad.resize(b.value.rows(), dim * q);
  thread_local Eigen::RowVectorXd tu, tv;  // row c of T, contiguous (a row of the 3 × q blocks is strided)
  for (int c = 0; c < dim; ++c) {
    tu = g.tu.row(c);
    tv = g.tv.row(c);
    grad.middleCols(c * q, q) = b.du.array().rowwise() * tu.array() + b.dv.array().rowwise() * tv.array();
  }
}

// The Laplacians (and, planar, the Hessians) from the parametric first and second derivatives of the functions
// and the map, for all points at once; grad as physical_gradients gives it.
void second_derivatives(const basis::BasisValues& b, const basis::GeometryValues& g, int dim,
                        const Eigen::MatrixXd& grad, Eigen::MatrixXd& laplacian, Eigen::MatrixXd& hessian,
                        bool with_hessian) {
  const Eigen::Index q = b.value.cols();
  thread_local Eigen::ArrayXXd m;  // rows: g11, g12, g22, inverse metric, Christoffel contractions
  m.resize(8, q);
  m.row(0) = g.xu.colwise().squaredNorm().array();
  m.row(1) = (g.xu.array() * g.xv.array()).colwise().sum();
  m.row(2) = g.xv.colwise().squaredNorm().array();
  const Eigen::ArrayXXd det = m.row(0) * m.row(2) - m.row(1).square();
  m.row(3) = m.row(2) / det;   // g^11
  m.row(4) = -m.row(1) / det;  // g^12
  m.row(5) = m.row(0) / det;   // g^22
  // c_l = g^{ij} x_{,l} · x_{,ij} (l = u, v); the first-derivative coefficients are g^{kl} c_l.
  auto dot = [](const Eigen::Matrix3Xd& a, const Eigen::Matrix3Xd& b) { return (a.array() * b.array()).colwise().sum(); };
  const Eigen::ArrayXXd cu = m.row(3) * dot(g.xu, g.xuu) + 2 * m.row(4) * dot(g.xu, g.xuv) + m.row(5) * dot(g.xu, g.xvv);
  const Eigen::ArrayXXd cv = m.row(3) * dot(g.xv, g.xuu) + 2 * m.row(4) * dot(g.xv, g.xuv) + m.row(5) * dot(g.xv, g.xvv);
  m.row(6) = m.row(3) * cu + m.row(4) * cv;  // coefficient of φ_u
  m.row(7) = m.row(4) * cu + m.row(5) * cv;  // coefficient of φ_v
  laplacian = (b.duu.array().rowwise() * m.row(3) + b.duv.array().rowwise() * (2 * m.row(4)) +
                   b.dvv.array().rowwise() * m.row(5) - b.du.array().rowwise() * m.row(6) -
                   b.dv.array().rowwise() * m.row(7)).matrix();
  if (dim != 2 || !with_hessian) {
    hessian.resize(0, 0);
    return;
  }
  // M_ij = φ_{,ij} − ∇_x φ · x_{,ij}; H_ab = Σ_ij K_ia M_ij K_jb with K = J^{-1}: K_ua = tu(a), K_va = tv(a).
  const Eigen::Index n = b.value.rows();
  thread_local Eigen::ArrayXXd muu, muv, mvv;
  const auto gx = grad.middleCols(0, q).array();
  const auto gy = grad.middleCols(q, q).array();
  muu = b.duu.array() - gx.rowwise() * g.xuu.row(0).array() - gy.rowwise() * g.xuu.row(1).array();
  muv = b.duv.array() - gx.rowwise() * g.xuv.row(0).array() - gy.rowwise() * g.xuv.row(1).array();
  mvv = b.dvv.array() - gx.rowwise() * g.xvv.row(0).array() - gy.rowwise() * g.xvv.row(1).array();
  hessian.resize(n, 3 * q);
  const int ab[3][2] = {{0, 0}, {0, 1}, {1, 1}};
  for (int k = 0; k < 3; ++k) {
    const auto ua = g.tu.row(ab[k][0]).array(), va = g.tv.row(ab[k][0]).array();
    const auto ub = g.tu.row(ab[k][1]).array(), vb = g.tv.row(ab[k][1]).array();
    hessian.middleCols(k * q, q) = (muu.rowwise() * (ua * ub) + muv.rowwise() * (ua * vb + va * ub) +
                                        mvv.rowwise() * (va * vb)).matrix();
  }
}
}  // namespace

Assembler::Assembler(const basis::Geometry& geometry, const quadrature::RuleProvider& rules, int components)
    : geometry_(geometry), rules_(rules), components_(components) {
  if (components < 1) throw InputError("assembler: components must be >= 1, got " + std::to_string(components));
}

void Assembler::field_dofs(Index e, std::vector<Index>& out) const {
  const auto dofs = geometry_.space().dofs(e);
  const Index d = components_;
  out.resize(dofs.size() * static_cast<std::size_t>(d));
  for (std::size_t a = 0; a < dofs.size(); ++a) {
    for (Index c = 0; c < d; ++c) out[a * static_cast<std::size_t>(d) + static_cast<std::size_t>(c)] = d * dofs[a] + c;
  }
}

std::pair<int, bool> Assembler::needs(std::span<const FormNeeds* const> forms) const {
  int needed = 1;
  bool hessian = false;
  for (const FormNeeds* form : forms) {
    if (form->components() != components_) {
      throw InputError("assembler: a form for " + std::to_string(form->components()) +
                       " component(s) given to the loop of a field with " + std::to_string(components_));
    }
    needed = std::max(needed, form->derivatives());
    hessian = hessian || (form->derivatives() >= 2 && form->hessian());
  }
  return {needed, hessian};
}

const AssemblyPlan& Assembler::plan(bool with_pattern) const {
  const bool pattern_missing = plan_ && with_pattern && plan_->pattern.rows() != num_dofs();
  if (!plan_ || pattern_missing) {
    // Swap, not move: Eigen 3.4's SparseMatrix has no move constructor and would be copied.
    AssemblyPlan made = make_assembly_plan(geometry_.space(), with_pattern, components_);
    if (!plan_) plan_ = std::make_unique<AssemblyPlan>();
    plan_->pattern.swap(made.pattern);
    plan_->colors.swap(made.colors);
    plan_->dense.swap(made.dense);
  }
  return *plan_;
}

void Assembler::prepare(Index e, ElementContext& ctx, int derivatives, bool hessian) const {
  if (derivatives != 1 && derivatives != 2) {
    throw InputError("element context: derivatives must be 1 or 2, got " + std::to_string(derivatives));
  }
  const basis::Space& space = geometry_.space();
  ctx.element = e;
  ctx.rule = &rules_.rule(space.kind(e));
  ctx.dim = geometry_.dim();
  ctx.derivatives = derivatives;
  evaluate_basis(e, ctx);
  geometry_.evaluate(e, ctx.basis, ctx.geo, true, derivatives);
  ctx.weight = ctx.rule->weights.cwiseProduct(ctx.geo.measure);
  physical_gradients(ctx.basis, ctx.geo, ctx.dim, ctx.grad);
  if (derivatives >= 2) {
    second_derivatives(ctx.basis, ctx.geo, ctx.dim, ctx.grad, ctx.laplacian, ctx.hessian, hessian);
  } else {
    ctx.laplacian.resize(0, 0);  // nothing stale from an earlier call with 2
    ctx.hessian.resize(0, 0);
  }
}

void Assembler::evaluate_basis(Index e, ElementContext& ctx) const {
  const basis::Space& space = geometry_.space();
  const Index twin = space.reference_element(e);
  if (twin == e) {  // the class's lowest element (or a class of one): evaluated, from the values the cache holds
    space.evaluate(e, ctx.rule->points, ctx.derivatives, ctx.basis);
    return;
  }
  const auto key = std::make_tuple(twin, ctx.rule, ctx.derivatives);
  const basis::BasisValues* values = nullptr;
  {
    std::lock_guard<std::mutex> lock(twins_mutex_);
    auto it = twins_.find(key);
    if (it == twins_.end()) {
      auto made = std::make_unique<basis::BasisValues>();
      space.evaluate_reference(twin, ctx.rule->points, ctx.derivatives, *made);
      it = twins_.emplace(key, std::move(made)).first;
    }
    values = it->second.get();
  }
  space.from_reference(e, *values, ctx.derivatives, ctx.basis);
}

AssemblyStats Assembler::assemble(std::span<const BilinearForm* const> bilinear,
                                  std::span<const LinearForm* const> linear, Eigen::SparseMatrix<double>& a,
                                  Eigen::VectorXd& b) const {
  CscSink sink(plan(), a, b);
  return assemble(bilinear, linear, sink);
}

AssemblyStats Assembler::assemble(std::span<const BilinearForm* const> bilinear,
                                  std::span<const LinearForm* const> linear, SystemSink& sink) const {
  const AssemblyPlan& p = plan(false);
  const basis::Space& space = geometry_.space();
  const Index ne = space.num_elements();
  std::vector<double> measure(static_cast<std::size_t>(ne), 0.0);
  std::vector<Index> points(static_cast<std::size_t>(ne), 0);
  std::vector<ElementContext> contexts(static_cast<std::size_t>(omp_get_max_threads()));
  std::vector<Eigen::MatrixXd> mats(contexts.size());
  std::vector<Eigen::VectorXd> vecs(contexts.size());
  std::vector<Index> taken;
  std::vector<const FormNeeds*> forms(bilinear.begin(), bilinear.end());
  forms.insert(forms.end(), linear.begin(), linear.end());
  const auto [needed, hessian] = needs(forms);  // the update flags: the largest order any form asks for
  for (const std::vector<Index>& colour : p.colors) {
    taken.clear();
    for (Index e : colour) {
      if (sink.takes(e)) taken.push_back(e);
    }
    parallel_for(static_cast<Index>(taken.size()), [&](Index i) {
      const std::size_t t = static_cast<std::size_t>(omp_get_thread_num());
      ElementContext& ctx = contexts[t];
      const Index e = taken[static_cast<std::size_t>(i)];
      prepare(e, ctx, needed, hessian);
      thread_local std::vector<Index> expanded;
      std::span<const Index> dofs = space.dofs(e);
      if (components_ > 1) {
        field_dofs(e, expanded);
        dofs = expanded;
      }
      const Index nloc = static_cast<Index>(dofs.size());
      Eigen::MatrixXd& k = mats[t];
      Eigen::VectorXd& f = vecs[t];
      k.setZero(nloc, nloc);
      f.setZero(nloc);
      for (const BilinearForm* form : bilinear) form->add(ctx, k);
      for (const LinearForm* form : linear) form->add(ctx, f);
      measure[static_cast<std::size_t>(e)] = ctx.weight.sum();
      points[static_cast<std::size_t>(e)] = ctx.rule->size();
      sink.add(i, dofs, k, f);
    });
    sink.end_colour(static_cast<Index>(taken.size()));
  }
  // After the loop, so that a value the quadrature points themselves find not finite is named as before.
  for (const FormNeeds* form : forms) {
    for (const Function* f : form->data()) check_domain_data(geometry_, *f);
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
  const Index n = num_dofs();
  std::vector<Eigen::Triplet<double>> entries;
  if (b) *b = Eigen::VectorXd::Zero(n);
  BoundaryContext ctx;
  Eigen::MatrixXd k;
  Eigen::VectorXd f;
  std::vector<const FormNeeds*> forms;
  if (bilinear && a) forms.push_back(bilinear);
  if (linear && b) forms.push_back(linear);
  const auto [needed, hessian] = needs(forms);
  std::vector<Index> dofs;
  for (const basis::BoundaryEdge& edge : edges) {
    prepare_side(edge.element, edge.side, 0.0, 1.0, rules_.side_rule(space.kind(edge.element), edge.side), ctx,
                 needed, hessian);
    field_dofs(edge.element, dofs);
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

void Assembler::prepare_side(Index e, int side, double t0, double t1, const quadrature::Rule1D& line,
                             BoundaryContext& ctx, int derivatives, bool hessian) const {
  if (derivatives != 1 && derivatives != 2) {
    throw InputError("side context: derivatives must be 1 or 2, got " + std::to_string(derivatives));
  }
  const basis::Space& space = geometry_.space();
  const basis::Shape shape = space.kind(e).shape;
  const Index q = line.size();
  thread_local Eigen::Matrix2Xd pts;
  pts.resize(2, q);
  for (Index i = 0; i < q; ++i) pts.col(i) = basis::side_point(shape, side, t0 + line.points(i) * (t1 - t0));
  const Eigen::Vector2d dt = basis::side_tangent(shape, side) * (t1 - t0);
  ctx.element = e;
  ctx.side = side;
  ctx.dim = geometry_.dim();
  ctx.derivatives = derivatives;
  space.evaluate(e, pts, derivatives, ctx.basis);
  geometry_.evaluate(e, ctx.basis, ctx.geo, false, derivatives);
  if (derivatives >= 2) {
    physical_gradients(ctx.basis, ctx.geo, ctx.dim, ctx.grad);
    second_derivatives(ctx.basis, ctx.geo, ctx.dim, ctx.grad, ctx.laplacian, ctx.hessian, hessian);
  }
  ctx.weight.resize(q);
  ctx.conormal.resize(3, q);
  for (Index i = 0; i < q; ++i) {
    const Eigen::Vector3d tangent = dt(0) * ctx.geo.xu.col(i) + dt(1) * ctx.geo.xv.col(i);
    const double len = tangent.stableNorm();
    if (!(len <= 1e154)) {  // as Geometry::evaluate refuses inside: products of two such lengths overflow a double
      std::ostringstream msg;
      msg << std::setprecision(3) << "element " << e << ": integrals over its boundary side overflow a double (the "
          << "geometry map's derivatives there are " << len << "); rescale the net: coordinates up to about 1e150 work";
      throw NumericalError(msg.str());
    }
    ctx.weight(i) = line.weights(i) * len;
    // The side's own direction (counter-clockwise on the element) gives the outward conormal, whatever the
    // sign of t1 - t0.
    const Eigen::Vector3d unit = (t1 >= t0 ? 1.0 : -1.0) * tangent / len;
    ctx.conormal.col(i) = len > 0 ? Eigen::Vector3d(unit.cross(ctx.geo.normal.col(i))) : Eigen::Vector3d::Zero();
  }
}

Eigen::MatrixXd Assembler::integrate_per_element(
    int n, const std::function<void(const ElementContext&, Eigen::Ref<Eigen::VectorXd>)>& f, int derivatives,
    const std::vector<char>* only) const {
  const Index ne = geometry_.space().num_elements();
  Eigen::MatrixXd partial = Eigen::MatrixXd::Zero(n, ne);
  std::vector<ElementContext> contexts(static_cast<std::size_t>(omp_get_max_threads()));
  parallel_for(ne, [&](Index e) {
    if (only && !(*only)[static_cast<std::size_t>(e)]) return;
    ElementContext& ctx = contexts[static_cast<std::size_t>(omp_get_thread_num())];
    prepare(e, ctx, derivatives);
    f(ctx, partial.col(e));
  });
  return partial;
}

Eigen::VectorXd Assembler::integrate(int n,
                                     const std::function<void(const ElementContext&, Eigen::Ref<Eigen::VectorXd>)>& f,
                                     int derivatives, const std::vector<char>* only) const {
  const Eigen::MatrixXd partial = integrate_per_element(n, f, derivatives, only);
  Eigen::VectorXd sum = Eigen::VectorXd::Zero(n);
  for (Index e = 0; e < partial.cols(); ++e) sum += partial.col(e);
  return sum;
}

}  // namespace iga::fem
