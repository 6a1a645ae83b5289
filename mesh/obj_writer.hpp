#pragma once
// Wavefront OBJ output for polygonal control meshes.
#include <ostream>
#include <string>

#include "mesh/poly_mesh.hpp"

namespace iga::mesh {

/// Writes `v x y z` lines (shortest text that reads back to exactly the same double) and 1-based `f` lines,
/// all vertices (isolated ones too) and faces in mesh order, so parse_obj(write_obj(mesh)) reproduces the
/// mesh exactly. Throws InputError if the stream fails.
void write_obj(const PolyMesh& mesh, std::ostream& out);

/// Writes to a file; throws InputError(path, 0, "cannot write file") if it cannot be created or written.
void write_obj(const PolyMesh& mesh, const std::string& path);

}  // namespace iga::mesh
