#pragma once
// BezierView (.bv) files: tensor-product Bézier patches for the SurfLab viewer (BezierView, "bview").
//
// Format (SurfLab's BezierView page, cise.ufl.edu/research/SurfLab/bview): a sequence of segments, each a
// patch header followed by its data.
//   [Group <id> <name>]     optional line; applies to the patches that follow (the polyhedral-spline writer
//                           repeats it before every patch)
//   5                       kind 5: tensor-product patch with degrees (deg_u, deg_v)
//   deg_u deg_v             (kind 4: one line "deg" for deg_u = deg_v = deg)
//   x y z                   (deg_u+1)(deg_v+1) control points, row-major with rows = u index:
//   …                       p(0,0) p(0,1) … p(0,deg_v) p(1,0) … p(deg_u,deg_v)
//
//   3                       kind 3: total-degree (triangular) Bézier patch of degree d
//   d
//   x y z                   (d+1)(d+2)/2 control points "with row-ascending ordering"; the page's cubic example
//   …                       numbers them           9
//                                                 7 8
//                                                4 5 6
//                                               0 1 2 3
//   i.e. the bottom row (d+1 points) first, then rows of d, d−1, …, 1 points. The page names no barycentric
//   indices; this module reads the picture as the reference triangle {u, v >= 0, u + v <= 1} with point 0 at
//   (0,0), point d at (1,0) and the last point at (0,1) (counter-clockwise, so the normal is du × dv): the
//   point in row k, position j is b_ijk with i = d − j − k, the coefficient of λ0^i λ1^j λ2^k (λ0 = 1 − u − v,
//   λ1 = u, λ2 = v), file index triangle_index(d, j, k).
// This module writes kinds 3 and 5 and reads kinds 3, 4 and 5 (others, e.g. 1 polyhedron, 8 rational, are
// rejected by name).
#include <Eigen/Core>
#include <istream>
#include <ostream>
#include <string>
#include <vector>

namespace iga::io {

struct BvPatch {
  std::string group;  ///< the whole group line ("Group 0 Regular"), empty for none
  /// Kind 3: a triangular patch of degree degree_u (degree_v is ignored on writing and set to degree_u on
  /// reading); points are (d+1)(d+2)/2 × 3 in the file's order, b_ijk in row triangle_index(d, j, k).
  bool triangle = false;
  int degree_u = 3;
  int degree_v = 3;
  /// Tensor patches: ((degree_u+1)(degree_v+1)) × 3; BB coefficient b_ij (i along u) is row
  /// j·(degree_u+1)+i, as in basis/polyhedral (the file's u-major order is translated on reading and writing).
  Eigen::MatrixXd points;
};

/// Row of b_ijk (i = d − j − k) of a triangular patch of degree d: row k of the file's triangle, position j,
/// i.e. k(d+1) − k(k−1)/2 + j.
constexpr int triangle_index(int degree, int j, int k) { return k * (degree + 1) - k * (k - 1) / 2 + j; }
/// (d+1)(d+2)/2.
constexpr int triangle_size(int degree) { return (degree + 1) * (degree + 2) / 2; }

/// Writes kind-5 (tensor) and kind-3 (triangle) patches, each preceded by its group line when it has one;
/// coordinates with 17 significant digits (exact round trip). Throws InputError for a patch whose point count
/// does not fit its degrees (or triangle degree) or whose points are not 3D, and InputError(path, 0, "cannot
/// write file") when the file cannot be written.
void write_bv(const std::string& path, const std::vector<BvPatch>& patches);
void write_bv(std::ostream& out, const std::vector<BvPatch>& patches);

/// Reads every patch of a .bv file. Throws InputError(path, 0, "cannot open file") and everything parse_bv
/// throws.
std::vector<BvPatch> read_bv(const std::string& path);

/// Parses .bv text; `name` is the file named in messages. Blank lines are skipped. Throws
/// InputError(name, line, reason) for an unknown or unsupported kind, a malformed degree line (degrees must
/// be 1..30; kind 3 has one degree), a control point line that is not three finite numbers, extra tokens on a line, and a patch cut
/// off by the end of the file (line = the last line).
std::vector<BvPatch> parse_bv(std::istream& in, const std::string& name);

}  // namespace iga::io
