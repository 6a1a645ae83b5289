#include "io/sampled_writer.hpp"

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkCellType.h>
#include <vtkDoubleArray.h>
#include <vtkIdTypeArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkSmartPointer.h>
#include <vtkUnsignedCharArray.h>
#include <vtkUnstructuredGrid.h>

#include "core/error.hpp"
#include "io/vtk_file.hpp"

namespace iga::io {

namespace {

vtkSmartPointer<vtkDoubleArray> array(const std::string& name, int components, Index tuples) {
  auto a = vtkSmartPointer<vtkDoubleArray>::New();
  a->SetName(name.c_str());
  a->SetNumberOfComponents(components);
  a->SetNumberOfTuples(static_cast<vtkIdType>(tuples));
  return a;
}

void check_size(const std::string& what, const std::string& name, Index size, Index expected) {
  if (size != expected) {
    throw InputError("sampled output: " + what + " '" + name + "' has " + std::to_string(size) + " values for " +
                     std::to_string(expected));
  }
}

// Planar points (z = 0) and cells of one VTK type given by offsets into the connectivity.
vtkSmartPointer<vtkUnstructuredGrid> make_grid(const Eigen::Matrix2Xd& pts, const std::vector<vtkIdType>& offsets,
                                               const std::vector<vtkIdType>& connectivity, unsigned char type) {
  const Index np = pts.cols();
  auto coords = array("Points", 3, np);
  for (Index k = 0; k < np; ++k) coords->SetTuple3(static_cast<vtkIdType>(k), pts(0, k), pts(1, k), 0.0);
  const Index nc = static_cast<Index>(offsets.size()) - 1;
  vtkNew<vtkIdTypeArray> off, conn;
  off->SetNumberOfTuples(static_cast<vtkIdType>(offsets.size()));
  for (std::size_t k = 0; k < offsets.size(); ++k) off->SetValue(static_cast<vtkIdType>(k), offsets[k]);
  conn->SetNumberOfTuples(static_cast<vtkIdType>(connectivity.size()));
  for (std::size_t k = 0; k < connectivity.size(); ++k) conn->SetValue(static_cast<vtkIdType>(k), connectivity[k]);
  vtkNew<vtkUnsignedCharArray> types;
  types->SetNumberOfTuples(static_cast<vtkIdType>(nc));
  for (Index k = 0; k < nc; ++k) types->SetValue(static_cast<vtkIdType>(k), type);
  vtkNew<vtkPoints> points;
  points->SetData(coords);
  vtkNew<vtkCellArray> cells;
  cells->SetData(off, conn);
  auto grid = vtkSmartPointer<vtkUnstructuredGrid>::New();
  grid->SetPoints(points);
  grid->SetCells(types, cells);
  return grid;
}

void add_point_scalars(vtkUnstructuredGrid* grid, const std::vector<std::pair<std::string, Eigen::VectorXd>>& data,
                       Index np) {
  for (const auto& [name, v] : data) {
    check_size("point data", name, v.size(), np);
    auto a = array(name, 1, np);
    for (Index k = 0; k < np; ++k) a->SetValue(static_cast<vtkIdType>(k), v(k));
    grid->GetPointData()->AddArray(a);
  }
  if (!data.empty()) grid->GetPointData()->SetActiveScalars(data.front().first.c_str());
}

}  // namespace

void write_curves_vtu(const std::string& path, const CurveData& c) {
  const Index np = c.points.cols();
  const Index nc = static_cast<Index>(c.offsets.size()) - 1;
  if (nc < 0 || c.offsets.front() != 0 || c.offsets.back() != np) {
    throw InputError("curve output: the cell offsets must run from 0 to the number of points");
  }
  for (Index k = 0; k < nc; ++k) {
    if (c.offsets[static_cast<std::size_t>(k + 1)] - c.offsets[static_cast<std::size_t>(k)] < 2) {
      throw InputError("curve output: cell " + std::to_string(k) + " has fewer than two points");
    }
  }
  std::vector<vtkIdType> offsets(c.offsets.begin(), c.offsets.end()), connectivity(static_cast<std::size_t>(np));
  for (Index k = 0; k < np; ++k) connectivity[static_cast<std::size_t>(k)] = static_cast<vtkIdType>(k);
  const auto grid = make_grid(c.points, offsets, connectivity, VTK_POLY_LINE);
  add_point_scalars(grid, c.point_scalars, np);
  for (const auto& [name, v] : c.point_vectors) {
    check_size("point vectors", name, v.cols(), np);
    auto a = array(name, 3, np);
    for (Index k = 0; k < np; ++k) a->SetTuple3(static_cast<vtkIdType>(k), v(0, k), v(1, k), 0.0);
    grid->GetPointData()->AddArray(a);
  }
  for (const auto& [name, v] : c.cell_scalars) {
    check_size("cell data", name, v.size(), nc);
    auto a = array(name, 1, nc);
    for (Index k = 0; k < nc; ++k) a->SetValue(static_cast<vtkIdType>(k), v(k));
    grid->GetCellData()->AddArray(a);
  }
  write_vtk_grid(path, grid);
}

void write_grid_vtu(const std::string& path, const GridData& g) {
  if (g.nx < 2 || g.ny < 2) {
    throw InputError("grid output: at least 2 × 2 points, got " + std::to_string(g.nx) + " × " + std::to_string(g.ny));
  }
  const Index np = g.nx * g.ny;
  if (g.points.cols() != np) {
    throw InputError("grid output: " + std::to_string(g.points.cols()) + " points for a " + std::to_string(g.nx) +
                     " × " + std::to_string(g.ny) + " grid");
  }
  std::vector<vtkIdType> offsets{0}, connectivity;
  const auto nx = static_cast<vtkIdType>(g.nx);
  for (Index j = 0; j + 1 < g.ny; ++j) {
    for (Index i = 0; i + 1 < g.nx; ++i) {
      const auto a = static_cast<vtkIdType>(i + g.nx * j);
      connectivity.insert(connectivity.end(), {a, a + 1, a + 1 + nx, a + nx});
      offsets.push_back(static_cast<vtkIdType>(connectivity.size()));
    }
  }
  const auto grid = make_grid(g.points, offsets, connectivity, VTK_QUAD);
  add_point_scalars(grid, g.point_scalars, np);
  write_vtk_grid(path, grid);
}

}  // namespace iga::io
