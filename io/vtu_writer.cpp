#include "io/vtu_writer.hpp"

#include <algorithm>

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
#include "io/vtu_cell_data.hpp"

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

// Values (and, when `grads` is not null, physical gradients) of the written field at element e's sample points.
using Sampler = std::function<void(Index e, const Eigen::Matrix2Xd& ref, const basis::BasisValues& bv,
                                   const basis::GeometryValues& gv, Eigen::VectorXd& values, Eigen::Matrix3Xd* grads)>;

/// The point arrays of the sampled grid ("u", "grad_u", "exact", "error"; the ones not written are empty).
struct SampleArrays {
  vtkSmartPointer<vtkDoubleArray> x, u, grad, exact, error;
  std::vector<vtkSmartPointer<vtkDoubleArray>> fields;  ///< VtuOptions::fields, in order
};

/// Samples element e into the arrays from point `base` on.
void sample_element(Index e, const basis::Geometry& geometry, const SamplePattern& p, const Sampler* sample,
                    const VtuOptions& options, Index base, SampleArrays& a) {
  thread_local basis::BasisValues bv;
  thread_local basis::GeometryValues gv;
  thread_local Eigen::VectorXd values, exact_values;
  thread_local Eigen::Matrix3Xd grads;
  int derivatives = 1;
  for (const SampledField& f : options.fields) derivatives = std::max(derivatives, f.derivatives);
  // Fields with second derivatives on an element at an extraordinary vertex: at field_points, apart.
  const bool moved = fields_moved(geometry.space(), e, derivatives);
  geometry.space().evaluate(e, p.points, moved ? 1 : derivatives, bv);
  geometry.evaluate(e, bv, gv, /*check=*/false, moved ? 1 : derivatives);
  const bool with_grad = a.grad != nullptr, with_exact = a.exact != nullptr;
  if (sample != nullptr) (*sample)(e, p.points, bv, gv, values, with_grad ? &grads : nullptr);
  if (with_exact) options.exact->values(gv.x, exact_values);
  thread_local Eigen::MatrixXd field;
  thread_local basis::BasisValues field_bv;
  thread_local basis::GeometryValues field_gv;
  if (moved) {
    geometry.space().evaluate(e, field_points(geometry.space(), e, p.points, derivatives), derivatives, field_bv);
    geometry.evaluate(e, field_bv, field_gv, /*check=*/false, derivatives);
  }
  for (std::size_t f = 0; f < options.fields.size(); ++f) {
    const SampledField& sf = options.fields[f];
    const bool apart = moved && sf.derivatives >= 2;
    sf.values(e, apart ? field_bv : bv, apart ? field_gv : gv, field);
    if (field.rows() != sf.components || field.cols() != p.num_points()) {
      throw Error("write_vtu: field '" + sf.name + "' gave " + std::to_string(field.rows()) + " × " +
                  std::to_string(field.cols()) + " values for " + std::to_string(sf.components) + " × " +
                  std::to_string(p.num_points()));
    }
    for (Index k = 0; k < p.num_points(); ++k) {
      a.fields[f]->SetTypedTuple(static_cast<vtkIdType>(base + k), field.col(k).data());
    }
  }
  for (Index k = 0; k < p.num_points(); ++k) {
    const vtkIdType g = static_cast<vtkIdType>(base + k);
    a.x->SetTuple3(g, gv.x(0, k), gv.x(1, k), gv.x(2, k));
    if (with_grad) a.grad->SetTuple3(g, grads(0, k), grads(1, k), grads(2, k));
    if (sample != nullptr) a.u->SetValue(g, values(k));
    if (with_exact) {
      a.exact->SetValue(g, exact_values(k));
      if (sample != nullptr) a.error->SetValue(g, values(k) - exact_values(k));
    }
  }
}

/// sample == nullptr: the geometry alone (no "u", "grad_u" or "error"; "exact" with options.exact).
void write_samples(const std::string& path, const basis::Geometry& geometry, const Sampler* sample, bool with_grad,
                   const VtuOptions& options, const ElementData& element_data, const Pieces& pieces = {}) {
  const basis::Space& space = geometry.space();
  if (options.samples < 2) {
    throw InputError("write_vtu: samples must be at least 2, got " + std::to_string(options.samples));
  }
  check_element_data(space, element_data);
  const std::array<SamplePattern, 2> patterns = {quad_pattern(options.samples), triangle_pattern(options.samples)};
  const auto pattern_of = [&](Index e) -> const SamplePattern& {
    return patterns[space.kind(e).shape == basis::Shape::Triangle ? 1 : 0];
  };

  // Sizes up front, so every array is allocated once.
  const Index num_elements = space.num_elements();
  Index total_points = 0, total_cells = 0, total_connectivity = 0;
  for (Index e = 0; e < num_elements; ++e) {
    const SamplePattern& p = pattern_of(e);
    total_points += p.num_points();
    total_cells += p.num_cells();
    total_connectivity += static_cast<Index>(p.cells.size());
  }
  const bool with_u = sample != nullptr, with_exact = static_cast<bool>(options.exact);
  SampleArrays a;
  a.x = make_double_array("Points", 3, total_points);
  if (with_u) a.u = make_double_array("u", 1, total_points);
  if (with_u && with_grad) a.grad = make_double_array("grad_u", 3, total_points);
  if (with_exact) a.exact = make_double_array("exact", 1, total_points);
  if (with_exact && with_u) a.error = make_double_array("error", 1, total_points);
  for (const SampledField& f : options.fields) {
    if (f.components < 1 || !f.values) throw InputError("write_vtu: field '" + f.name + "' is empty");
    a.fields.push_back(make_double_array(f.name.c_str(), f.components, total_points));
  }

  vtkNew<vtkIdTypeArray> offsets;
  offsets->SetNumberOfTuples(static_cast<vtkIdType>(total_cells + 1));
  vtkNew<vtkIdTypeArray> connectivity;
  connectivity->SetNumberOfTuples(static_cast<vtkIdType>(total_connectivity));
  vtkNew<vtkUnsignedCharArray> cell_types;
  cell_types->SetNumberOfTuples(static_cast<vtkIdType>(total_cells));
  std::vector<Index> element_of_cell;
  element_of_cell.reserve(static_cast<std::size_t>(total_cells));

  vtkIdType point_base = 0, conn_pos = 0;
  offsets->SetValue(0, 0);
  for (Index e = 0; e < num_elements; ++e) {
    const SamplePattern& p = pattern_of(e);
    sample_element(e, geometry, p, sample, options, point_base, a);
    for (Index c = 0; c < p.num_cells(); ++c) {
      for (int k = 0; k < p.cell_size; ++k) {
        connectivity->SetValue(conn_pos++, point_base + p.cells[static_cast<std::size_t>(c * p.cell_size + k)]);
      }
      cell_types->SetValue(static_cast<vtkIdType>(element_of_cell.size()), p.vtk_type);
      element_of_cell.push_back(e);
      offsets->SetValue(static_cast<vtkIdType>(element_of_cell.size()), conn_pos);
    }
    point_base += static_cast<vtkIdType>(p.num_points());
  }

  vtkNew<vtkPoints> points;
  points->SetData(a.x);
  vtkNew<vtkCellArray> cells;
  cells->SetData(offsets, connectivity);
  vtkNew<vtkUnstructuredGrid> grid;
  grid->SetPoints(points);
  grid->SetCells(cell_types, cells);
  for (const auto& array : {a.u, a.grad, a.exact, a.error}) {
    if (array != nullptr) grid->GetPointData()->AddArray(array);
  }
  for (const auto& array : a.fields) grid->GetPointData()->AddArray(array);
  if (with_u) grid->GetPointData()->SetActiveScalars("u");
  if (a.grad != nullptr) grid->GetPointData()->SetActiveVectors("grad_u");
  add_element_cell_data(grid, space, element_of_cell, element_data);
  write_vtk_grid(path, grid, pieces);
}

}  // namespace

bool fields_moved(const basis::Space& space, Index e, int derivatives) {
  return derivatives >= 2 && !space.polynomial_degree(e) && !space.rational_form(e);
}

Eigen::Matrix2Xd field_points(const basis::Space& space, Index e, const Eigen::Matrix2Xd& at, int derivatives) {
  if (!fields_moved(space, e, derivatives)) return at;
  const Eigen::Vector2d centre =
      space.kind(e).shape == basis::Shape::Triangle ? Eigen::Vector2d(1.0 / 3, 1.0 / 3) : Eigen::Vector2d(0.5, 0.5);
  constexpr double kInside = 1e-6;
  return (at.colwise() - centre) * (1 - kInside) + centre.replicate(1, at.cols());
}

Eigen::Matrix2Xd sample_points(basis::Shape shape, int samples) {
  if (samples < 2) throw InputError("write_vtu: samples must be at least 2, got " + std::to_string(samples));
  return (shape == basis::Shape::Triangle ? triangle_pattern(samples) : quad_pattern(samples)).points;
}

void write_vtu(const std::string& path, const basis::Geometry& geometry, const Eigen::VectorXd& u,
               const VtuOptions& options, const ElementData& element_data, const Pieces& pieces) {
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
  write_samples(path, geometry, &sample, true, options, element_data, pieces);
}

void write_vtu(const std::string& path, const basis::Geometry& geometry, const ElementField& field,
               const VtuOptions& options, const ElementData& element_data) {
  const Sampler sample = [&](Index e, const Eigen::Matrix2Xd& ref, const basis::BasisValues&,
                             const basis::GeometryValues& gv, Eigen::VectorXd& values, Eigen::Matrix3Xd*) {
    values.resize(ref.cols());
    field(e, ref, gv.x, values);
  };
  write_samples(path, geometry, &sample, false, options, element_data);
}

void write_vtu(const std::string& path, const basis::Geometry& geometry, const VtuOptions& options,
               const ElementData& element_data, const Pieces& pieces) {
  write_samples(path, geometry, nullptr, false, options, element_data, pieces);
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
