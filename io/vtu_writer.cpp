#include "io/vtu_writer.hpp"

#include <vtkCallbackCommand.h>
#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkXMLDataElement.h>
#include <vtkXMLUtilities.h>
#include <fstream>
#include <vtkCellType.h>
#include <vtkCommand.h>
#include <vtkDoubleArray.h>
#include <vtkErrorCode.h>
#include <vtkExecutive.h>
#include <vtkIdTypeArray.h>
#include <vtkIntArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkUnsignedCharArray.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLUnstructuredGridWriter.h>

#include <array>
#include <functional>
#include <vector>

#include "basis/basis_values.hpp"
#include "basis/element_kind.hpp"
#include "core/error.hpp"
#include "io/vtk_file.hpp"

namespace iga::io {

namespace {

/// The sample points of one reference domain and the local cells connecting them.
struct SamplePattern {
  Eigen::Matrix2Xd points;        ///< reference coordinates, 2 × points
  std::vector<vtkIdType> cells;   ///< local point indices, cell_size per cell
  int cell_size = 4;
  unsigned char vtk_type = VTK_QUAD;

  Index num_points() const { return points.cols(); }
  Index num_cells() const { return static_cast<Index>(cells.size()) / cell_size; }
};

/// samples × samples grid of the unit square; point (i, j) has index i + j * samples.
SamplePattern quad_pattern(int samples) {
  SamplePattern p;
  p.cell_size = 4;
  p.vtk_type = VTK_QUAD;
  const Index s = samples;
  const double h = 1.0 / static_cast<double>(s - 1);
  p.points.resize(2, s * s);
  for (Index j = 0; j < s; ++j) {
    for (Index i = 0; i < s; ++i) {
      // Exact end points (i == s - 1 gives exactly 1).
      p.points(0, i + j * s) = i == s - 1 ? 1.0 : static_cast<double>(i) * h;
      p.points(1, i + j * s) = j == s - 1 ? 1.0 : static_cast<double>(j) * h;
    }
  }
  p.cells.reserve(static_cast<std::size_t>(4 * (s - 1) * (s - 1)));
  for (Index j = 0; j + 1 < s; ++j) {
    for (Index i = 0; i + 1 < s; ++i) {
      const vtkIdType a = static_cast<vtkIdType>(i + j * s);
      // Counter-clockwise in the reference square.
      p.cells.insert(p.cells.end(), {a, a + 1, a + 1 + static_cast<vtkIdType>(s), a + static_cast<vtkIdType>(s)});
    }
  }
  return p;
}

/// Triangular lattice {(i, j) / m : i + j <= m}, m = samples - 1, rows of constant j one after another.
SamplePattern triangle_pattern(int samples) {
  SamplePattern p;
  p.cell_size = 3;
  p.vtk_type = VTK_TRIANGLE;
  const Index m = samples - 1;
  const double h = 1.0 / static_cast<double>(m);
  const auto index = [m](Index i, Index j) -> vtkIdType {
    return static_cast<vtkIdType>(j * (m + 1) - j * (j - 1) / 2 + i);
  };
  p.points.resize(2, (m + 1) * (m + 2) / 2);
  for (Index j = 0; j <= m; ++j) {
    for (Index i = 0; i + j <= m; ++i) {
      p.points(0, index(i, j)) = i == m ? 1.0 : static_cast<double>(i) * h;
      p.points(1, index(i, j)) = j == m ? 1.0 : static_cast<double>(j) * h;
    }
  }
  p.cells.reserve(static_cast<std::size_t>(3 * m * m));
  for (Index j = 0; j < m; ++j) {
    for (Index i = 0; i + j < m; ++i) {
      // "Upward" triangle, then the "downward" one next to it when it exists; both counter-clockwise.
      p.cells.insert(p.cells.end(), {index(i, j), index(i + 1, j), index(i, j + 1)});
      if (i + j + 1 < m) p.cells.insert(p.cells.end(), {index(i + 1, j), index(i + 1, j + 1), index(i, j + 1)});
    }
  }
  return p;
}

vtkNew<vtkDoubleArray> make_double_array(const char* name, int components, Index tuples) {
  vtkNew<vtkDoubleArray> a;
  a->SetName(name);
  a->SetNumberOfComponents(components);
  a->SetNumberOfTuples(static_cast<vtkIdType>(tuples));
  return a;
}

// Values (and, when `grads` is not null, physical gradients) of the written field at element e's sample points.
using Sampler = std::function<void(Index e, const Eigen::Matrix2Xd& ref, const basis::BasisValues& bv,
                                   const basis::GeometryValues& gv, Eigen::VectorXd& values, Eigen::Matrix3Xd* grads)>;

void write_samples(const std::string& path, const basis::Geometry& geometry, const Sampler& sample, bool with_grad,
                   const VtuOptions& options, const ElementData& element_data) {
  const basis::Space& space = geometry.space();
  if (options.samples < 2) {
    throw InputError("write_vtu: samples must be at least 2, got " + std::to_string(options.samples));
  }

  const std::array<SamplePattern, 2> patterns = {quad_pattern(options.samples), triangle_pattern(options.samples)};
  const auto pattern_of = [&](const basis::ElementKind& k) -> const SamplePattern& {
    return patterns[k.shape == basis::Shape::Triangle ? 1 : 0];
  };

  // Sizes up front, so every array is allocated once.
  const Index num_elements = space.num_elements();
  Index total_points = 0;
  Index total_cells = 0;
  Index total_connectivity = 0;
  for (Index e = 0; e < num_elements; ++e) {
    const SamplePattern& p = pattern_of(space.kind(e));
    total_points += p.num_points();
    total_cells += p.num_cells();
    total_connectivity += static_cast<Index>(p.cells.size());
  }

  auto coords = make_double_array("Points", 3, total_points);
  auto u_array = make_double_array("u", 1, total_points);
  auto grad_array = make_double_array("grad_u", 3, with_grad ? total_points : 0);
  const bool with_exact = static_cast<bool>(options.exact);
  auto exact_array = make_double_array("exact", 1, with_exact ? total_points : 0);
  auto error_array = make_double_array("error", 1, with_exact ? total_points : 0);

  vtkNew<vtkIdTypeArray> offsets;
  offsets->SetNumberOfTuples(static_cast<vtkIdType>(total_cells + 1));
  vtkNew<vtkIdTypeArray> connectivity;
  connectivity->SetNumberOfTuples(static_cast<vtkIdType>(total_connectivity));
  vtkNew<vtkUnsignedCharArray> cell_types;
  cell_types->SetNumberOfTuples(static_cast<vtkIdType>(total_cells));
  vtkNew<vtkIdTypeArray> element_array;
  element_array->SetName("element");
  element_array->SetNumberOfTuples(static_cast<vtkIdType>(total_cells));
  vtkNew<vtkIntArray> kind_array;
  kind_array->SetName("element_kind");
  kind_array->SetNumberOfTuples(static_cast<vtkIdType>(total_cells));

  double* x_out = coords->GetPointer(0);
  double* u_out = u_array->GetPointer(0);
  double* grad_out = with_grad ? grad_array->GetPointer(0) : nullptr;
  double* exact_out = with_exact ? exact_array->GetPointer(0) : nullptr;
  double* error_out = with_exact ? error_array->GetPointer(0) : nullptr;
  vtkIdType* offset_out = offsets->GetPointer(0);
  vtkIdType* conn_out = connectivity->GetPointer(0);
  unsigned char* type_out = cell_types->GetPointer(0);
  vtkIdType* element_out = element_array->GetPointer(0);
  int* kind_out = kind_array->GetPointer(0);
  vtkNew<vtkIntArray> level_array;
  level_array->SetName("level");
  level_array->SetNumberOfTuples(static_cast<vtkIdType>(total_cells));
  int* level_out = level_array->GetPointer(0);
  std::vector<vtkSmartPointer<vtkDoubleArray>> extra;
  for (const auto& [name, values] : element_data) {
    if (values.size() != num_elements) {
      throw InputError("vtu: element data '" + name + "' has " + std::to_string(values.size()) + " values for " +
                       std::to_string(num_elements) + " elements");
    }
    auto a = vtkSmartPointer<vtkDoubleArray>::New();
    a->SetName(name.c_str());
    a->SetNumberOfTuples(static_cast<vtkIdType>(total_cells));
    extra.push_back(a);
  }

  basis::BasisValues bv;
  basis::GeometryValues gv;
  Eigen::VectorXd values;
  Eigen::Matrix3Xd grads;
  Eigen::VectorXd exact_values;

  vtkIdType point_base = 0;
  vtkIdType conn_pos = 0;
  Index cell = 0;
  offset_out[0] = 0;
  for (Index e = 0; e < num_elements; ++e) {
    const basis::ElementKind kind = space.kind(e);
    const SamplePattern& p = pattern_of(kind);
    const Index q = p.num_points();

    space.evaluate(e, p.points, 1, bv);
    geometry.evaluate(e, bv, gv, /*check=*/false);

    sample(e, p.points, bv, gv, values, with_grad ? &grads : nullptr);
    if (with_exact) options.exact->values(gv.x, exact_values);

    for (Index k = 0; k < q; ++k) {
      const Index g = point_base + k;
      for (int c = 0; c < 3; ++c) {
        x_out[3 * g + c] = gv.x(c, k);
        if (with_grad) grad_out[3 * g + c] = grads(c, k);
      }
      u_out[g] = values(k);
      if (with_exact) {
        exact_out[g] = exact_values(k);
        error_out[g] = values(k) - exact_values(k);
      }
    }

    const Index nc = p.num_cells();
    for (Index c = 0; c < nc; ++c) {
      for (int a = 0; a < p.cell_size; ++a) {
        conn_out[conn_pos++] = point_base + p.cells[static_cast<std::size_t>(c * p.cell_size + a)];
      }
      offset_out[cell + 1] = conn_pos;
      type_out[cell] = p.vtk_type;
      element_out[cell] = static_cast<vtkIdType>(e);
      kind_out[cell] = basis::kind_code(kind);
      level_out[cell] = space.level(e);
      for (std::size_t k = 0; k < extra.size(); ++k) extra[k]->SetValue(cell, element_data[k].second(e));
      ++cell;
    }
    point_base += static_cast<vtkIdType>(q);
  }

  vtkNew<vtkPoints> points;
  points->SetData(coords);
  vtkNew<vtkCellArray> cells;
  cells->SetData(offsets, connectivity);

  vtkNew<vtkUnstructuredGrid> grid;
  grid->SetPoints(points);
  grid->SetCells(cell_types, cells);
  grid->GetPointData()->AddArray(u_array);
  grid->GetPointData()->SetActiveScalars("u");
  if (with_grad) {
    grid->GetPointData()->AddArray(grad_array);
    grid->GetPointData()->SetActiveVectors("grad_u");
  }
  if (with_exact) {
    grid->GetPointData()->AddArray(exact_array);
    grid->GetPointData()->AddArray(error_array);
  }
  grid->GetCellData()->AddArray(element_array);
  grid->GetCellData()->AddArray(kind_array);
  grid->GetCellData()->AddArray(level_array);
  for (const auto& a : extra) grid->GetCellData()->AddArray(a);

  write_vtk_grid(path, grid);
}

}  // namespace

Eigen::Matrix2Xd sample_points(basis::Shape shape, int samples) {
  if (samples < 2) throw InputError("write_vtu: samples must be at least 2, got " + std::to_string(samples));
  return (shape == basis::Shape::Triangle ? triangle_pattern(samples) : quad_pattern(samples)).points;
}

void write_vtu(const std::string& path, const basis::Geometry& geometry, const Eigen::VectorXd& u,
               const VtuOptions& options, const ElementData& element_data) {
  const basis::Space& space = geometry.space();
  if (u.size() != space.num_dofs()) {
    throw InputError("write_vtu: the solution has " + std::to_string(u.size()) + " coefficients, the space has " +
                     std::to_string(space.num_dofs()) + " functions");
  }
  Eigen::VectorXd local_u, du, dv;
  const Sampler sample = [&](Index e, const Eigen::Matrix2Xd&, const basis::BasisValues& bv,
                             const basis::GeometryValues& gv, Eigen::VectorXd& values, Eigen::Matrix3Xd* grads) {
    const auto dofs = space.dofs(e);
    local_u.resize(static_cast<Index>(dofs.size()));
    for (std::size_t a = 0; a < dofs.size(); ++a) local_u(static_cast<Index>(a)) = u(dofs[a]);
    values.noalias() = bv.value.transpose() * local_u;
    du.noalias() = bv.du.transpose() * local_u;
    dv.noalias() = bv.dv.transpose() * local_u;
    grads->resize(3, values.size());
    for (Index k = 0; k < values.size(); ++k) grads->col(k) = gv.tu.col(k) * du(k) + gv.tv.col(k) * dv(k);
  };
  write_samples(path, geometry, sample, true, options, element_data);
}

void write_vtu(const std::string& path, const basis::Geometry& geometry, const ElementField& field,
               const VtuOptions& options, const ElementData& element_data) {
  const Sampler sample = [&](Index e, const Eigen::Matrix2Xd& ref, const basis::BasisValues&,
                             const basis::GeometryValues& gv, Eigen::VectorXd& values, Eigen::Matrix3Xd*) {
    values.resize(ref.cols());
    field(e, ref, gv.x, values);
  };
  write_samples(path, geometry, sample, false, options, element_data);
}

void write_pvd(const std::string& path, const std::vector<SeriesEntry>& entries) {
  // The collection format ParaView reads: VTKFile type="Collection" with one DataSet per step, built as a VTK
  // XML element tree and written by vtkXMLUtilities.
  vtkNew<vtkXMLDataElement> root;
  root->SetName("VTKFile");
  root->SetAttribute("type", "Collection");
  root->SetAttribute("version", "0.1");
  root->SetAttribute("byte_order", "LittleEndian");
  vtkNew<vtkXMLDataElement> collection;
  collection->SetName("Collection");
  for (const SeriesEntry& entry : entries) {
    vtkNew<vtkXMLDataElement> set;
    set->SetName("DataSet");
    set->SetDoubleAttribute("timestep", entry.time);
    set->SetAttribute("group", "");
    set->SetAttribute("part", "0");
    set->SetAttribute("file", entry.file.c_str());
    collection->AddNestedElement(set);
  }
  root->AddNestedElement(collection);
  std::ofstream out(path);
  if (!out) throw InputError(path, 0, "cannot write file");
  vtkXMLUtilities::FlattenElement(root, out);
  out << "\n";
  if (!out) throw InputError(path, 0, "cannot write file");
}

}  // namespace iga::io
