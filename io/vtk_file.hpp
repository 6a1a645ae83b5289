#pragma once
// Writing a VTK data set to a file with VTK's XML writers, errors as one InputError naming the path (shared by
// the .vtu writers of io/).
#include <string>

class vtkDataSet;

namespace iga::io {

/// Writes an unstructured grid (binary, zlib) to path ("-": standard output). InputError(path, 0, "cannot write file") when VTK fails;
/// VTK's own error output is suppressed.
void write_vtk_grid(const std::string& path, vtkDataSet* grid);

}  // namespace iga::io
