#pragma once
// Pieces shared by the .vtu writers of a Space (vtu_writer.cpp: sampled linear cells; bezier_writer.cpp: Bézier
// cells): named double arrays and the per-cell data that says which element a VTK cell belongs to. Internal to
// io/ (it names VTK types, which io/ links privately).
#include <Eigen/Core>
#include <algorithm>
#include <span>
#include <string>
#include <utility>
#include <vector>
#include <vtkCellArray.h>
#include <vtkDoubleArray.h>
#include <vtkIdTypeArray.h>
#include <vtkNew.h>
#include <vtkUnsignedCharArray.h>
#include <vtkUnstructuredGrid.h>
#include <vtkSmartPointer.h>

#include "basis/space.hpp"
#include "io/element_data.hpp"

namespace iga::io {

/// A double array of `tuples` tuples with `components` components.
vtkSmartPointer<vtkDoubleArray> make_double_array(const char* name, int components, Index tuples);

/// InputError naming the entry when an entry of element_data does not have one value per element.
void check_element_data(const basis::Space& space, const ElementData& element_data);

/// Adds the cell data of cells that belong to elements element_of_cell[c]: "element" (vtkIdTypeArray, the element
/// index), "element_kind" (vtkIntArray, basis::kind_code of its kind), "level" (vtkIntArray, Space::level) and each
/// entry of element_data (vtkDoubleArray; checked as check_element_data).
void add_element_cell_data(vtkUnstructuredGrid* grid, const basis::Space& space, std::span<const Index> element_of_cell,
                           const ElementData& element_data);

/// Sets the cells of grid: cell c has the points connectivity[offsets[c] .. offsets[c + 1]) and the VTK type
/// types[c] (offsets has one entry more than types). I: Index or vtkIdType.
template <class I>
void set_cells(vtkUnstructuredGrid* grid, const std::vector<I>& offsets, const std::vector<I>& connectivity,
               const std::vector<unsigned char>& types) {
  vtkNew<vtkIdTypeArray> off, conn;
  off->SetNumberOfTuples(static_cast<vtkIdType>(offsets.size()));
  std::copy(offsets.begin(), offsets.end(), off->GetPointer(0));
  conn->SetNumberOfTuples(static_cast<vtkIdType>(connectivity.size()));
  std::copy(connectivity.begin(), connectivity.end(), conn->GetPointer(0));
  vtkNew<vtkUnsignedCharArray> type_array;
  type_array->SetNumberOfTuples(static_cast<vtkIdType>(types.size()));
  std::copy(types.begin(), types.end(), type_array->GetPointer(0));
  vtkNew<vtkCellArray> cells;
  cells->SetData(off, conn);
  grid->SetCells(type_array, cells);
}

}  // namespace iga::io
