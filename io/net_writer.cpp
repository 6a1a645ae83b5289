#include "io/net_writer.hpp"

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkCellType.h>
#include <vtkIdTypeArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkUnsignedCharArray.h>
#include <vtkUnstructuredGrid.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <optional>
#include <vector>

#include "io/vtk_file.hpp"
#include "io/vtu_cell_data.hpp"

namespace iga::io {

namespace {

Eigen::Vector3d control_point(const basis::Geometry& geometry, Index d) {
  Eigen::Vector3d x = Eigen::Vector3d::Zero();
  x.head(geometry.dim()) = geometry.control_points().row(d).transpose();
  return x;
}

/// The dof at each net vertex's position (std::nullopt where there is none), by rounding to a grid of `tol` and
/// checking the neighbouring cells.
std::vector<std::optional<Index>> dof_at_vertices(const basis::Geometry& geometry, const mesh::PolyMesh& net,
                                                  double tol) {
  using Key = std::array<long long, 3>;
  const auto key_of = [tol](const Eigen::Vector3d& x) {
    return Key{static_cast<long long>(std::floor(x(0) / tol)), static_cast<long long>(std::floor(x(1) / tol)),
               static_cast<long long>(std::floor(x(2) / tol))};
  };
  std::map<Key, std::vector<Index>> grid;
  for (Index d = 0; d < geometry.control_points().rows(); ++d) grid[key_of(control_point(geometry, d))].push_back(d);
  std::vector<std::optional<Index>> out(static_cast<std::size_t>(net.num_vertices()));
  for (Index v = 0; v < net.num_vertices(); ++v) {
    const Key k = key_of(net.point(v));
    for (int n = 0; n < 27 && !out[static_cast<std::size_t>(v)]; ++n) {
      const auto it = grid.find({k[0] + n % 3 - 1, k[1] + (n / 3) % 3 - 1, k[2] + n / 9 - 1});
      if (it == grid.end()) continue;
      for (const Index d : it->second) {
        if ((control_point(geometry, d) - net.point(v)).lpNorm<Eigen::Infinity>() <= tol) out[static_cast<std::size_t>(v)] = d;
      }
    }
  }
  return out;
}

}  // namespace

void write_control_net_vtu(const std::string& path, const basis::Geometry& geometry, const mesh::PolyMesh* net) {
  const Index n = geometry.control_points().rows();
  auto coords = make_double_array("Points", 3, n);
  vtkNew<vtkIdTypeArray> dof;
  dof->SetName("dof");
  dof->SetNumberOfTuples(static_cast<vtkIdType>(n));
  std::vector<vtkIdType> offsets{0}, connectivity, face;
  std::vector<unsigned char> types;
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(0.0), hi = lo;
  for (Index d = 0; d < n; ++d) {
    const Eigen::Vector3d x = control_point(geometry, d);
    coords->SetTuple3(static_cast<vtkIdType>(d), x(0), x(1), x(2));
    dof->SetValue(static_cast<vtkIdType>(d), static_cast<vtkIdType>(d));
    lo = d == 0 ? x : lo.cwiseMin(x);
    hi = d == 0 ? x : hi.cwiseMax(x);
    connectivity.push_back(static_cast<vtkIdType>(d));
    offsets.push_back(static_cast<vtkIdType>(connectivity.size()));
    types.push_back(VTK_VERTEX);
    face.push_back(-1);
  }
  if (net != nullptr && n > 0) {
    const double tol = 1e-10 * std::max((hi - lo).norm(), 1e-300);
    const auto dof_of = dof_at_vertices(geometry, *net, tol);
    for (Index f = 0; f < net->num_faces(); ++f) {
      const auto vs = net->face(f);
      if (!std::all_of(vs.begin(), vs.end(), [&](Index v) { return dof_of[static_cast<std::size_t>(v)].has_value(); })) continue;
      for (const Index v : vs) connectivity.push_back(static_cast<vtkIdType>(*dof_of[static_cast<std::size_t>(v)]));
      offsets.push_back(static_cast<vtkIdType>(connectivity.size()));
      types.push_back(VTK_POLYGON);
      face.push_back(static_cast<vtkIdType>(f));
    }
  }
  vtkNew<vtkUnstructuredGrid> grid;
  vtkNew<vtkPoints> points;
  points->SetData(coords);
  grid->SetPoints(points);
  set_cells(grid, offsets, connectivity, types);
  vtkNew<vtkIdTypeArray> face_array;
  face_array->SetNumberOfTuples(static_cast<vtkIdType>(face.size()));
  std::copy(face.begin(), face.end(), face_array->GetPointer(0));
  face_array->SetName("net_face");
  grid->GetPointData()->AddArray(dof);
  grid->GetCellData()->AddArray(face_array);
  write_vtk_grid(path, grid);
}

}  // namespace iga::io
