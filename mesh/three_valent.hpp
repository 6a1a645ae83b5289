#pragma once
// Three-valent control nets (every vertex on 3 edges; faces mostly hexagons) made from triangle meshes, the
// input of the half-box spline backend: the geometric dual and the trisection of thesis Appendix B.1.
//
// Boundary convention (the appendix is silent on boundaries; Section 3.2.1 calls "an ordinary boundary ...
// a contiguous set of hexagons at the boundary of a three-valent mesh", whose boundary vertices alternate
// between 2 and 3 edges): an interior vertex of a three-valent net has exactly 3 edges, a boundary vertex 2
// or 3. Both constructions keep the domain's boundary: the net's boundary polygon is the input's boundary
// polygon (every boundary vertex of the input, corners included, at its own position) with the midpoint
// (dual) or the two trisection points (trisection) of every boundary edge inserted. The input's boundary
// vertices get 2 edges in the net, the inserted points 3.
//
// Positions are copied or averaged from the input (same units: physical coordinates); a planar input
// (all z = 0) gives a planar net.
#include <string>

#include "mesh/poly_mesh.hpp"

namespace iga::mesh {

/// Geometric dual (Appendix B.1: "new vertices at the vertex centroids of the triangles ... connects these
/// over the triangle edges"). Net vertex t (t < F) is the vertex centroid (a + b + c) / 3 of triangle t.
/// Face k of the net surrounds input vertex k, counter-clockwise like the input:
///  - interior vertex with k edges: the k-gon of the centroids of its triangles;
///  - boundary vertex with k edges (k - 1 triangles): the (k + 2)-gon midpoint of the outgoing boundary edge,
///    the k - 1 centroids, midpoint of the incoming boundary edge, the vertex itself (a hexagon at a
///    regular boundary vertex, k = 4; a quadrilateral at a corner with one triangle).
/// After the F centroids come, loop by loop along boundary_loops(), for each boundary half-edge its origin
/// (the input vertex, 2 edges in the net) and then its midpoint (3 edges). Counts for a closed input:
/// V' = F, E' = E, F' = V; with B boundary edges: V' = F + 2B, E' = E + 2B, F' = V (Euler characteristic
/// kept). Throws InputError naming the face (1-based) if a face is not a triangle, naming the vertex
/// (1-based) if a vertex is in no triangle or an interior vertex has fewer than 3 edges (its dual face would
/// have fewer than 3 sides).
PolyMesh dual_net(const PolyMesh& triangles);

/// Trisection (Appendix B.1: "trisecting the edges of the triangle mesh, connecting the resulting vertices
/// around the original vertices and adding edges by connecting the pairs of new vertices on each original
/// edge"; topologically dual to one sqrt(3) refinement step): every edge ab gets the points (2a + b) / 3 and
/// (a + 2b) / 3, and every triangle's corners are cut off, leaving a hexagon. Net vertices 2e and 2e + 1 are
/// the points of edge e near its first and its second end, edges numbered in order of their first
/// half-edge (the half-edge with the lower index) and oriented along it; after the 2E edge points come
/// the input's boundary vertices in the order of boundary_loops(). Faces: first face k around input vertex
/// k (interior, k edges: the k-gon of the points near it; boundary, k edges: the (k + 1)-gon of those
/// points closed by the vertex itself), then the hexagon of triangle t as face V + t. Counts for a closed
/// input: V' = 2E, E' = 3E, F' = V + F; with B boundary edges: V' = 2E + B, E' = E + 3F + 2B, F' = V + F
/// (Euler characteristic kept). Throws InputError as dual_net does.
PolyMesh trisect_net(const PolyMesh& triangles);

/// Checks that `net` is a three-valent net in the sense above: an interior vertex has exactly 3 edges, a
/// boundary vertex 2 or 3 (an isolated vertex, 0 edges, fails). Throws
/// InputError(file, 0, "vertex 17 has 4 edges; a half-box net must be three-valent") for the lowest
/// offending vertex, 1-based as in OBJ files; `file` names the net in the message.
void check_three_valent(const PolyMesh& net, const std::string& file);

}  // namespace iga::mesh
