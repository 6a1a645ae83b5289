#include "io/vtk_file.hpp"

#include <vtkCallbackCommand.h>
#include <vtkCommand.h>
#include <vtkDataSet.h>
#include <vtkErrorCode.h>
#include <vtkExecutive.h>
#include <vtkNew.h>
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkExtractCells.h>
#include <vtkIdList.h>
#include <vtkIdTypeArray.h>
#include <vtkIntArray.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPointSet.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLDataElement.h>
#include <vtkXMLUnstructuredGridWriter.h>
#include <vtkXMLUtilities.h>

#include <fstream>

#include "core/error.hpp"
#include "io/report.hpp"

namespace iga::io {

namespace {
void on_vtk_error(vtkObject* /*caller*/, unsigned long /*event*/, void* client_data, void* /*call_data*/) {
  *static_cast<bool*>(client_data) = true;
}
}  // namespace

void write_vtk_grid(const std::string& path, vtkDataSet* grid) {
  // Errors are reported by the exception below; the observers also keep VTK from printing them (the writer
  // reports a file it cannot open, its executive the failed request that follows).
  bool vtk_error = false;
  vtkNew<vtkCallbackCommand> on_error;
  on_error->SetCallback(on_vtk_error);
  on_error->SetClientData(&vtk_error);
  vtkNew<vtkXMLUnstructuredGridWriter> writer;
  writer->AddObserver(vtkCommand::ErrorEvent, on_error);
  writer->GetExecutive()->AddObserver(vtkCommand::ErrorEvent, on_error);
  const bool to_stdout = path == "-";
  if (to_stdout) {
    writer->WriteToOutputStringOn();
  } else {
    writer->SetFileName(path.c_str());
  }
  writer->SetInputData(grid);
  writer->SetDataModeToBinary();
  writer->SetCompressorTypeToZLib();
  const int ok = writer->Write();
  if (ok != 1 || vtk_error || writer->GetErrorCode() != vtkErrorCode::NoError) {
    throw InputError(path, 0, "cannot write file");
  }
  if (to_stdout) write_text("-", writer->GetOutputString());
}

namespace {

std::string stem(const std::string& path) {
  const std::string ext = ".vtu";
  const bool has_ext = path.size() > ext.size() && path.compare(path.size() - ext.size(), ext.size(), ext) == 0;
  return has_ext ? path.substr(0, path.size() - ext.size()) : path;
}

std::string file_name(const std::string& path) {
  const std::size_t slash = path.find_last_of('/');
  return slash == std::string::npos ? path : path.substr(slash + 1);
}

// The XML type name of a VTK array (the names the XML writers use for the types iga's grids hold).
const char* xml_type(int vtk_type) {
  switch (vtk_type) {
    case VTK_DOUBLE: return "Float64";
    case VTK_FLOAT: return "Float32";
    case VTK_INT: return "Int32";
    case VTK_LONG_LONG: return "Int64";
    case VTK_ID_TYPE: return sizeof(vtkIdType) == 8 ? "Int64" : "Int32";
    case VTK_UNSIGNED_CHAR: return "UInt8";
    default: throw InputError("distributed .vtu output: an array of VTK type " + std::to_string(vtk_type) + " has no XML name here");
  }
}

void add_arrays(vtkXMLDataElement* parent, const char* tag, vtkFieldData* data) {
  vtkNew<vtkXMLDataElement> group;
  group->SetName(tag);
  for (int i = 0; i < data->GetNumberOfArrays(); ++i) {
    vtkDataArray* a = vtkDataArray::SafeDownCast(data->GetAbstractArray(i));
    if (!a) continue;
    vtkNew<vtkXMLDataElement> e;
    e->SetName("PDataArray");
    e->SetAttribute("type", xml_type(a->GetDataType()));
    e->SetAttribute("Name", a->GetName());
    e->SetIntAttribute("NumberOfComponents", a->GetNumberOfComponents());
    group->AddNestedElement(e);
  }
  parent->AddNestedElement(group);
}

// The .pvtu summary (ParaView's parallel unstructured grid): the arrays of the pieces, from rank 0's, and the
// pieces' files, relative to the summary's folder. Written as a VTK XML element tree: VTK's own parallel writer
// lists only the pieces its process writes unless it runs under VTK's MPI controller, which Debian's VTK lacks.
void write_summary(const std::string& path, vtkUnstructuredGrid* piece, int ranks) {
  vtkNew<vtkXMLDataElement> root;
  root->SetName("VTKFile");
  root->SetAttribute("type", "PUnstructuredGrid");
  root->SetAttribute("version", "1.0");
  root->SetAttribute("byte_order", "LittleEndian");
  root->SetAttribute("header_type", "UInt64");
  vtkNew<vtkXMLDataElement> grid;
  grid->SetName("PUnstructuredGrid");
  grid->SetIntAttribute("GhostLevel", 0);
  add_arrays(grid, "PPointData", piece->GetPointData());
  add_arrays(grid, "PCellData", piece->GetCellData());
  vtkNew<vtkXMLDataElement> points;
  points->SetName("PPoints");
  vtkNew<vtkXMLDataElement> coordinates;
  coordinates->SetName("PDataArray");
  coordinates->SetAttribute("type", xml_type(piece->GetPoints() ? piece->GetPoints()->GetDataType() : VTK_DOUBLE));
  coordinates->SetIntAttribute("NumberOfComponents", 3);
  points->AddNestedElement(coordinates);
  grid->AddNestedElement(points);
  for (int r = 0; r < ranks; ++r) {
    vtkNew<vtkXMLDataElement> e;
    e->SetName("Piece");
    e->SetAttribute("Source", file_name(piece_path(path, r)).c_str());
    grid->AddNestedElement(e);
  }
  root->AddNestedElement(grid);
  std::ofstream out(summary_path(path));
  vtkXMLUtilities::FlattenElement(root, out);
  out << "\n";
  if (!out) throw InputError(summary_path(path), 0, "cannot write file");
}

}  // namespace

std::string summary_path(const std::string& path) { return stem(path) + ".pvtu"; }

std::string piece_path(const std::string& path, int rank) { return stem(path) + "_" + std::to_string(rank) + ".vtu"; }

void write_vtk_grid(const std::string& path, vtkDataSet* grid, const Pieces& pieces) {
  if (pieces.ranks <= 1) {
    write_vtk_grid(path, grid);
    return;
  }
  if (path == "-") throw InputError("distributed .vtu output: pieces cannot go to standard output");
  auto* element = vtkIdTypeArray::SafeDownCast(grid->GetCellData()->GetArray("element"));
  if (element == nullptr) throw InputError(path, 0, "distributed .vtu output: the grid has no element cell array");
  vtkNew<vtkIdList> mine;
  for (vtkIdType c = 0; c < grid->GetNumberOfCells(); ++c) {
    const auto e = static_cast<std::size_t>(element->GetValue(c));
    if (e < pieces.element_owner.size() && pieces.element_owner[e] == pieces.rank) mine->InsertNextId(c);
  }
  vtkNew<vtkExtractCells> extract;
  extract->SetInputData(grid);
  extract->SetCellList(mine);
  extract->Update();
  vtkUnstructuredGrid* piece = extract->GetOutput();
  piece->GetCellData()->RemoveArray("vtkOriginalCellIds");  // the element array says where each cell comes from
  vtkNew<vtkIntArray> rank;  // for ParaView: colour by the rank that assembled the cell
  rank->SetName("rank");
  rank->SetNumberOfTuples(piece->GetNumberOfCells());
  rank->FillValue(pieces.rank);
  piece->GetCellData()->AddArray(rank);
  write_vtk_grid(piece_path(path, pieces.rank), piece);
  if (pieces.rank == 0) write_summary(path, piece, pieces.ranks);
}

}  // namespace iga::io
