#pragma once
// Whether a space's functions are in H² (C1): what fourth-order problems (the biharmonic equation, the Kirchhoff–Love
// shell) ask of a space before anything is assembled.
#include <string>

#include "basis/geometry.hpp"

namespace iga::fem {

/// Every element of degree >= 2 and no interior edge with C0 continuity (a repeated interior knot, a C0 patch
/// interface). InputError "<problem>: element N has degree d: its functions are not in H² (<equation> needs a C1 space
/// of degree >= 2)" or "<problem>: the space is only C0 across the side shared by elements N and M (midpoint (x, y)):
/// <equation> needs a C1 space (degree >= 2, no repeated interior knot)", elements numbered from 0 as in the
/// geometry's messages and the .vtu's "element" cell data. Returns the line
/// for a report: "C1 across all N interior edges", or, for a backend that lists no interior edges (polyhedral
/// splines, C1 by construction), that it was not checked edge by edge.
std::string check_c1(const basis::Geometry& geometry, const std::string& problem, const std::string& equation);

}  // namespace iga::fem
