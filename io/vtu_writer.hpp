#pragma once
// Output of a discrete solution for ParaView: a VTK XML unstructured grid (.vtu).
#include <Eigen/Core>
#include <functional>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "basis/geometry.hpp"
#include "fem/function.hpp"
#include "io/element_data.hpp"
#include "io/vtk_file.hpp"

namespace iga::io {

/// A point array of the sampled grid computed from what the writer evaluated on element e (the basis with first
/// derivatives and the map at the element's sample points): out is components × q. For fields that are not one
/// scalar combination of the space's functions: a displacement (3 components, ParaView's Warp By Vector), a
/// stress tensor (6 components XX, YY, ZZ, XY, YZ, XZ: ParaView's symmetric tensor order), a von Mises stress.
struct SampledField {
  std::string name;
  int components = 1;
  std::function<void(Index e, const basis::BasisValues& basis, const basis::GeometryValues& geo, Eigen::MatrixXd& out)>
      values;
  /// What values() reads: 1 the basis with first derivatives and the map's Jacobian, 2 also the second derivatives
  /// of both (curvatures, bending moments). The writer evaluates the largest any field asks for.
  int derivatives = 1;
};

/// Where the writers evaluate fields that read `derivatives` on element e for its reference points `at`: `at` itself,
/// except for second derivatives on an element that is neither polynomial nor rational (at an extraordinary vertex,
/// where they need not exist at the corner: half-box refuses it): there each point is moved 1e-6 of the way to the
/// element's centre.
Eigen::Matrix2Xd field_points(const basis::Space& space, Index e, const Eigen::Matrix2Xd& at, int derivatives);
/// Whether field_points moves the points of element e (second derivatives on an element at an extraordinary vertex).
bool fields_moved(const basis::Space& space, Index e, int derivatives);

struct VtuOptions {
  int samples = 5;                             ///< points per direction on each element (>= 2)
  std::shared_ptr<const fem::Function> exact;  ///< optional exact solution
  std::vector<SampledField> fields = {};       ///< more point arrays (every write_vtu below writes them)
};


/// One step of a series for ParaView: a .vtu file and its time (the adaptive step).
struct SeriesEntry {
  double time = 0.0;
  std::string file;  ///< as referenced from the .pvd (relative to its folder)
};
/// Writes a ParaView collection (.pvd) so ParaView plays the files as a time series. InputError(path, 0, ..) when
/// the file cannot be written.
void write_pvd(const std::string& path, const std::vector<SeriesEntry>& entries);

/// Writes the solution u (coefficients of geometry.space()'s functions) as a binary VTK XML unstructured
/// grid, with VTK's own writer.
///
/// Every element is sampled on its reference domain with t_i = i / (samples - 1), both ends included; the
/// points are duplicated per element (no merging across element edges):
///  - Quad-shape elements: the samples × samples grid, as (samples - 1)^2 VTK_QUAD cells;
///  - Triangle-shape elements: the lattice {(i, j) / (samples - 1) : i + j <= samples - 1}, as
///    (samples - 1)^2 VTK_TRIANGLE cells.
/// Points are the physical positions (3D, z = 0 on planar domains).
/// Point data: "u", "grad_u" (3 components, the physical / surface gradient) and, when options.exact is
/// set, "exact" and "error" (= u - exact). Cell data: "element" (vtkIdTypeArray, the element index) and
/// "element_kind" (vtkIntArray, basis::kind_code of the element's kind), "level" (vtkIntArray, Space::level: the
/// refinement level in hierarchical spaces, 0 otherwise) and each entry of element_data (InputError when its size
/// is not the number of elements).
///
/// Throws InputError when u.size() != num_dofs or samples < 2, and InputError(path, 0, "cannot write file")
/// when VTK's writer fails.
/// pieces: a distributed run's (vtk_file.hpp): this rank writes its elements' cells, rank 0 the .pvtu.
void write_vtu(const std::string& path, const basis::Geometry& geometry, const Eigen::VectorXd& u,
               const VtuOptions& options = {}, const ElementData& element_data = {}, const Pieces& pieces = {});

/// The reference points write_vtu samples on an element of this shape, in the order of its points in the file
/// (2 × q; InputError for samples < 2).
Eigen::Matrix2Xd sample_points(basis::Shape shape, int samples);

/// A field given point by point on each element (a solution that is not a combination of the space's functions,
/// e.g. the BEM's interior representation): out(k) is its value at reference point ref.col(k) of element e,
/// physical point x.col(k) (3 × q); `out` has ref.cols() entries.
using ElementField = std::function<void(Index e, const Eigen::Matrix2Xd& ref, const Eigen::Matrix3Xd& x,
                                        Eigen::VectorXd& out)>;
/// The same grid as above with "u" = field (no "grad_u"), "exact"/"error" with options.exact.
void write_vtu(const std::string& path, const basis::Geometry& geometry, const ElementField& field,
               const VtuOptions& options = {}, const ElementData& element_data = {});
/// The geometry alone (no solution): the same grid without "u", "grad_u" and "error" ("exact" with options.exact).
void write_vtu(const std::string& path, const basis::Geometry& geometry, const VtuOptions& options,
               const ElementData& element_data = {}, const Pieces& pieces = {});

}  // namespace iga::io
