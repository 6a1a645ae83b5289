#include "io/vtk_file.hpp"

#include <vtkCallbackCommand.h>
#include <vtkCommand.h>
#include <vtkDataSet.h>
#include <vtkErrorCode.h>
#include <vtkExecutive.h>
#include <vtkNew.h>
#include <vtkXMLUnstructuredGridWriter.h>

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

}  // namespace iga::io
