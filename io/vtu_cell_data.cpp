#include "io/vtu_cell_data.hpp"

#include <vtkCellData.h>
#include <vtkIdTypeArray.h>
#include <vtkIntArray.h>
#include <vtkNew.h>
#include <vtkUnstructuredGrid.h>

#include "basis/element_kind.hpp"
#include "core/error.hpp"

namespace iga::io {

vtkSmartPointer<vtkDoubleArray> make_double_array(const char* name, int components, Index tuples) {
  auto a = vtkSmartPointer<vtkDoubleArray>::New();
  a->SetName(name);
  a->SetNumberOfComponents(components);
  a->SetNumberOfTuples(static_cast<vtkIdType>(tuples));
  return a;
}

void check_element_data(const basis::Space& space, const ElementData& element_data) {
  for (const auto& [name, values] : element_data) {
    if (values.size() != space.num_elements()) {
      throw InputError("vtu: element data '" + name + "' has " + std::to_string(values.size()) + " values for " +
                       std::to_string(space.num_elements()) + " elements");
    }
  }
}

void add_element_cell_data(vtkUnstructuredGrid* grid, const basis::Space& space, std::span<const Index> element_of_cell,
                           const ElementData& element_data) {
  check_element_data(space, element_data);
  const auto cells = static_cast<vtkIdType>(element_of_cell.size());
  vtkNew<vtkIdTypeArray> element;
  element->SetName("element");
  element->SetNumberOfTuples(cells);
  vtkNew<vtkIntArray> kind;
  kind->SetName("element_kind");
  kind->SetNumberOfTuples(cells);
  vtkNew<vtkIntArray> level;
  level->SetName("level");
  level->SetNumberOfTuples(cells);
  for (vtkIdType c = 0; c < cells; ++c) {
    const Index e = element_of_cell[static_cast<std::size_t>(c)];
    element->SetValue(c, static_cast<vtkIdType>(e));
    kind->SetValue(c, basis::kind_code(space.kind(e)));
    level->SetValue(c, space.level(e));
  }
  grid->GetCellData()->AddArray(element);
  grid->GetCellData()->AddArray(kind);
  grid->GetCellData()->AddArray(level);
  for (const auto& [name, values] : element_data) {
    auto a = make_double_array(name.c_str(), 1, static_cast<Index>(cells));
    for (vtkIdType c = 0; c < cells; ++c) a->SetValue(c, values(element_of_cell[static_cast<std::size_t>(c)]));
    grid->GetCellData()->AddArray(a);
  }
}

}  // namespace iga::io
