#pragma once
// Uniform Catmull–Clark refinement of a control net through OpenSubdiv (topology and stencils), with the
// prolongation matrix between the nets.
#include <Eigen/Sparse>

#include "mesh/poly_mesh.hpp"

namespace iga::basis::catmull_clark {

/// A refined net and P (fine vertices × coarse vertices): fine positions = P · coarse positions.
struct NetRefinement {
  mesh::PolyMesh mesh;
  Eigen::SparseMatrix<double> prolongation;
};

/// `steps` (0..10) uniform Catmull–Clark refinements of `mesh` with OpenSubdiv's Far::TopologyRefiner
/// (scheme Catmark, VTX_BOUNDARY_EDGE_AND_CORNER: boundary = cubic B-spline of the boundary polygon, vertices
/// with one face are corners). Vertex and face order are OpenSubdiv's. Faces: the children of a face are
/// consecutive in the parent's order (quads of an all-quad net: children of f are 4f + k); child k is the
/// quarter at the parent's corner k, its vertex j at (c_k + c_j) / 2 in the parent's coordinates (c_j =
/// (0,0), (1,0), (1,1), (0,1) for the parent's vertex j), i.e. child coordinates (a, b) are parent coordinates
/// (c_k + (a, b)) / 2 (tests/basis/test_cc_refine.cpp, ChildOrdering). P is assembled from OpenSubdiv's
/// stencil table (duplicate entries accumulated). Throws InputError for steps out of range or an isolated
/// vertex (named).
NetRefinement refine_net(const mesh::PolyMesh& mesh, int steps);

/// Throws InputError naming the first vertex that no face uses.
void check_no_isolated_vertices(const mesh::PolyMesh& mesh, const std::string& name);

}  // namespace iga::basis::catmull_clark
