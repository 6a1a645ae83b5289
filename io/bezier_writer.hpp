#pragma once
// Exact output for ParaView: every element as one VTK Bézier cell (VTK_BEZIER_QUADRILATERAL / VTK_BEZIER_TRIANGLE)
// with its control points shared between neighbouring cells, plus the element outlines as VTK_BEZIER_CURVE cells.
#include <Eigen/Core>
#include <memory>
#include <string>
#include <vector>

#include "basis/geometry.hpp"
#include "fem/function.hpp"
#include "io/vtu_writer.hpp"

namespace iga::io {

struct BezierOptions {
  /// Degree of the cells of elements that are not polynomial (Space::polynomial_degree() == std::nullopt: at an
  /// extraordinary vertex or face), 1 .. kMaxBezierDegree (bezier_layout.hpp).
  int degree = 6;
  /// Control points on element sides closer than merge_tolerance × (diagonal of the bounding box of the geometry's
  /// control points), with u coefficients closer than merge_tolerance × max |u|, are one point.
  double merge_tolerance = 1e-10;
  std::shared_ptr<const fem::Function> exact;  ///< optional exact solution
  /// More point arrays (vtu_writer.hpp): a vector or tensor field, written as the Bernstein coefficients of its
  /// degree-d interpolant at the cell's nodes (exact where the field is a polynomial of the cell's degree, e.g. a
  /// displacement on a polynomial element; an interpolant of forces or stresses).
  std::vector<SampledField> fields = {};
};

/// The Bézier cells of a geometry and a field on it. Element e is cell e, of degree d = Space::polynomial_degree(e)
/// or, when that is std::nullopt, options.degree; its control points (of the map x and of u) are the Bernstein
/// coefficients of the cell's degree that interpolate x and u at the nodes of bezier_layout(shape, d), which
/// include the element's sides:
///  - polynomial elements: x and u exactly (to round-off);
///  - other elements: an interpolant inside; a side shared with a polynomial element of degree <= d is exact
///    (it is a polynomial curve), and a side shared with another element of the same degree gets the same control
///    points (the nodes on a side are symmetric about its midpoint), so the surface has no cracks.
/// In a locally refined (hierarchical) space, a side of a non-polynomial element that meets several finer elements is
/// one interpolating curve: the finer cells along it take that curve (restricted to their piece, at the coarse cell's
/// degree or higher; bezier_hanging.hpp), so they are exact except along that side, and there are no cracks there
/// either.
/// Control points on element sides are merged (BezierOptions::merge_tolerance); interior ones are the cell's own.
struct BezierMesh {
  Eigen::Matrix3Xd points;  ///< control points (physical; z = 0 for planar geometries)
  Eigen::VectorXd u;        ///< Bernstein coefficients of u per point (empty: no field)
  Eigen::VectorXd exact;    ///< coefficients of the degree-d interpolant of options.exact per point (empty without)
  Eigen::VectorXd weights;  ///< rational weights per point (VTK's RationalWeights; empty when no cell is rational)
  /// BezierOptions::fields in order: name and coefficients (components × points). A point on a side shared by cells
  /// has the first cell's (a field whose derivatives jump across the side, e.g. a force on a C1 space, is continuous
  /// in the file).
  std::vector<std::pair<std::string, Eigen::MatrixXd>> fields;
  std::vector<Index> offsets{0};  ///< cell c: points connectivity[offsets[c] .. offsets[c + 1] − 1], VTK's order
  std::vector<Index> connectivity;
  std::vector<int> degree;             ///< per cell
  std::vector<basis::Shape> shape;     ///< per cell
  std::vector<bool> exact_cell;        ///< per cell: x and u exact on the whole cell
  Index num_polynomial = 0;            ///< cells that are exact

  Index num_cells() const { return static_cast<Index>(degree.size()); }
};

/// u: coefficients of geometry.space()'s functions, or nullptr for the geometry alone. InputError when u has the
/// wrong size or options.degree is out of range.
BezierMesh bezier_mesh(const basis::Geometry& geometry, const Eigen::VectorXd* u, const BezierOptions& options = {});

/// Writes the cells (binary VTK XML, VTK's writer). Point data: "u" (the exact Bernstein coefficients) when the
/// mesh has a field; with an exact solution "exact" (its interpolant of each cell's degree, not the exact solution's
/// Bernstein coefficients) and "error" = u − exact. Cell data: "HigherOrderDegrees" (VTK's attribute: d, d, 0),
/// "element", "element_kind", "level" and element_data (vtu_cell_data.hpp); the mesh's fields as point data. InputError(
/// path, 0, "cannot write file") when VTK fails.
void write_bezier_vtu(const std::string& path, const basis::Space& space, const BezierMesh& mesh,
                      const ElementData& element_data = {}, const Pieces& pieces = {});

/// Writes each element side once as a VTK_BEZIER_CURVE (the side's control points of its cell; a side between
/// cells of different degrees appears once per degree, both exact), with cell data "element" (the first element
/// that has it) and "side"; point data "u" when the mesh has it.
void write_bezier_outline_vtu(const std::string& path, const BezierMesh& mesh, const Pieces& pieces = {});

/// "<base>_outline.vtu" for "<base>.vtu" (or "<path>_outline.vtu").
std::string outline_path(const std::string& vtu_path);

/// bezier_mesh, write_bezier_vtu to path and write_bezier_outline_vtu to outline_path(path).
/// pieces: a distributed run's (vtk_file.hpp): this rank writes its elements' cells, rank 0 the .pvtu.
void write_bezier(const std::string& path, const basis::Geometry& geometry, const Eigen::VectorXd* u,
                  const BezierOptions& options = {}, const ElementData& element_data = {}, const Pieces& pieces = {});

}  // namespace iga::io
