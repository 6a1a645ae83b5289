#pragma once
// A planar domain must be bounded by simple closed curves and covered once (issue 38, classes 2 and 3): a net that
// winds over itself (a spiral over part of an annulus) has a domain measure larger than the area it covers, and a
// net with a slit or crack (two boundary sides along the same curve) imposes boundary data inside the domain. Both
// are refused; a crack is not a supported feature (model it as a geometry whose boundary goes around it with a
// gap, or solve on each side).
//
// The test, on the boundary sides of the space (Space::boundary_edges(), each sampled at kSamples + 1 points) and
// first on a net's own boundary polygon: the boundary must not meet itself: two segments that are not neighbours
// closer than 1e-9 of the domain's diameter (a slit, a crack, a touching or crossing boundary: a net wound over
// itself crosses its own boundary), or two neighbours that turn back onto each other (a cusp: the tip of a slit).
// Sampled, so a limit boundary that meets itself only between samples of a side (closer than the sag of a 1/16
// chord) is seen only when it crosses. A local diffeomorphism (no fold: fold_certificate.hpp) of a disk whose
// boundary curve is simple is one to one, so for nets of disk topology these two tests together exclude overlap.
#include <string>

#include "basis/geometry.hpp"
#include "mesh/poly_mesh.hpp"

namespace iga::basis {

/// For a planar geometry, the message naming where its boundary meets itself ("the boundary meets itself at
/// (0.5, 0.25) (element 3 side 1 and element 0 side 3): a slit, a crack or a net that overlaps itself ..."), or ""
/// (also for surfaces).
std::string boundary_overlap(const Geometry& geometry);

/// The same test on a planar control net's own boundary polygon (OBJ numbering: vertices and faces from 1, with the
/// face's line): a crack or slit of the net, whatever a backend would make of it (polyhedral splines would match
/// its two sides as an interior edge).
std::string net_boundary_overlap(const mesh::PolyMesh& net);

}  // namespace iga::basis
