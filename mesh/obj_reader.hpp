#pragma once
// Wavefront OBJ input for polygonal control meshes.
#include <istream>
#include <string>

#include "mesh/poly_mesh.hpp"

namespace iga::mesh {

/// Reads an OBJ file ("-": standard input, named "stdin" in messages). Throws InputError(path, 0, "cannot open file") if it cannot be opened,
/// InputError(path, 0, "cannot read (is a directory)") for a directory, and everything parse_obj throws.
PolyMesh read_obj(const std::string& path);

/// Parses OBJ text; `name` is the file named in error messages ("name:line: reason", 1-based lines).
/// Uses `v x y z [w]` (w and any further numbers ignored) and `f` with the index forms i, i/j, i//k, i/j/k,
/// including negative (relative) indices; a face may only use vertices defined before it. Comments (#),
/// blank lines, tabs, a UTF-8 byte-order mark and LF, CRLF or CR-only line ends (each counted as one line, as
/// an editor does) are accepted; other statements (vt, vn, g, o, s, usemtl, mtllib, l, p, ...) are ignored.
/// Binary data (a control character other than tab, VT, FF and the line ends; DEL) is refused with its line
/// and 1-based column ("binary data (byte 0x00 at column 7)"), UTF-16 text as such, an empty input as
/// "file is empty" (line 0). Throws InputError with the line of the offending statement for malformed numbers,
/// non-finite coordinates, invalid or out-of-range indices, faces with < 3 vertices or a repeated vertex,
/// and for the topology problems PolyMesh::build detects (non-manifold edge or vertex, inconsistent
/// orientation); line 0 when the file has no vertices or no faces. Indices in messages are 1-based.
PolyMesh parse_obj(std::istream& in, const std::string& name);

}  // namespace iga::mesh
