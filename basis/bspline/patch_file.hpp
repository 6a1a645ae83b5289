#pragma once
// iga's JSON patch format: one B-spline or NURBS patch with its knots, control points and (optional) weights.
#include <string>

#include "basis/geometry.hpp"

namespace iga::basis::bspline {

/// The format (README, "Patch files"):
///   {
///     "format": "iga-patch", "version": 1,
///     "degree": [p_u, p_v],
///     "knots": [[u_0, ..., u_{m-1}], [v_0, ..., v_{k-1}]],   open (clamped) knot vectors
///     "control_points": [[x, y], ...] or [[x, y, z], ...],   n_u n_v rows, u fastest: index i + n_u j
///     "weights": [w_0, ...]                                  optional: n_u n_v positive numbers (NURBS)
///   }
/// with n_u = m − p_u − 1 and n_v = k − p_v − 1. Planar patches (two coordinates) are 2D domains, three
/// coordinates a surface. Without "weights" the patch is a (non-rational) B-spline patch; with them, every weight
/// 1 included, a NURBS patch. Unknown keys are refused (a misspelt "weight" must not give a polynomial patch).

/// The geometry of a patch file; InputError "<name>: <what is wrong>" (JSON syntax errors with their line and
/// column, keys, sizes and values with their JSON path, e.g. "weights[4] is -1: weights must be positive").
Geometry parse_patch(const std::string& text, const std::string& name);
/// parse_patch of a file's contents; InputError naming the file when it cannot be read.
Geometry read_patch(const std::string& path);

/// The patch file text of a B-spline or NURBS geometry (weights written for NURBS only); UnsupportedError for
/// another backend's space. Coordinates with 17 significant digits, so reading gives the same numbers back.
std::string patch_text(const Geometry& geometry);
/// patch_text written to a file; InputError naming the file when it cannot be written.
void write_patch(const std::string& path, const Geometry& geometry);

/// Whether a --geometry value names a patch file rather than a built-in geometry (it ends in ".json").
bool is_patch_file(const std::string& geometry);

}  // namespace iga::basis::bspline
