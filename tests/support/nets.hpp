#pragma once
// Small geometries shared by tests: the regular m × m quad net of the unit square, a closed fan around an
// interior extraordinary vertex, and a distorted B-spline square (a non-affine map).
#include <cmath>
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

/// A fan of `sectors` sectors of k × k quads around vertex 0, its spokes of length `radius` at the angles
/// angle · t / sectors: closed (angle 2π, the last spoke is the first; vertex 0 an interior EV of valence `sectors`)
/// or open (vertex 0 a boundary vertex with `sectors` faces and interior angle `angle`). Vertices: 0, the spokes'
/// points outward spoke by spoke, then each sector's inner points.
inline mesh::PolyMesh fan(int sectors, double angle, bool closed, int k, double radius) {
  const int n = sectors;
  std::vector<Eigen::Vector3d> p{Eigen::Vector3d::Zero()};
  auto dir = [&](int t) { return Eigen::Vector3d(radius * std::cos(angle * t / n), radius * std::sin(angle * t / n), 0.0); };
  const int spokes = closed ? n : n + 1;
  std::vector<std::vector<Index>> spoke(static_cast<std::size_t>(spokes), std::vector<Index>(static_cast<std::size_t>(k + 1), 0));
  for (int t = 0; t < spokes; ++t) {
    for (int i = 1; i <= k; ++i) {
      spoke[static_cast<std::size_t>(t)][static_cast<std::size_t>(i)] = static_cast<Index>(p.size());
      p.push_back(dir(t) * i / k);
    }
  }
  std::vector<std::vector<Index>> faces;
  for (int s = 0; s < n; ++s) {
    std::vector<std::vector<Index>> id(static_cast<std::size_t>(k + 1), std::vector<Index>(static_cast<std::size_t>(k + 1)));
    for (int i = 0; i <= k; ++i) {
      for (int j = 0; j <= k; ++j) {
        Index v;
        if (j == 0) v = spoke[static_cast<std::size_t>(s)][static_cast<std::size_t>(i)];
        else if (i == 0) v = spoke[static_cast<std::size_t>((s + 1) % spokes)][static_cast<std::size_t>(j)];
        else {
          v = static_cast<Index>(p.size());
          p.push_back((dir(s) * i + dir(s + 1) * j) / k);
        }
        id[static_cast<std::size_t>(i)][static_cast<std::size_t>(j)] = v;
      }
    }
    for (int i = 0; i < k; ++i)
      for (int j = 0; j < k; ++j)
        faces.push_back({id[static_cast<std::size_t>(i)][static_cast<std::size_t>(j)], id[static_cast<std::size_t>(i + 1)][static_cast<std::size_t>(j)],
                         id[static_cast<std::size_t>(i + 1)][static_cast<std::size_t>(j + 1)], id[static_cast<std::size_t>(i)][static_cast<std::size_t>(j + 1)]});
  }
  return mesh::PolyMesh::build(p, faces);
}

/// A closed fan of n sectors of k × k quads around vertex 0, an interior EV of valence n, its spokes of length
/// `radius`; the boundary has corners (the sectors' outer corners) and smooth boundary vertices only. With k = 1
/// the EV's faces reach the boundary.
inline mesh::PolyMesh closed_fan(int n, int k, double radius = 1.0) { return fan(n, 2 * M_PI, true, k, radius); }

/// An open fan of `faces` sectors of 2 × 2 quads around vertex 0, a boundary vertex with that many faces and interior
/// angle `angle`, its boundary spokes along the angles 0 and `angle`.
inline mesh::PolyMesh open_fan(int faces, double angle, double radius = 1.0) { return fan(faces, angle, false, 2, radius); }

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
