#pragma once
// B-spline geometries built in code or read from a structured quad control net.
#include <Eigen/Core>

#include "basis/bspline/tensor_space.hpp"
#include "basis/geometry.hpp"
#include "mesh/poly_mesh.hpp"

namespace iga::basis::bspline {

/// Geometry over TensorSpace(u, v) with control points (nu*nv) × dim, index i + nu*j.
Geometry make_patch(KnotVector u, KnotVector v, Eigen::MatrixXd control_points);

/// The quarter annulus r_inner <= r <= r_outer in the first quadrant, exactly, as a single NURBS (rational
/// Bézier) patch of degree (p, p), p >= 2: u runs radially (linear), v along the arcs, each the rational quadratic
/// quarter circle (control points (1,0), (1,1), (0,1) scaled by r, weights 1, 1/√2, 1) raised to degree p in
/// homogeneous coordinates, so every p >= 2 represents the same domain and refinements are nested. The arcs are
/// circles (|x| = r exactly) but not parametrised by arc length. InputError for p < 2.
Geometry make_quarter_annulus(int degree, double r_inner = 1.0, double r_outer = 2.0);

/// The quarter of a square plate [0, L]² with a circular hole of radius R about the origin, exactly, as one NURBS
/// patch of degree (p, p), p >= 2 (the classic domain of Kirsch's problem in IgA; Hughes, Cottrell and Bazilevs
/// 2005 build it from the same two arcs): u runs radially on straight segments from the hole (u0) to the outer
/// sides (u1), v along the hole from θ = 0 (v0, the segment y = 0) to θ = 90° (v1, the segment x = 0). v has a knot
/// of multiplicity p at 1/2, the diagonal x = y: each half is the rational quadratic 45° arc (weights 1, cos 22.5°,
/// 1) raised to degree p, and the outer sides x = L and y = L carry the same weights, so the patch is C0 in the
/// space there and the hole exactly circular. InputError for p < 2 or not 0 < R < L.
Geometry make_plate_with_hole(int degree, double radius = 1.0, double side = 4.0);

/// A cylindrical shell x = (R sin θ, y, R cos θ), θ0 <= θ <= θ1 (radians, θ1 − θ0 in (0, π)), 0 <= y <= L, exactly,
/// as one NURBS patch of degree (p, p), p >= 2: u runs along the arc (the rational quadratic arc, weights 1,
/// cos((θ1 − θ0)/2), 1, raised to degree p), v along the axis. Boundary parts: v0 the arc at y = 0, v1 at y = L,
/// u0 the straight edge at θ0, u1 at θ1. The Scordelis–Lo roof is θ = ±40°, R = 25, L = 50; the pinched cylinder's
/// octant θ in [0, 90°]. InputError for p < 2, R or L not > 0, or the angle range outside (0, π).
Geometry make_cylinder_patch(int degree, double radius, double length, double theta0, double theta1);

/// A zone of the sphere x = R (cos φ cos λ, cos φ sin λ, sin φ), λ0 <= λ <= λ1 (longitude), φ0 <= φ <= φ1
/// (latitude), radians, each range in (0, π) and |φ| <= π/2, exactly, as one NURBS patch of degree (p, p), p >= 2: the
/// surface of revolution of the rational quadratic meridian arc about the z axis (weights the products of the two
/// arcs' weights), u along the parallels (longitude), v along the meridians. Boundary parts: v0 the parallel at φ0,
/// v1 at φ1, u0 the meridian at λ0, u1 at λ1. The pinched hemisphere with an 18° hole is a quarter: λ in [0, 90°],
/// φ in [0, 72°]. InputError for p < 2, R not > 0 or a range outside (0, π) or beyond the poles.
Geometry make_sphere_patch(int degree, double radius, double lambda0, double lambda1, double phi0, double phi1);

/// The rectangle [x0,x1]×[y0,y1] (affine map) as a single Bézier patch of degree (p, p), p >= 1.
Geometry make_rectangle(int degree, double x0 = 0.0, double x1 = 1.0, double y0 = 0.0, double y1 = 1.0);

/// The L-shaped domain [0,2]² minus (1,2]² (area 3, reflex corner (1,1): the domain of data/meshes/l_shape.obj)
/// as one patch of degree (p, p), p >= 1, with a knot of multiplicity p at u = 1/2: two bilinear pieces, exactly
/// represented at every degree, meeting C0 along the segment from the reflex corner (1,1) to (0,0).
/// u ∈ [0, 1/2] maps to the quadrilateral (2,1), (1,1), (0,0), (2,0); u ∈ [1/2, 1] to (1,1), (1,2), (0,2), (0,0).
/// Boundary parts: v0 the inner polyline (2,1)–(1,1)–(1,2) with the reflex corner, u0 the segment
/// (2,1)–(2,0), u1 (1,2)–(0,2), v1 the outer polyline (2,0)–(0,0)–(0,2).
Geometry make_l_shape(int degree);

/// A B-spline geometry whose control net is a structured quad grid (a topological rectangle of
/// nu × nv vertices): degree p in both directions on open uniform knot vectors with nu - p and nv - p
/// intervals. u runs along the boundary from a corner with the mesh on its left, v across it.
/// Planar meshes (all z = 0) give a 2D geometry, others a surface in 3D. InputError naming what is wrong
/// when the mesh is not such a grid (non-quad face, holes, interior valence != 4, ...) or has fewer than
/// p+1 vertices in a direction. `name` is used in messages (the file name).
Geometry geometry_from_quad_grid(const mesh::PolyMesh& mesh, int degree, const std::string& name = "mesh");

}  // namespace iga::basis::bspline
