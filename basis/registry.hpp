#pragma once
// The backend registry (DESIGN.md, "Where the joints must widen next", item 1): the one place that maps a
// backend name to what programs and refine:: need of it — net → space and geometry, uniform refinement with
// its prolongation (or "not nested"), defaults (degree, refinement steps, quadrature), the options it takes,
// and its Bézier patches for export. Programs and refine/ ask the registry; nothing outside basis/ tests a
// backend's name or type. Adding a backend touches its folder and one line in registry.cpp.
#include <Eigen/Core>
#include <Eigen/Sparse>
#include <functional>
#include <map>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "basis/fit_surface.hpp"
#include "basis/geometry.hpp"
#include "mesh/poly_mesh.hpp"

namespace iga::basis {

/// Settings a program passes to a backend. A setting the backend does not take must be left unset;
/// check_options() names the ones given in error.
struct BackendOptions {
  static constexpr int kUnset = -1;
  int degree = kUnset;        ///< polynomial degree per direction ("degree": bspline)
  int presubdivide = kUnset;  ///< Catmull–Clark steps of the net before building ("presubdivide": polyhedral)
  bool degree_raise = false;  ///< Bézier export: raise every patch to the element degree ("degree-raise")
  std::string geometry;       ///< a built-in geometry or a patch file instead of a net ("geometry": bspline)
  std::string net_name = "mesh";  ///< the net's file name, for messages
  std::string cc_boundary;        ///< "cc-boundary": cc, natural (default when empty) or clamped
  std::string cc_enrich;          ///< "cc-enrich": cc, none (default when empty) or quadratic (at the EVs)
  std::vector<Index> cc_corners;  ///< "cc-corners": cc (clamped), 0-based net vertices the limit domain keeps as corners
  /// "coarse-split" (bspline): every knot interval of the patch split into split_u × split_v equal parts before any
  /// refinement (knot insertion: the same map, a coarse mesh of chosen aspect ratio)
  int split_u = 1, split_v = 1;
  /// "fit-to" (any backend): the built geometry's control points fitted so that its surface lies on this surface
  /// (basis::fit_to_surface), before any refinement; the largest distance left is a note of BackendFacts.
  std::optional<ExactSurface> fit_to;
};

/// Facts about a build or refinement that a program reports: counts for the JSON report under '/'-separated
/// paths ("cc_global_steps", "patches_per_configuration/star5"), notes for stderr. Refinement adds to (or
/// replaces) what the build wrote.
struct BackendFacts {
  std::map<std::string, long long> counts;
  std::vector<std::string> notes;  ///< e.g. "applied 1 global Catmull–Clark step(s) first"
  /// With BackendOptions::fit_to: the largest distance of the fitted surface's samples from the exact shape
  /// (SurfaceFit::distance), how far points given on the shape may lie from the geometry; negative: not fitted.
  double fit_distance = -1.0;
};

/// A refined geometry: the same map on a finer space. Nested spaces carry the prolongation (fine coefficients
/// = prolongation × coarse coefficients); spaces that are not nested (polyhedral: a refined net gives a new
/// space that does not contain the old one) have nested = false and an empty prolongation.
struct Refinement {
  Geometry geometry;
  Eigen::SparseMatrix<double> prolongation;
  bool nested = true;
  /// When asked for (keep_steps): the prolongation of each uniform step, coarsest first (steps[k] maps the dofs
  /// after k steps to those after k + 1; their product is `prolongation`): the levels of a multigrid solver.
  std::vector<Eigen::SparseMatrix<double>> steps{};
};

/// One Bézier patch of a geometry for export (BezierView .bv): a tensor-product patch of degrees
/// (degree_u, degree_v) with (degree_u + 1)(degree_v + 1) points in u-fastest order, or a triangular patch
/// (triangle = true) of degree degree_u with its (d+1)(d+2)/2 points b_ijk (barycentric λ0 = 1 − u − v,
/// λ1 = u, λ2 = v) ordered by i, then j, descending: (d00), (d−1,1,0), (d−1,0,1), …, (00d) (for d = 3 the order
/// of basis/half_box/regular_patch.hpp); writers map it to their file's order (io/bv.hpp: iga-geometry).
struct BezierPatch {
  std::string group;
  bool triangle = false;
  int degree_u = 0, degree_v = 0;
  Eigen::MatrixXd points;  ///< rows × 3
};

struct Backend {
  std::string name;         ///< as on the command line (--basis NAME); equals Space::name() of its spaces
  std::string description;  ///< one line for --help
  /// Options it takes beyond the common ones, by their program names: "degree", "presubdivide",
  /// "degree-raise", "refine-intervals".
  std::vector<std::string> options;
  int default_degree = 3;  ///< degree per direction of the functions (the default of --degree when taken)
  /// The degree per direction these options give when it is not just --degree or default_degree (bspline: a patch
  /// file's own degree); empty otherwise. InputError when the options contradict each other.
  std::function<int(const BackendOptions&)> degree_of;
  int default_refine = 0;  ///< refinement steps programs apply by default
  bool nested = true;      ///< refinement gives nested spaces with a prolongation
  /// net → geometry; throws InputError naming the file (options.net_name) on a net it cannot take.
  std::function<Geometry(const mesh::PolyMesh&, const BackendOptions&, BackendFacts&)> from_net;
  /// The geometry without a net (bspline: the quarter annulus); empty when a net is required.
  std::function<Geometry(const BackendOptions&)> default_geometry;
  /// `steps` uniform refinements (steps >= 1); the map is unchanged.
  std::function<Refinement(const Geometry&, int steps, BackendFacts&)> refine;
  /// Not nested backends: `steps` refinements of the net itself, applied before building (so a net that only
  /// its refinement makes admissible can be used); empty for nested backends.
  std::function<mesh::PolyMesh(const mesh::PolyMesh&, int steps, const BackendOptions&, BackendFacts&)> refine_net;
  /// Local refinement: the marked elements of the geometry's space are split (plus what keeps the mesh admissible
  /// of class `admissibility`, 0 = none), nested, with the prolongation; the map is unchanged. Empty when the
  /// backend has no local refinement. Writes facts "marked", "added" (cells refined for admissibility), "levels".
  /// With with_prolongation = false the prolongation is left empty (the control points are still prolongated):
  /// for loops that only need the refined geometry.
  std::function<Refinement(const Geometry&, std::span<const Index> marked, int admissibility, BackendFacts&,
                           bool with_prolongation)>
      refine_marked;
  /// A priori grading toward the irregular elements (Family::Irregular; --grade-evs): `levels` local refinements,
  /// step k splitting the elements within rings(k) rings of the irregular ones (ring 1: sharing a function with
  /// one; ring j + 1: with one of ring j), admissibility class `admissibility`, planned on the cells and built
  /// once; the map is unchanged. With keep_steps each step's prolongation in Refinement::steps (their product is
  /// `prolongation`), without it the prolongation is left empty. Facts "graded_levels" (steps taken), "marked",
  /// "added", "levels". Empty when the backend has no local refinement.
  std::function<Refinement(const Geometry&, int levels, const std::function<int(int step)>& rings, int admissibility,
                           BackendFacts&, bool keep_steps)>
      refine_graded;
  /// The default quadrature specification for a degree (quadrature::make_rule_provider).
  std::function<std::string(int degree)> default_quadrature;
  /// Whether a program that can impose Dirichlet data weakly (iga-poisson's Nitsche method) should, unless told
  /// otherwise, with these options; empty: never. (cc with the clamped rule: its strong conditions next to boundary
  /// extraordinary vertices are refused, and it is the fastest configuration.)
  std::function<bool(const BackendOptions&)> prefers_weak_dirichlet;
  /// The local refinements toward the irregular elements (Family::Irregular; --grade-evs) programs apply after
  /// `refine` uniform steps when none are asked for and the mesh has such elements; empty: none. Only with
  /// refine_graded.
  std::function<int(const BackendOptions&, int refine)> default_grading;
  /// Bézier patches of the geometry (elements that are not polynomial are counted in facts "bv_skipped").
  std::function<std::vector<BezierPatch>(const Geometry&, const BackendOptions&, BackendFacts&)> bezier_patches;
};

/// Every backend of this build, in a fixed order.
const std::vector<Backend>& backends();
/// Their names, comma-separated, for messages.
std::string backend_names();
/// The backend of a name; UnsupportedError listing the available ones otherwise.
const Backend& backend(const std::string& name);
/// The backend a space belongs to (by Space::name()).
const Backend& backend_of(const Space& space);

/// InputError for the first option in `given` (program names without dashes) that the backend does not take:
/// "--degree is not an option of --basis cc (its options: none)".
void check_options(const Backend& backend, const std::vector<std::string>& given);
/// The degree per direction the backend uses with these options.
int degree(const Backend& backend, const BackendOptions& options);
/// The geometry from a net, or the backend's default geometry when net is null (InputError naming the backend
/// when it needs a net).
Geometry make_geometry(const Backend& backend, const mesh::PolyMesh* net, const BackendOptions& options,
                       BackendFacts& facts);
/// The geometry from a net (or the default geometry) refined `steps` >= 0 times: nested backends build and
/// refine (with the prolongation), the others refine the net first and build once. keep_steps: nested backends
/// also return each step's prolongation (Refinement::steps; refined one step at a time, the same spaces).
Refinement make_refined_geometry(const Backend& backend, const mesh::PolyMesh* net, const BackendOptions& options,
                                 int steps, BackendFacts& facts, bool keep_steps = false);
/// `steps` >= 0 uniform refinements through the backend of the geometry's space (steps = 0: the geometry and
/// the identity, no steps). keep_steps: as make_refined_geometry.
Refinement refine_uniform(const Geometry& geometry, int steps, BackendFacts& facts, bool keep_steps = false);

/// Local refinement of the marked elements through the backend of the geometry's space (UnsupportedError naming
/// the backend when it has none).
Refinement refine_marked(const Geometry& geometry, std::span<const Index> marked, int admissibility, BackendFacts& facts,
                         bool with_prolongation = true);

/// For backends whose dofs are some of a net's vertices and which refine by rebuilding from a refined net:
/// the net with the control point of dof d at vertex vertex_of_dof(d) (planar geometries get z = 0; vertices
/// that are no dof keep their positions).
mesh::PolyMesh net_with_control_points(const mesh::PolyMesh& net, const Geometry& geometry,
                                       const std::function<Index(Index)>& vertex_of_dof);

/// Registration functions, one per backend folder.
Backend bspline_backend();
Backend catmull_clark_backend();
Backend polyhedral_backend();
Backend half_box_backend();

}  // namespace iga::basis
