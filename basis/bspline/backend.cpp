// Registration of the tensor-product B-spline backend (basis/registry.hpp).
#include <memory>
#include <numbers>

#include "basis/bspline/extraction.hpp"
#include "basis/bspline/knot_insertion.hpp"
#include "basis/bspline/patch_file.hpp"
#include "basis/bspline/patches.hpp"
#include "basis/bspline/rational_space.hpp"
#include "basis/bspline/tensor_space.hpp"
#include "basis/hierarchical/geometry_refinement.hpp"
#include "basis/thb/dyadic_levels.hpp"
#include "basis/registry.hpp"
#include "core/error.hpp"

namespace iga::basis {
namespace {

using bspline::TensorSpace;

using hierarchical::HierarchicalSpace;

// The THB space of a geometry: its own, or (a tensor-product patch) the patch as level 0 with the permutation
// from the patch's dofs to the THB dofs.
std::shared_ptr<const HierarchicalSpace> thb_of(const Geometry& g, Eigen::SparseMatrix<double>* to_thb) {
  if (auto h = std::dynamic_pointer_cast<const HierarchicalSpace>(g.space_ptr())) return h;
  const TensorSpace* t = bspline::tensor_space(g.space());
  if (!t) throw InputError("a '" + g.space().name() + "' space is not a B-spline space");
  auto h = thb::coarse_thb_space(t->knots_u(), t->knots_v());
  *to_thb = hierarchical::level0_permutation(*h, t->num_dofs());
  return h;
}

// THB refinement of the marked elements (a patch becomes level 0 first); the control points are prolongated.
Refinement refine_thb(const Geometry& geometry, std::span<const Index> marked, int admissibility, BackendFacts& facts,
                      bool with_prolongation) {
  // An InputError, not UnsupportedError: the adaptive loop reads the latter as "the deepest level is reached".
  if (bspline::rational_space(geometry.space())) {
    throw InputError("local (THB) refinement of a NURBS patch is not implemented (uniform refinement is)");
  }
  Eigen::SparseMatrix<double> to_thb;
  const auto coarse = thb_of(geometry, &to_thb);
  return hierarchical::refine_marked_geometry(geometry, coarse, to_thb, marked, admissibility, facts, with_prolongation);
}

const TensorSpace& tensor_of(const Geometry& g) {
  const TensorSpace* t = bspline::tensor_space(g.space());
  if (!t) throw InputError("a '" + g.space().name() + "' space is not a tensor-product B-spline space");
  return *t;
}

// Each step inserts the midpoint of every non-empty knot interval in both directions (Oslo, thesis §2.3.1);
// the refinement matrices of the steps compose.
// NURBS patches refine their B-spline space and carry the weights along (rational_space.hpp).
Refinement refine_midpoints(const Geometry& geometry, int steps, BackendFacts& facts) {
  const bspline::RationalSpace* rational = bspline::rational_space(geometry.space());
  if (!rational && !bspline::tensor_space(geometry.space())) {
    return hierarchical::refine_all_geometry(geometry, steps, facts);  // THB
  }
  std::shared_ptr<const TensorSpace> coarse = rational ? rational->base_ptr()
                                                       : std::shared_ptr<const TensorSpace>(geometry.space_ptr(), &tensor_of(geometry));
  Eigen::SparseMatrix<double> total;
  for (int s = 0; s < steps; ++s) {
    const std::string step = "refinement " + std::to_string(s + 1) + ": the ";
    auto fine = std::make_shared<const TensorSpace>(bspline::insert_midpoints(coarse->knots_u(), step + "u knot interval"),
                                                    bspline::insert_midpoints(coarse->knots_v(), step + "v knot interval"));
    Eigen::SparseMatrix<double> r = bspline::refinement_matrix(*coarse, *fine);
    if (s == 0) {
      total.swap(r);
    } else {
      Eigen::SparseMatrix<double> composed = r * total;
      total.swap(composed);
    }
    coarse = fine;
  }
  if (rational) {
    Eigen::SparseMatrix<double> prolongation;
    Geometry fine = bspline::refine_rational(geometry, coarse, total, &prolongation);
    return {std::move(fine), std::move(prolongation), true};
  }
  Eigen::MatrixXd cp = total * geometry.control_points();
  return {Geometry(coarse, std::move(cp)), std::move(total), true};
}

// --coarse-split U,V: every knot interval of the patch split into U equal parts along u and V along v by knot
// insertion, before any refinement: the same map on the run's coarsest space (the multigrid's coarsest level too).
Geometry split_patch(Geometry geometry, const BackendOptions& o) {
  if (o.split_u == 1 && o.split_v == 1) return geometry;
  const bspline::RationalSpace* rational = bspline::rational_space(geometry.space());
  const TensorSpace& coarse = rational ? rational->base() : tensor_of(geometry);
  auto fine = std::make_shared<const TensorSpace>(
      bspline::split_intervals(coarse.knots_u(), o.split_u, "--coarse-split: the u knot interval"),
      bspline::split_intervals(coarse.knots_v(), o.split_v, "--coarse-split: the v knot interval"));
  const Eigen::SparseMatrix<double> r = bspline::refinement_matrix(coarse, *fine);
  if (rational) {
    Eigen::SparseMatrix<double> prolongation;
    return bspline::refine_rational(geometry, std::move(fine), r, &prolongation);
  }
  Eigen::MatrixXd cp = r * geometry.control_points();
  return Geometry(std::move(fine), std::move(cp));
}

// Every element by Bézier extraction: BB coefficient (a, b) = Σ_ij C_u(i, a) C_v(j, b) P_dof(i, j).
std::vector<BezierPatch> extracted_patches(const Geometry& geometry, const BackendOptions&, BackendFacts&) {
  if (bspline::rational_space(geometry.space())) {
    throw UnsupportedError("Bezier export of a NURBS patch is not implemented (the .bv format has no weights)");
  }
  if (!bspline::tensor_space(geometry.space())) {
    throw UnsupportedError("Bezier export of a THB (hierarchical B-spline) space is not implemented");
  }
  const TensorSpace& space = tensor_of(geometry);
  Eigen::MatrixXd cp = Eigen::MatrixXd::Zero(geometry.control_points().rows(), 3);
  cp.leftCols(geometry.dim()) = geometry.control_points();
  const auto cu = bspline::extraction_operators(space.knots_u());
  const auto cv = bspline::extraction_operators(space.knots_v());
  const int p = space.knots_u().degree(), q = space.knots_v().degree();
  std::vector<BezierPatch> patches;
  for (Index ey = 0; ey < space.num_elements_v(); ++ey) {
    for (Index ex = 0; ex < space.num_elements_u(); ++ex) {
      const Index span_u = space.knots_u().interval_spans()[static_cast<std::size_t>(ex)];
      const Index span_v = space.knots_v().interval_spans()[static_cast<std::size_t>(ey)];
      const Eigen::MatrixXd& Cu = cu[static_cast<std::size_t>(ex)];
      const Eigen::MatrixXd& Cv = cv[static_cast<std::size_t>(ey)];
      BezierPatch patch{"Group 0 BSpline", false, p, q, Eigen::MatrixXd::Zero((p + 1) * (q + 1), 3)};
      for (int b = 0; b <= q; ++b) {
        for (int a = 0; a <= p; ++a) {
          for (int j = 0; j <= q; ++j) {
            for (int i = 0; i <= p; ++i) {
              const Index dof = (span_u - p + i) + space.num_basis_u() * (span_v - q + j);
              patch.points.row(b * (p + 1) + a) += Cu(i, a) * Cv(j, b) * cp.row(dof);
            }
          }
        }
      }
      patches.push_back(std::move(patch));
    }
  }
  return patches;
}

// --degree, or a patch file's larger degree (a --degree that differs from it is refused: patch files are not
// degree-elevated).
int patch_degree(const BackendOptions& o) {
  if (!bspline::is_patch_file(o.geometry)) return o.degree == BackendOptions::kUnset ? 3 : o.degree;
  const Geometry g = bspline::read_patch(o.geometry);
  const bspline::RationalSpace* r = bspline::rational_space(g.space());
  const TensorSpace& t = r ? r->base() : tensor_of(g);
  const int p = std::max(t.knots_u().degree(), t.knots_v().degree());
  if (o.degree != BackendOptions::kUnset && o.degree != p) {
    throw InputError("--degree " + std::to_string(o.degree) + ": the patch file " + o.geometry + " has degree (" +
                     std::to_string(t.knots_u().degree()) + ", " + std::to_string(t.knots_v().degree()) +
                     "), and patch files are not degree-elevated; leave --degree out");
  }
  return p;
}

// The built-in geometry or patch file of --geometry.
Geometry built_in_geometry(const BackendOptions& o) {
  if (bspline::is_patch_file(o.geometry)) {
    patch_degree(o);  // refuses a --degree that is not the file's
    return bspline::read_patch(o.geometry);
  }
  const int p = o.degree == BackendOptions::kUnset ? 3 : o.degree;
  if (o.geometry.empty() || o.geometry == "quarter-annulus") return bspline::make_quarter_annulus(p);
  if (o.geometry == "l-shape") return bspline::make_l_shape(p);
  if (o.geometry == "square") return bspline::make_rectangle(p);
  if (o.geometry == "plate-with-hole") return bspline::make_plate_with_hole(p);
  // The shell obstacle course's surfaces (pde/shell/problems.hpp gives their loads and supports).
  const double deg = std::numbers::pi / 180;
  if (o.geometry == "scordelis-lo-roof") return bspline::make_cylinder_patch(p, 25.0, 50.0, -40 * deg, 40 * deg);
  if (o.geometry == "pinched-cylinder") return bspline::make_cylinder_patch(p, 300.0, 300.0, 0.0, 90 * deg);
  if (o.geometry == "pinched-hemisphere") return bspline::make_sphere_patch(p, 10.0, 0.0, 90 * deg, 0.0, 72 * deg);
  throw InputError("--geometry: unknown built-in geometry '" + o.geometry +
                   "' (quarter-annulus, l-shape, square, plate-with-hole, scordelis-lo-roof, pinched-cylinder, "
                   "pinched-hemisphere, or a patch file FILE.json)");
}

}  // namespace

Backend bspline_backend() {
  Backend b;
  b.name = "bspline";
  b.description = "tensor-product B-splines and NURBS on one patch (a structured quad-grid net, the exact quarter annulus, or a patch file)";
  b.options = {"degree", "refine-intervals", "geometry", "coarse-split"};
  b.default_degree = 3;
  b.default_refine = 4;
  b.from_net = [](const mesh::PolyMesh& net, const BackendOptions& o, BackendFacts&) {
    return split_patch(bspline::geometry_from_quad_grid(net, o.degree == BackendOptions::kUnset ? 3 : o.degree, o.net_name), o);
  };
  b.degree_of = patch_degree;
  b.default_geometry = [](const BackendOptions& o) { return split_patch(built_in_geometry(o), o); };
  b.refine = refine_midpoints;
  b.refine_marked = refine_thb;
  b.default_quadrature = [](int degree) { return "gauss:" + std::to_string(degree + 1); };
  b.bezier_patches = extracted_patches;
  return b;
}

}  // namespace iga::basis
