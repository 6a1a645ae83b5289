#pragma once
// Writing a VTK data set to a file with VTK's XML writers, errors as one InputError naming the path (shared by
// the .vtu writers of io/).
#include <string>
#include <vector>

class vtkDataSet;

namespace iga::io {

/// A distributed run's output: rank `rank` of `ranks` writes the cells of the elements it owns
/// (element_owner[e] == rank, by the grid's "element" cell array) as its own piece. One rank (ranks <= 1): the
/// whole grid, as one file.
struct Pieces {
  int rank = 0;
  int ranks = 1;
  std::vector<int> element_owner;
};

/// The files of a distributed output written for `path` (X.vtu or X): the summary X.pvtu that ParaView opens,
/// and the piece of rank r, X_r.vtu.
std::string summary_path(const std::string& path);
std::string piece_path(const std::string& path, int rank);

/// Writes an unstructured grid (binary, zlib) to path ("-": standard output). InputError(path, 0, "cannot write file") when VTK fails;
/// VTK's own error output is suppressed.
void write_vtk_grid(const std::string& path, vtkDataSet* grid);
/// With pieces.ranks > 1: this rank's cells to piece_path(path, rank), and on rank 0 the summary
/// summary_path(path) naming every rank's piece and the arrays they hold. Otherwise as above.
void write_vtk_grid(const std::string& path, vtkDataSet* grid, const Pieces& pieces);

}  // namespace iga::io
