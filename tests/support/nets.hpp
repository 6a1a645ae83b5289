#pragma once
// Small geometries shared by tests: the regular m × m quad net of the unit square, and a distorted B-spline
// square (a non-affine map).
#include <random>
#include <vector>

#include "basis/bspline/patches.hpp"
#include "basis/bspline/tensor_space.hpp"
#include "mesh/poly_mesh.hpp"
#include "refine/uniform.hpp"

namespace iga::test {

/// (m+1)² vertices at (i/m, j/m), m² counter-clockwise quads.
inline mesh::PolyMesh square_grid(int m) {
  std::vector<Eigen::Vector3d> p;
  for (int j = 0; j <= m; ++j)
    for (int i = 0; i <= m; ++i) p.emplace_back(double(i) / m, double(j) / m, 0.0);
  std::vector<std::vector<Index>> f;
  const int n = m + 1;
  for (int j = 0; j < m; ++j)
    for (int i = 0; i < m; ++i) f.push_back({j * n + i, j * n + i + 1, (j + 1) * n + i + 1, (j + 1) * n + i});
  return mesh::PolyMesh::build(p, f);
}

/// A 4×4-element degree-p square [0,1]² whose interior control points are moved by up to 0.04: a non-affine map.
inline basis::Geometry distorted_square(int p, unsigned seed) {
  const basis::Geometry g = refine::refine_uniform(basis::bspline::make_rectangle(p), 2).geometry;
  const auto& s = dynamic_cast<const basis::bspline::TensorSpace&>(g.space());
  Eigen::MatrixXd cp = g.control_points();
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> d(-0.04, 0.04);
  for (Index j = 1; j + 1 < s.num_basis_v(); ++j) {
    for (Index i = 1; i + 1 < s.num_basis_u(); ++i) {
      cp(i + s.num_basis_u() * j, 0) += d(rng);
      cp(i + s.num_basis_u() * j, 1) += d(rng);
    }
  }
  return basis::Geometry(g.space_ptr(), cp);
}

}  // namespace iga::test
