#pragma once
// Corner vertices of the clamped Catmull–Clark boundary: a boundary vertex the limit domain keeps as a true corner.
//
// With the clamped rule (ghost_net.hpp) a boundary vertex with k >= 2 faces is an interior extraordinary vertex of
// valence n = k + 2 of the extended net, and the domain is k of its n sectors. Near it the limit map is
//   x = l + λ^m (c1 χ1 + c2 χ2) + o(λ^m)   (Stam 1998; eigen_structure.hpp),
// l = w0 · P the limit point, c_i = w_i · P with w1, w2 the dual vectors of the subdominant pair, χ the
// characteristic map, which sends the edge k of the vertex to the ray at angle θ_k = 2πk/n. So the boundary leaves
// the limit point along the two boundary edges' tangents t_k = cos θ_k c1 + sin θ_k c2, and the corner's angle is
// the one between them: the k sectors of the characteristic map (2πk/n) under the linear map (c1, c2). The ghost
// positions of ghost_net.hpp give a limit point off the vertex and an angle set by the valence (216° at a reflex
// corner with three faces, in the characteristic map); the space does not depend on them (only the geometry does).
//
// A corner vertex v gets the limit point at its own position and the tangents along its two boundary edges of the
// net: four linear conditions (l = v; t_a × (a − v) = 0, t_b × (b − v) = 0 for its boundary neighbours a, b) on the
// geometry's control points of v and of its ghost neighbour v' (the vertex across v, 2 v − mean(w) before), solved
// exactly; then t_a · (a − v) > 0 and t_b · (b − v) > 0 are required (else the conditions have no solution with the
// right orientation). The limit domain then has an interior angle at v equal to the net's polygon angle there (270°
// at an L-shape's reflex corner), tangent to its edges; the boundary near v is curved at second order (it is the
// limit of the extended net's edge curves, not the net's segments). Planar nets only.
//
// Which corners exist: with k >= 3 faces the domain is k of the k + 2 sectors of the characteristic map (216° for
// k = 3), a reflex wedge that the linear map (c1, c2) keeps reflex, so the corner must be reflex (any angle in
// (180°, 360°)); with k = 2 the vertex is a regular point of the extended net, where the map is a local
// diffeomorphism and the boundary smooth: no corner; with k = 1 it is a convex corner of the clamped rule already.
#include <span>
#include <string>

#include "core/types.hpp"

namespace iga::basis {
class Geometry;
}

namespace iga::basis::catmull_clark {

/// The geometry of a clamped Catmull–Clark space (make_catmull_clark_geometry, no global step) with the control
/// points of each corner vertex and its ghost moved as above. `corners`: 0-based vertices of the net; `name` prefixes
/// messages, which number vertices from 1 as the OBJ's f lines do. InputError for a vertex out of range, not on the
/// boundary, with collinear boundary edges, conditions without a solution of the right
/// orientation, or a convex corner with three or more faces; UnsupportedError for a vertex with two faces, the natural
/// rule, a net that needed a global step, or a surface (3D) net.
/// A vertex with one face is a corner of the clamped rule already (interpolated, tangent to its edges): unchanged.
Geometry with_corners(const Geometry& geometry, std::span<const Index> corners, const std::string& name);

}  // namespace iga::basis::catmull_clark
