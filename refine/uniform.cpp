#include "refine/uniform.hpp"

#include <memory>

#include "basis/bspline/knot_insertion.hpp"
#include "basis/bspline/tensor_space.hpp"
#include "basis/catmull_clark/space.hpp"
#include "refine/refine_smooth.hpp"
#include "core/error.hpp"

namespace iga::refine {

Refinement refine_uniform(const basis::Geometry& geometry, int steps) {
  if (steps < 0) throw InputError("refinement steps must be >= 0, got " + std::to_string(steps));
  const auto* tensor = dynamic_cast<const basis::bspline::TensorSpace*>(&geometry.space());
  const Index n = geometry.space().num_dofs();
  Eigen::SparseMatrix<double> identity(n, n);
  identity.setIdentity();
  if (steps == 0) return {geometry, identity};
  if (const auto* cc = dynamic_cast<const basis::catmull_clark::CatmullClarkSpace*>(&geometry.space())) {
    // Catmull–Clark: `steps` subdivisions of the control net (OpenSubdiv topology); every refined net has
    // quads only, each touching at most one extraordinary vertex, so no global step is needed again.
    basis::catmull_clark::NetRefinement net = basis::catmull_clark::refine_net(cc->control_mesh(), steps);
    auto fine = std::make_shared<const basis::catmull_clark::CatmullClarkSpace>(net.mesh, "refined net");
    if (fine->refinement_steps() != 0) throw NumericalError("refined Catmull–Clark net needed another global step");
    Eigen::MatrixXd cp = net.prolongation * geometry.control_points();
    return {basis::Geometry(fine, std::move(cp)), std::move(net.prolongation)};
  }
  if (!tensor) {
    throw UnsupportedError("uniform refinement of a '" + geometry.space().name() + "' space is not implemented");
  }
  // Tensor-product B-splines: each step is the symmetric refine-and-smooth algorithm (Cashman, Dodgson,
  // Sabin) with the midpoint of every non-empty interval in both directions; prolongations compose.
  Refinement out = refine_smooth_tensor(geometry);
  for (int s = 1; s < steps; ++s) {
    Refinement next = refine_smooth_tensor(out.geometry);
    Eigen::SparseMatrix<double> composed = next.prolongation * out.prolongation;
    out.geometry = next.geometry;
    out.prolongation.swap(composed);
  }
  return out;
}

}  // namespace iga::refine
