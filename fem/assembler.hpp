#pragma once
// The one element loop (DESIGN.md, "fem::Assembler"): OpenMP over the elements of one colour at a time,
// thread-local buffers, basis and geometry evaluated once per element, local matrices as dense products,
// one scatter into a precomputed sparsity pattern.
#include <Eigen/Sparse>
#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <span>
#include <tuple>
#include <utility>
#include <vector>

#include "basis/geometry.hpp"
#include "fem/assembly_plan.hpp"
#include "fem/forms.hpp"
#include "fem/system_sink.hpp"
#include "quadrature/rule_provider.hpp"

namespace iga::fem {

struct AssemblyStats {
  Index quadrature_points = 0;  ///< points used over all elements
  double measure = 0.0;         ///< sum of physical weights: the domain's area or surface area
};

class Assembler {
 public:
  /// Keeps references to geometry and rules (they must outlive the assembler). The plan is built lazily.
  /// components = d: the unknown is a field of d components over the geometry's scalar space (DESIGN.md item 2),
  /// its dofs interleaved (d·i + c: component c of function i; make_assembly_plan), and forms must say they are
  /// written for d components (FormNeeds::components()). 1: a scalar field.
  Assembler(const basis::Geometry& geometry, const quadrature::RuleProvider& rules, int components = 1);

  const basis::Geometry& geometry() const { return geometry_; }
  const quadrature::RuleProvider& rules() const { return rules_; }
  int components() const { return components_; }
  /// The field's dofs: components() × the space's.
  Index num_dofs() const { return components_ * geometry_.space().num_dofs(); }
  /// Element e's field dofs in the local order of the forms' matrices: d·dofs(e)[a] + c at d·a + c.
  void field_dofs(Index e, std::vector<Index>& out) const;
  /// with_pattern = false: the colouring alone (the pattern stays 0 × 0 until a call asks for it), for a sink
  /// with its own pattern.
  const AssemblyPlan& plan(bool with_pattern = true) const;

  /// A = sum of the bilinear forms, b = sum of the linear forms, in one loop over the elements, each element
  /// prepared to the largest derivative order the forms ask for (FormNeeds).
  /// A gets the plan's pattern; b has num_dofs entries. Deterministic for any thread count.
  AssemblyStats assemble(std::span<const BilinearForm* const> bilinear, std::span<const LinearForm* const> linear,
                         Eigen::SparseMatrix<double>& a, Eigen::VectorXd& b) const;
  /// The same loop over the elements the sink takes (SystemSink::takes), written through the sink: colour by
  /// colour, the elements of a colour in parallel. Stats cover the elements taken.
  AssemblyStats assemble(std::span<const BilinearForm* const> bilinear, std::span<const LinearForm* const> linear,
                         SystemSink& sink) const;

  /// Boundary integrals over `edges` (serial; boundaries are small), each side prepared to the order the forms
  /// ask for: a (num_dofs()², may be null) and b (num_dofs(), may be null) are overwritten.
  void assemble_boundary(std::span<const basis::BoundaryEdge> edges, const BoundaryBilinearForm* bilinear,
                         const BoundaryLinearForm* linear, Eigen::SparseMatrix<double>* a,
                         Eigen::VectorXd* b) const;

  /// The `n` element quantities computed by f(ctx, out) for every element (out has n entries, zeroed): an
  /// n × num_elements matrix, column e for element e (deal.II's per-cell vectors: error indicators,
  /// estimators). Computed in parallel; each column by one call, so the result does not depend on the threads.
  /// derivatives: what prepare() evaluates (2: second derivatives through the map as well).
  /// only (optional, one entry per element): the elements e with only[e] != 0, the other columns zero (a
  /// distributed run's own elements).
  Eigen::MatrixXd integrate_per_element(int n,
                                        const std::function<void(const ElementContext&, Eigen::Ref<Eigen::VectorXd>)>& f,
                                        int derivatives = 1, const std::vector<char>* only = nullptr) const;
  /// Their sum over elements, reduced in element order (reproducible). For error norms and measures.
  Eigen::VectorXd integrate(int n, const std::function<void(const ElementContext&, Eigen::Ref<Eigen::VectorXd>)>& f,
                            int derivatives = 1, const std::vector<char>* only = nullptr) const;

  /// Fills ctx on the piece [t0, t1] of side `side` of element e (side parameter, side_point conventions) at the
  /// points s of `line` on [0, 1] (side parameter t0 + s (t1 - t0)): basis with first derivatives, geometry
  /// (unchecked), weight = line weight × |dx/ds|, outward conormal. The whole side is t0 = 0, t1 = 1.
  /// derivatives = 2: also ctx.grad, ctx.laplacian and (planar) ctx.hessian, as prepare() gives them.
  void prepare_side(Index e, int side, double t0, double t1, const quadrature::Rule1D& line, BoundaryContext& ctx,
                    int derivatives = 1, bool hessian = true) const;

  /// Fills ctx for element e at its rule's points (basis with first derivatives, geometry, weights,
  /// physical gradients; with derivatives = 2 also ctx.laplacian and, planar, ctx.hessian — update flags in the
  /// manner of deal.II's).
  /// hessian = false (with derivatives 2): the Laplacians only, ctx.hessian left empty.
  void prepare(Index e, ElementContext& ctx, int derivatives = 1, bool hessian = true) const;

 private:
  /// Element e's local functions at its rule's points into ctx.basis: evaluated, or derived from the reference
  /// values of its twin class (basis::Space::reference_element, from_reference), computed once per class, rule and
  /// derivative order.
  void evaluate_basis(Index e, ElementContext& ctx) const;

  /// The largest derivative order the forms ask for and whether one reads Hessians; InputError for a form of other
  /// components than the field's.
  std::pair<int, bool> needs(std::span<const FormNeeds* const> forms) const;

  const basis::Geometry& geometry_;
  const quadrature::RuleProvider& rules_;
  int components_ = 1;
  mutable std::unique_ptr<AssemblyPlan> plan_;
  /// Reference values of twin classes: (lowest element, rule, derivatives) → values. Entries are never removed or
  /// changed once made, so a pointer read under the lock stays valid after it.
  mutable std::mutex twins_mutex_;
  mutable std::map<std::tuple<Index, const quadrature::Rule*, int>, std::unique_ptr<const basis::BasisValues>> twins_;
};

}  // namespace iga::fem
