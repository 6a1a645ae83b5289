#pragma once
// BezierView (.bv) files: tensor-product Bézier patches for the SurfLab viewer (BezierView, "bview").
//
// Format (SurfLab's BezierView page): a sequence of segments, each a patch header followed by its data.
//   [Group <id> <name>]     optional line; applies to the patches that follow (the polyhedral-spline writer
//                           repeats it before every patch)
//   5                       kind 5: tensor-product patch with degrees (deg_u, deg_v)
//   deg_u deg_v             (kind 4: one line "deg" for deg_u = deg_v = deg)
//   x y z                   (deg_u+1)(deg_v+1) control points, row-major with rows = u index:
//   …                       p(0,0) p(0,1) … p(0,deg_v) p(1,0) … p(deg_u,deg_v)
// This module writes kind 5 and reads kinds 4 and 5 (others, e.g. 1 polyhedron, 3 triangle, 8 rational,
// are rejected by name).
#include <Eigen/Core>
#include <istream>
#include <ostream>
#include <string>
#include <vector>

namespace iga::io {

struct BvPatch {
  std::string group;  ///< the whole group line ("Group 0 Regular"), empty for none
  int degree_u = 3;
  int degree_v = 3;
  /// ((degree_u+1)(degree_v+1)) × 3; BB coefficient b_ij (i along u) is row j·(degree_u+1)+i, as in
  /// basis/polyhedral (the file's u-major order is translated on reading and writing).
  Eigen::MatrixXd points;
};

/// Writes kind-5 patches, each preceded by its group line when it has one; coordinates with 17 significant
/// digits (exact round trip). Throws InputError for a patch whose point count does not fit its degrees or
/// whose points are not 3D, and InputError(path, 0, "cannot write file") when the file cannot be written.
void write_bv(const std::string& path, const std::vector<BvPatch>& patches);
void write_bv(std::ostream& out, const std::vector<BvPatch>& patches);

/// Reads every patch of a .bv file. Throws InputError(path, 0, "cannot open file") and everything parse_bv
/// throws.
std::vector<BvPatch> read_bv(const std::string& path);

/// Parses .bv text; `name` is the file named in messages. Blank lines are skipped. Throws
/// InputError(name, line, reason) for an unknown or unsupported kind, a malformed degree line (degrees must
/// be 1..30), a control point line that is not three finite numbers, extra tokens on a line, and a patch cut
/// off by the end of the file (line = the last line).
std::vector<BvPatch> parse_bv(std::istream& in, const std::string& name);

}  // namespace iga::io
