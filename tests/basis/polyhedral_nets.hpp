#pragma once
// Small control nets with one polyhedral configuration each, built in code for the polyhedral tests, and the
// location of the reference data (../shared/reference/polyhedral next to the repository, or
// $IGA_POLYHEDRAL_REFERENCE), which tests read only and skip without.
#include "support/paths.hpp"
#include <Eigen/Core>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <random>
#include <vector>

#include "mesh/poly_mesh.hpp"

namespace polyhedral_nets {
using iga::Index;
namespace mesh = iga::mesh;


inline std::filesystem::path reference_dir() {
  if (const char* env = std::getenv("IGA_POLYHEDRAL_REFERENCE")) return env;
  return std::filesystem::path(IGA_SOURCE_DIR) / ".." / "shared" / "reference" / "polyhedral";
}

inline double jitter(std::mt19937& rng, double a) { return std::uniform_real_distribution<double>(-a, a)(rng); }

/// Star of valence n: centre 0; sector t (between spokes t and t+1, counter-clockwise) is a 2 × 2 grid of quads
/// P_t(i, j), i, j = 0..2, with P_t(0,0) = centre, P_t(i,0) on spoke t, P_t(0,j) on spoke t+1. Vertex order:
/// centre, then spoke t points (t·2 + 1, t·2 + 2) for i = 1, 2, then the sector points. z is jittered.
inline mesh::PolyMesh star_net(int n, unsigned seed = 1, bool planar = false) {
  std::mt19937 rng(seed);
  std::vector<Eigen::Vector3d> p{Eigen::Vector3d(0, 0, planar ? 0.0 : jitter(rng, 0.2))};
  const double a = 2.0 * M_PI / n;
  auto dir = [&](double ang) { return Eigen::Vector3d(std::cos(ang), std::sin(ang), 0.0); };
  auto spoke = [&](int t, int i) -> Index { return 1 + 2 * ((t % n + n) % n) + (i - 1); };
  for (int t = 0; t < n; ++t) {
    for (int i = 1; i <= 2; ++i) p.push_back(i * dir(a * t) + Eigen::Vector3d(0, 0, planar ? 0.0 : jitter(rng, 0.2)));
  }
  const Index base = static_cast<Index>(p.size());
  auto inner = [&](int t, int i, int j) -> Index { return base + 4 * t + 2 * (i - 1) + (j - 1); };
  for (int t = 0; t < n; ++t) {
    for (int i = 1; i <= 2; ++i) {
      for (int j = 1; j <= 2; ++j) {
        p.push_back(i * dir(a * t) + j * dir(a * (t + 1)) * 0.9 + Eigen::Vector3d(0, 0, planar ? 0.0 : jitter(rng, 0.2)));
      }
    }
  }
  auto P = [&](int t, int i, int j) -> Index {
    if (i == 0 && j == 0) return 0;
    if (j == 0) return spoke(t, i);
    if (i == 0) return spoke(t + 1, j);
    return inner(t, i, j);
  };
  std::vector<std::vector<Index>> faces;
  for (int t = 0; t < n; ++t) {
    for (int i = 0; i < 2; ++i) {
      for (int j = 0; j < 2; ++j) faces.push_back({P(t, i, j), P(t, i + 1, j), P(t, i + 1, j + 1), P(t, i, j + 1)});
    }
  }
  return mesh::PolyMesh::build(std::move(p), std::move(faces));
}

/// n-gon F = (c_0..c_{n-1}) (vertices 0..n-1) with its 2n quads: A_k = (c_{k+1}, c_k, p_k, r_{k+1}),
/// B_k = (c_k, r_k, d_k, p_k); r_k = n + 3k, d_k = n + 3k + 1, p_k = n + 3k + 2 (so the mask.hpp gather order
/// of F is 0, 1, …, 4n − 1 when F's first corner is c_0).
inline mesh::PolyMesh ngon_net(int n, unsigned seed = 2) {
  std::mt19937 rng(seed);
  std::vector<Eigen::Vector3d> p;
  const double a = 2.0 * M_PI / n, delta = 0.25 * a;
  auto at = [&](double r, double ang) { return Eigen::Vector3d(r * std::cos(ang), r * std::sin(ang), jitter(rng, 0.15)); };
  for (int k = 0; k < n; ++k) p.push_back(at(1.0, a * k));
  for (int k = 0; k < n; ++k) {
    p.push_back(at(2.0, a * k - delta));
    p.push_back(at(2.6, a * k));
    p.push_back(at(2.0, a * k + delta));
  }
  auto c = [&](int k) -> Index { return (k % n + n) % n; };
  auto r = [&](int k) -> Index { return n + 3 * c(k); };
  auto d = [&](int k) -> Index { return n + 3 * c(k) + 1; };
  auto pp = [&](int k) -> Index { return n + 3 * c(k) + 2; };
  std::vector<std::vector<Index>> faces;
  std::vector<Index> f;
  for (int k = 0; k < n; ++k) f.push_back(k);
  faces.push_back(f);
  for (int k = 0; k < n; ++k) {
    faces.push_back({c(k + 1), c(k), pp(k), r(k + 1)});
    faces.push_back({c(k), r(k), d(k), pp(k)});
  }
  return mesh::PolyMesh::build(std::move(p), std::move(faces));
}

/// Polar fan: pole 0, ring q_k = 1 + k (interior, 4-valent), outer ring o_k = 1 + n + k (boundary);
/// triangles (P, q_k, q_{k+1}) and quads (q_k, o_k, o_{k+1}, q_{k+1}).
inline mesh::PolyMesh polar_net(int n, unsigned seed = 3) {
  std::mt19937 rng(seed);
  std::vector<Eigen::Vector3d> p{Eigen::Vector3d(0, 0, 1.0 + jitter(rng, 0.1))};
  const double a = 2.0 * M_PI / n;
  for (int r = 1; r <= 2; ++r) {
    for (int k = 0; k < n; ++k) p.push_back(Eigen::Vector3d(r * std::cos(a * k), r * std::sin(a * k), 1.0 - 0.4 * r + jitter(rng, 0.1)));
  }
  std::vector<std::vector<Index>> faces;
  for (int k = 0; k < n; ++k) {
    const Index q0 = 1 + k, q1 = 1 + (k + 1) % n;
    faces.push_back({0, q0, q1});
    faces.push_back({q0, q0 + n, q1 + n, q1});
  }
  return mesh::PolyMesh::build(std::move(p), std::move(faces));
}

/// A net given on an integer grid (x, y) with quads and one special face (vertex indices as listed); faces
/// are re-oriented counter-clockwise in the xy-plane (or clockwise with `mirror`), z jittered.
inline mesh::PolyMesh grid_net(const std::vector<Eigen::Vector2d>& xy, std::vector<std::vector<Index>> faces, bool mirror,
                               unsigned seed) {
  std::mt19937 rng(seed);
  std::vector<Eigen::Vector3d> p;
  for (const auto& q : xy) p.push_back(Eigen::Vector3d(q.x(), q.y(), jitter(rng, 0.1)));
  for (auto& f : faces) {
    double area = 0.0;
    for (std::size_t i = 0; i < f.size(); ++i) {
      const auto& a = xy[static_cast<std::size_t>(f[i])];
      const auto& b = xy[static_cast<std::size_t>(f[(i + 1) % f.size()])];
      area += a.x() * b.y() - a.y() * b.x();
    }
    if ((area < 0) != mirror) std::reverse(f.begin(), f.end());
  }
  return mesh::PolyMesh::build(std::move(p), std::move(faces));
}

/// The T0 picture of configuration.hpp (vertex k at its picture position).
inline mesh::PolyMesh t0_net(bool mirror, unsigned seed = 4) {
  const std::vector<Eigen::Vector2d> xy{{-1, 1},  {0, 1},    {1, 1},   {-1, 0},    {0, 0},  {1, 0},  {-1.5, -1},
                                        {-0.5, -1}, {0.5, -1}, {1.5, -1}, {-1.5, -2}, {-0.5, -2}, {0.5, -2}, {1.5, -2}};
  return grid_net(xy, {{0, 1, 4, 3}, {1, 2, 5, 4}, {3, 4, 7, 6}, {4, 5, 9, 8}, {6, 7, 11, 10}, {7, 8, 12, 11}, {8, 9, 13, 12}, {4, 7, 8}},
                  mirror, seed);
}
inline const std::vector<std::vector<Index>>& t0_picture_quads() {
  static const std::vector<std::vector<Index>> q{{0, 1, 4, 3}, {1, 2, 5, 4}, {3, 4, 7, 6}, {4, 5, 9, 8}, {6, 7, 11, 10}, {7, 8, 12, 11}, {8, 9, 13, 12}};
  return q;
}

inline const std::vector<std::vector<Index>>& t1_picture_quads() {
  static const std::vector<std::vector<Index>> q{{0, 1, 5, 4},   {1, 2, 6, 5},     {2, 3, 7, 6},     {4, 5, 9, 8},  {6, 7, 12, 11},
                                                 {8, 9, 14, 13}, {9, 10, 15, 14}, {10, 11, 16, 15}, {11, 12, 17, 16}};
  return q;
}
inline std::vector<std::vector<Index>> t1_picture_faces() {
  auto f = t1_picture_quads();
  f.push_back({10, 9, 5, 6, 11});
  return f;
}

/// The T1 picture of configuration.hpp.
inline mesh::PolyMesh t1_net(bool mirror, unsigned seed = 5) {
  std::vector<Eigen::Vector2d> xy;
  for (int i = 0; i < 4; ++i) xy.push_back({i - 1.5, 3});
  for (int i = 0; i < 4; ++i) xy.push_back({i - 1.5, 2});
  for (int i = 0; i < 5; ++i) xy.push_back({i - 2.0, 1});
  for (int i = 0; i < 5; ++i) xy.push_back({i - 2.0, 0});
  auto faces = t1_picture_faces();
  return grid_net(xy, faces, mirror, seed);
}
/// The T2 picture of configuration.hpp.
inline const std::vector<std::vector<Index>>& t2_picture_quads() {
  static const std::vector<std::vector<Index>> q{{0, 1, 5, 4},     {1, 2, 6, 5},     {2, 3, 7, 6},     {4, 5, 9, 8},     {6, 7, 14, 13},
                                                 {8, 9, 11, 10},   {10, 11, 16, 15}, {11, 12, 17, 16}, {12, 13, 18, 17}, {13, 14, 19, 18}};
  return q;
}
inline mesh::PolyMesh t2_net(bool mirror, unsigned seed = 6) {
  const std::vector<Eigen::Vector2d> xy{{0, 4}, {1, 4}, {3, 4}, {4, 4}, {0, 3}, {1, 3}, {3, 3}, {4, 3}, {0, 2}, {1, 2},
                                        {0, 1}, {1, 1}, {2, 1}, {3, 1}, {4, 1}, {0, 0}, {1, 0}, {2, 0}, {3, 0}, {4, 0}};
  auto faces = t2_picture_quads();
  faces.push_back({9, 11, 12, 13, 6, 5});
  return grid_net(xy, faces, mirror, seed);
}

/// The same net with z = 0 (the builders above jitter z).
inline mesh::PolyMesh flattened(const mesh::PolyMesh& net) {
  std::vector<Eigen::Vector3d> p = net.points();
  for (auto& x : p) x.z() = 0.0;
  std::vector<std::vector<Index>> faces;
  for (Index f = 0; f < net.num_faces(); ++f) faces.emplace_back(net.face(f).begin(), net.face(f).end());
  return mesh::PolyMesh::build(p, faces);
}

}  // namespace polyhedral_nets
