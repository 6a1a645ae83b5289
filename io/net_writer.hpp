#pragma once
// The control net of a geometry for ParaView (--net FILE.vtu).
#include <string>

#include "basis/geometry.hpp"
#include "mesh/poly_mesh.hpp"

namespace iga::io {

/// Writes every control point of the geometry as a point with a VTK_VERTEX cell (point data "dof": its dof index;
/// z = 0 for planar geometries) and, when `net` is given, each face of the net whose corners all lie at control
/// points (within 1e-10 of the diagonal of the control points' bounding box) as a VTK_POLYGON through those points
/// (cell data "net_face": the face's index, −1 on the vertex cells). The rule is positional, so it draws the net's
/// faces exactly where the dofs are the net's vertices at their positions (Catmull–Clark, polyhedral and half-box
/// geometries built from that net without refinement; polyhedral and half-box keep only the faces whose vertices
/// are all dofs); after refinement or --presubdivide only the points are written. InputError(path, 0, "cannot write
/// file") when VTK fails.
void write_control_net_vtu(const std::string& path, const basis::Geometry& geometry, const mesh::PolyMesh* net);

}  // namespace iga::io
