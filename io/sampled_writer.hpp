#pragma once
// Output of data sampled at points rather than given by a Space, for ParaView (VTK XML unstructured grids):
// curves as polyline cells (the boundary with the BEM's u and q on it) and planar point grids as quads.
#include <Eigen/Core>
#include <string>
#include <utility>
#include <vector>

#include "core/types.hpp"

namespace iga::io {

/// Cell c is a VTK_POLY_LINE through points offsets[c] .. offsets[c + 1] − 1 (offsets has cells + 1 entries,
/// starting at 0 and ending at points.cols()). Points are planar (written with z = 0). Point data: scalars
/// (one value per point) and 2D vectors (written with z = 0); cell data: one value per cell.
struct CurveData {
  Eigen::Matrix2Xd points;
  std::vector<Index> offsets{0};
  std::vector<std::pair<std::string, Eigen::VectorXd>> point_scalars;
  std::vector<std::pair<std::string, Eigen::Matrix2Xd>> point_vectors;
  std::vector<std::pair<std::string, Eigen::VectorXd>> cell_scalars;
};

/// InputError when the offsets or an array's size do not match, or (path, 0, "cannot write file") when VTK's
/// writer fails.
void write_curves_vtu(const std::string& path, const CurveData& curves);

/// A planar grid of nx × ny points (point (i, j) is column i + nx j of points), written as (nx − 1)(ny − 1)
/// VTK_QUAD cells, with point data.
struct GridData {
  Index nx = 0, ny = 0;
  Eigen::Matrix2Xd points;
  std::vector<std::pair<std::string, Eigen::VectorXd>> point_scalars;
};
/// InputError when nx, ny < 2 or a size does not match; (path, 0, "cannot write file") when VTK fails.
void write_grid_vtu(const std::string& path, const GridData& grid);

}  // namespace iga::io
