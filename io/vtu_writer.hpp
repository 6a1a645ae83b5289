#pragma once
// Output of a discrete solution for ParaView: a VTK XML unstructured grid (.vtu).
#include <Eigen/Core>
#include <memory>
#include <string>

#include "basis/geometry.hpp"
#include "fem/function.hpp"

namespace iga::io {

struct VtuOptions {
  int samples = 5;                             ///< points per direction on each element (>= 2)
  std::shared_ptr<const fem::Function> exact;  ///< optional exact solution
};

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
/// "element_kind" (vtkIntArray, basis::kind_code of the element's kind).
///
/// Throws InputError when u.size() != num_dofs or samples < 2, and InputError(path, 0, "cannot write file")
/// when VTK's writer fails.
void write_vtu(const std::string& path, const basis::Geometry& geometry, const Eigen::VectorXd& u,
               const VtuOptions& options = {});

}  // namespace iga::io
