#pragma once
// Shared helpers of the half-box tests: closed three-valent nets (duals of triangulated tori, optionally with
// edge flips that make pentagon/heptagon pairs), random control points, and evaluation of a patch of a net.
#include <Eigen/Core>
#include <cmath>
#include <map>
#include <numbers>
#include <random>
#include <utility>
#include <vector>

#include "basis/basis_values.hpp"
#include "basis/half_box/irregular_patch.hpp"
#include "basis/half_box/patch_net.hpp"
#include "mesh/poly_mesh.hpp"

namespace half_box_test {

using iga::Index;

// Dual of a closed oriented triangle mesh: one net vertex per triangle (at the centroid of `pos`), one face per
// triangle-mesh vertex (its triangles counter-clockwise).
inline iga::mesh::PolyMesh dual_net(const std::vector<Eigen::Vector3d>& pos, const std::vector<std::array<Index, 3>>& tris) {
  std::map<std::pair<Index, Index>, Index> edge_tri;  // directed edge → triangle
  std::vector<Eigen::Vector3d> points;
  for (std::size_t t = 0; t < tris.size(); ++t) {
    const auto& c = tris[t];
    for (int i = 0; i < 3; ++i) edge_tri[{c[static_cast<std::size_t>(i)], c[static_cast<std::size_t>((i + 1) % 3)]}] = static_cast<Index>(t);
    points.push_back((pos[static_cast<std::size_t>(c[0])] + pos[static_cast<std::size_t>(c[1])] + pos[static_cast<std::size_t>(c[2])]) / 3.0);
  }
  std::vector<std::vector<Index>> faces(pos.size());
  std::vector<bool> done(pos.size(), false);
  for (std::size_t t0 = 0; t0 < tris.size(); ++t0)
    for (int i = 0; i < 3; ++i) {
      const Index p = tris[t0][static_cast<std::size_t>(i)];
      if (done[static_cast<std::size_t>(p)]) continue;
      done[static_cast<std::size_t>(p)] = true;
      Index t = static_cast<Index>(t0);
      do {
        faces[static_cast<std::size_t>(p)].push_back(t);
        const auto& c = tris[static_cast<std::size_t>(t)];
        int j = 0;
        while (c[static_cast<std::size_t>(j)] != p) ++j;
        const Index b = c[static_cast<std::size_t>((j + 2) % 3)];  // triangle (p, a, b): next one holds p → b
        t = edge_tri.at({p, b});
      } while (t != static_cast<Index>(t0));
    }
  return iga::mesh::PolyMesh::build(std::move(points), std::move(faces));
}

// m × m triangulated torus (radii 3 and 1), with `flips` edge flips spread out (each makes two pentagons and
// two heptagons in the dual), points perturbed by `noise` (fixed seed).
inline iga::mesh::PolyMesh torus_net(int m, int flips, double noise, unsigned seed = 7) {
  std::vector<Eigen::Vector3d> pos;
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> d(-noise, noise);
  for (int j = 0; j < m; ++j)
    for (int i = 0; i < m; ++i) {
      const double a = 2 * std::numbers::pi * i / m, b = 2 * std::numbers::pi * j / m;
      pos.emplace_back((3 + std::cos(b)) * std::cos(a) + d(rng), (3 + std::cos(b)) * std::sin(a) + d(rng), std::sin(b) + d(rng));
    }
  auto id = [m](int i, int j) { return static_cast<Index>(((j % m + m) % m) * m + ((i % m + m) % m)); };
  std::vector<std::array<Index, 3>> tris;
  for (int j = 0; j < m; ++j)
    for (int i = 0; i < m; ++i) {
      tris.push_back({id(i, j), id(i + 1, j), id(i, j + 1)});
      tris.push_back({id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)});
    }
  for (int f = 0; f < flips; ++f) {
    // Flip the diagonal of square (i, j): (a,b,c) = (i+1,j),(i+1,j+1),(i,j+1) and (i,j),(i+1,j),(i,j+1).
    const int i = (f * m) / std::max(flips, 1) + 1, j = (f * m) / std::max(flips, 1) + m / 2;
    const std::size_t t = static_cast<std::size_t>(2 * (((j % m) * m) + (i % m)));
    const Index p00 = id(i, j), p10 = id(i + 1, j), p11 = id(i + 1, j + 1), p01 = id(i, j + 1);
    tris[t] = {p00, p10, p11};
    tris[t + 1] = {p00, p11, p01};
  }
  return dual_net(pos, tris);
}

// Evaluates the patch p of `net` at uv: positions (3 × q) and, if asked, d/du and d/dv (3 × q each).
struct PatchEval {
  Eigen::Matrix3Xd x, du, dv;
};
inline PatchEval eval_patch(const iga::mesh::PolyMesh& net, const iga::basis::half_box::PatchNet& p,
                            const Eigen::Matrix2Xd& uv, int derivatives = 1) {
  iga::basis::BasisValues b;
  iga::basis::half_box::evaluate_patch(p.valence, uv, derivatives, b);
  Eigen::Matrix3Xd c(3, static_cast<Index>(p.points.size()));
  for (std::size_t i = 0; i < p.points.size(); ++i) c.col(static_cast<Index>(i)) = net.point(p.points[i]);
  PatchEval e;
  e.x = c * b.value;
  if (derivatives >= 1) {
    e.du = c * b.du;
    e.dv = c * b.dv;
  }
  return e;
}

// Random points of the reference triangle (fixed seed).
inline Eigen::Matrix2Xd random_triangle_points(int q, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> d(0.0, 1.0);
  Eigen::Matrix2Xd uv(2, q);
  for (int i = 0; i < q; ++i) {
    double u = d(rng), v = d(rng);
    if (u + v > 1) { u = 1 - u; v = 1 - v; }
    uv(0, i) = u;
    uv(1, i) = v;
  }
  return uv;
}

}  // namespace half_box_test
