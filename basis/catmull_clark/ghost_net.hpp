#pragma once
// The clamped boundary of the Catmull–Clark backend as one ring of ghost faces: the control net extended
// across its boundary, Catmull–Clark's interior rules everywhere inside the extension, and the space
// restricted to the original faces.
//
// Why this is the clamped space: on a part of the boundary where the net is a regular grid, the bicubic
// patches of the domain faces are then the uniform B-splines of the extended grid restricted to the domain,
// i.e. in the normal direction the spline space on [0, m] with knots 0, 1, ..., m and no condition at 0: the
// open knot vector 0,0,0,0,1,2,...,m-1,m,m,m,m (a cubic spline on [0, m] restricted from the line has full
// freedom at the end). The ghost basis is the uniform B-spline basis of that space, not the end-interpolating
// one; the space is the same (tests/basis/test_cc_clamped.cpp compares it with the B-spline backend). The old
// rule ("natural": phantom 2 P_b − P_in) is the subspace with u_nn = 0 on the boundary.
// A boundary vertex with k faces becomes an interior vertex of valence k + 2 (a corner, k = 1: three ghost
// vertices, valence 4), so boundary extraordinary vertices are interior ones of the extended net: Stam's
// evaluation, its eigen-structure and the C1 of Catmull–Clark limit surfaces at interior EVs (Peters–Reif)
// apply to the domain, which is k of the k + 2 sectors.
//
// Ghost positions: across a boundary vertex v with interior neighbours w_1..w_r (r >= 1) the ghost is
// 2 v − mean(w); at a corner c with boundary neighbours a (before c along the boundary) and b (after) and
// opposite vertex d: 2 c − b across the incoming edge, 2 c − a across the outgoing one, 4 c − 2 a − 2 b + d on
// the diagonal. These are the phantom points of the natural rule, so on regular boundary parts the geometry
// (and with it the domain) is the natural rule's: the boundary curve there is the uniform cubic B-spline of
// the boundary polygon with interpolated corners. At a boundary EV the boundary is the limit of the two edge
// curves of an interior EV of the extended net: smooth (C1 as curves) on both sides, meeting at the EV's
// limit point at the angle the ghost positions give (not in general the cubic B-spline of the polygon).
#include <Eigen/Sparse>
#include <string>

#include "mesh/poly_mesh.hpp"

namespace iga::basis::catmull_clark {

/// A net with one ring of ghost faces: faces [0, domain_faces) are the domain, the others the ghosts. From
/// extend_net the domain faces are the net's faces and the first vertices the net's, both in order.
struct ExtendedNet {
  mesh::PolyMesh mesh;
  Index domain_faces = 0;
};

/// The net extended by one ring of ghost faces (a quad per boundary edge and one more per corner). Source
/// lines of the net's vertices and faces are kept (ghosts: 0). InputError (prefixed by name) for a net with
/// no boundary.
ExtendedNet extend_net(const mesh::PolyMesh& net, const std::string& name);

/// `steps` uniform Catmull–Clark refinements of an extended net (refine_net: OpenSubdiv), each trimmed to the
/// domain's children and the ghost faces that share a vertex with them (the next one ring). Face and vertex
/// order are OpenSubdiv's with the trimmed ones removed: an n-gon's n children are consecutive, so the domain
/// stays first and the children of a quad domain face f are faces 4f + k when the domain is all quads. Trimming loses nothing: every point a domain face's patch or
/// its subdivision reads lies in its one ring. P (fine kept vertices × coarse vertices) = the rows of the
/// refinement's prolongation of the kept vertices.
struct ExtendedRefinement {
  ExtendedNet net;
  Eigen::SparseMatrix<double> prolongation;
};
ExtendedRefinement refine_extended(const ExtendedNet& net, int steps);

}  // namespace iga::basis::catmull_clark
