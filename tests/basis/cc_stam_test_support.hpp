#pragma once
// Shared pieces of the Stam evaluator tests: an explicit sector mesh around an EV, its one-step Catmull–Clark
// refinement written independently of the library, the bicubic B-spline, random sample points.
#include <Eigen/Core>
#include <array>
#include <cmath>
#include <numbers>
#include <random>
#include <vector>

#include "basis/catmull_clark/stam.hpp"

namespace cc_stam_test {

using iga::basis::BasisValues;
using iga::basis::catmull_clark::stam_evaluator;
using iga::basis::catmull_clark::StamEvaluator;

inline double subdominant(int n) {  // Stam's closed form
  const double c = std::cos(2.0 * std::numbers::pi / n);
  return (5.0 + c + std::cos(std::numbers::pi / n) * std::sqrt(2.0 * (9.0 + c))) / 16.0;
}

// ---- An explicit mesh: n sectors of R×R quads around the EV (vertex 0), sector k spanned by rays k, k+1. ----
struct SectorMesh {
  int n, r;
  std::vector<std::array<int, 4>> quads;
  int num_vertices() const { return 1 + n * r + n * r * r; }
  // Vertex at integer sector coordinates (a, b): a along ray k, b along ray k+1.
  int id(int k, int a, int b) const {
    k = ((k % n) + n) % n;
    if (a == 0 && b == 0) return 0;
    if (b == 0) return 1 + k * r + (a - 1);
    if (a == 0) return id(k + 1, b, 0);
    return 1 + n * r + k * r * r + (a - 1) + r * (b - 1);
  }
  SectorMesh(int valence, int rings) : n(valence), r(rings) {
    for (int k = 0; k < n; ++k) {
      for (int b = 0; b < r; ++b) {
        for (int a = 0; a < r; ++a)
          quads.push_back({id(k, a, b), id(k, a + 1, b), id(k, a + 1, b + 1), id(k, a, b + 1)});
      }
    }
  }
  // Element grid coordinates in doubled units (2i, 2j) -> (sector, doubled sector coordinates).
  std::array<int, 3> sector_of(int x2, int y2) const {
    if (y2 < 0) return {n - 1, -y2, x2};
    if (x2 < 0) return {1, y2, -x2};
    return {0, x2, y2};
  }
  int vertex_at(int i, int j) const {
    const auto [k, a, b] = sector_of(2 * i, 2 * j);
    return id(k, a / 2, b / 2);
  }
};

// The contract's local ordering, written out independently of the library (grid names of 2n+1 .. 2n+7).
inline std::vector<int> local_vertices(const SectorMesh& m) {
  std::vector<int> ids = {0};
  for (int k = 0; k < m.n; ++k) {
    ids.push_back(m.id(k, 1, 0));
    ids.push_back(m.id(k, 1, 1));
  }
  for (auto [i, j] : std::vector<std::array<int, 2>>{{2, -1}, {2, 0}, {2, 1}, {2, 2}, {1, 2}, {0, 2}, {-1, 2}}) {
    ids.push_back(m.vertex_at(i, j));
  }
  return ids;
}

// One Catmull–Clark step (§3.2.2) on the whole mesh, interior entities only. Face point: centroid; edge point:
// (v_a + v_b + F_1 + F_2) / 4; vertex point: (F + 2R + (m − 3) V) / m with F the mean of the new face points
// and R the mean of the edge MIDPOINTS (Catmull & Clark 1978; this gives (3.45) a_n = 1 − 7/(4n), b_n =
// 3/(2n²), c_n = 1/(4n²) and the bicubic B-spline rule 9/16, 3/32, 1/64 for m = 4. Taking R as the mean of
// the edge neighbours themselves would not reproduce either).
struct Refined {
  std::vector<Eigen::Vector3d> face, vertex;
  std::map<std::pair<int, int>, Eigen::Vector3d> edge;
};
inline Refined catmull_clark_step(const SectorMesh& m, const Eigen::Matrix3Xd& x) {
  Refined out;
  std::map<std::pair<int, int>, std::vector<int>> edge_faces;
  std::vector<std::vector<int>> vertex_faces(static_cast<std::size_t>(m.num_vertices()));
  std::vector<std::set<int>> neighbours(static_cast<std::size_t>(m.num_vertices()));
  for (std::size_t f = 0; f < m.quads.size(); ++f) {
    const auto& q = m.quads[f];
    Eigen::Vector3d c = Eigen::Vector3d::Zero();
    for (int i = 0; i < 4; ++i) {
      c += 0.25 * x.col(q[static_cast<std::size_t>(i)]);
      const int a = q[static_cast<std::size_t>(i)], b = q[static_cast<std::size_t>((i + 1) % 4)];
      edge_faces[{std::min(a, b), std::max(a, b)}].push_back(static_cast<int>(f));
      vertex_faces[static_cast<std::size_t>(a)].push_back(static_cast<int>(f));
      neighbours[static_cast<std::size_t>(a)].insert(b);
      neighbours[static_cast<std::size_t>(b)].insert(a);
    }
    out.face.push_back(c);
  }
  for (const auto& [e, faces] : edge_faces) {
    if (faces.size() != 2) continue;
    out.edge[e] = 0.25 * (x.col(e.first) + x.col(e.second) + out.face[static_cast<std::size_t>(faces[0])] +
                          out.face[static_cast<std::size_t>(faces[1])]);
  }
  out.vertex.assign(static_cast<std::size_t>(m.num_vertices()), Eigen::Vector3d::Constant(NAN));
  for (int v = 0; v < m.num_vertices(); ++v) {
    const auto& faces = vertex_faces[static_cast<std::size_t>(v)];
    const auto& nb = neighbours[static_cast<std::size_t>(v)];
    if (faces.size() != nb.size()) continue;  // boundary
    const double valence = static_cast<double>(faces.size());
    Eigen::Vector3d f = Eigen::Vector3d::Zero(), r = Eigen::Vector3d::Zero();
    for (int face : faces) f += out.face[static_cast<std::size_t>(face)] / valence;
    for (int u : nb) r += 0.5 * (x.col(v) + x.col(u)) / valence;
    out.vertex[static_cast<std::size_t>(v)] = (f + 2.0 * r + (valence - 3.0) * x.col(v)) / valence;
  }
  return out;
}

// The new point at level-1 element grid coordinates (i, j), looked up in the refined mesh.
inline Eigen::Vector3d refined_point(const SectorMesh& m, const Refined& ref, int i, int j) {
  const auto [k, a, b] = m.sector_of(i, j);
  const int a0 = a / 2, b0 = b / 2;
  if (a % 2 == 0 && b % 2 == 0) return ref.vertex[static_cast<std::size_t>(m.id(k, a0, b0))];
  if (a % 2 == 1 && b % 2 == 1) return ref.face[static_cast<std::size_t>(k * m.r * m.r + a0 + m.r * b0)];
  const int p = m.id(k, a0, b0), q = (a % 2 == 1) ? m.id(k, a0 + 1, b0) : m.id(k, a0, b0 + 1);
  return ref.edge.at({std::min(p, q), std::max(p, q)});
}

// Uniform cubic cardinal B-spline centred at 0 and its first two derivatives (closed form).
template <typename T = double>
inline std::array<T, 3> cardinal(T x) {
  const T ax = std::abs(x), sg = x < 0 ? T(-1) : T(1);
  if (ax < 1) return {(4 - 6 * ax * ax + 3 * ax * ax * ax) / 6, sg * (-2 * ax + T(1.5) * ax * ax), -2 + 3 * ax};
  if (ax < 2) return {(2 - ax) * (2 - ax) * (2 - ax) / 6, -sg * (2 - ax) * (2 - ax) / 2, 2 - ax};
  return {0, 0, 0};
}

// n = 4 grid coordinates of the 16 local points, as listed in the contract.
constexpr std::array<std::array<int, 2>, 16> kRegularGrid = {{{0, 0},
                                                              {1, 0},
                                                              {1, 1},
                                                              {0, 1},
                                                              {-1, 1},
                                                              {-1, 0},
                                                              {-1, -1},
                                                              {0, -1},
                                                              {1, -1},
                                                              {2, -1},
                                                              {2, 0},
                                                              {2, 1},
                                                              {2, 2},
                                                              {1, 2},
                                                              {0, 2},
                                                              {-1, 2}}};

// Random points in [0,1]^2: uniform, log-uniform towards the EV down to 1e-12, and tiny ones ~ 1e-12.
inline Eigen::Matrix2Xd sample_points(std::mt19937& rng, int count) {
  std::uniform_real_distribution<double> unit(0.0, 1.0), decade(0.0, 12.0);
  Eigen::Matrix2Xd pts(2, count);
  for (int p = 0; p < count; ++p) {
    const double scale = p % 5 < 3 ? 1.0 : (p % 5 == 3 ? std::pow(10.0, -decade(rng)) : 1e-12);
    pts.col(p) << scale * unit(rng), scale * unit(rng);
  }
  return pts;
}

inline double max_abs(const Eigen::MatrixXd& m) { return m.size() ? m.cwiseAbs().maxCoeff() : 0.0; }

// ---- 1. Eigen-structure ----

}  // namespace cc_stam_test
