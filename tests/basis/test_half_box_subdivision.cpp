// Half-box subdivision stencils and one global step (basis/half_box/subdivision.hpp). The mask is recomputed
// here by discrete directional convolution on the three-directional grid (thesis Figure 3.7): the indicator
// of a coarse triangle is the sum of its four children, and each convolution with a bisected direction d
// doubles the mask as m + shift(m, d). Lines x, y, x + y ∈ Z; directions (1,0), (0,1), (1,-1).
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <numbers>
#include <tuple>

#include "basis/half_box/local_net.hpp"
#include "basis/half_box/subdivision.hpp"
#include "core/error.hpp"
#include "test_half_box_support.hpp"

namespace {

using namespace iga::basis::half_box;
using iga::Index;
using Tri = std::tuple<bool, int, int>;  // (up?, i, j): U(i,j) = (i,j) + {(0,0),(1,0),(0,1)}, D(i,j) its mirror

// Mask of the coarse control point U(0,0) (up = true) or D(0,0): fine control triangles → coefficient (sum 32).
std::map<Tri, double> mask(bool up) {
  std::map<Tri, double> m;
  if (up) m = {{{true, 0, 0}, 1}, {{true, 1, 0}, 1}, {{true, 0, 1}, 1}, {{false, 0, 0}, 1}};
  else m = {{{false, 1, 0}, 1}, {{false, 0, 1}, 1}, {{false, 1, 1}, 1}, {{true, 1, 1}, 1}};
  const int d[3][2] = {{1, 0}, {0, 1}, {1, -1}};
  for (const auto& s : d) {
    std::map<Tri, double> r = m;
    for (const auto& [t, c] : m) r[{std::get<0>(t), std::get<1>(t) + s[0], std::get<2>(t) + s[1]}] += c;
    m = r;
  }
  // The support of the fine function of triangle ρ is centred on ρ + (1,0), that of the coarse one on
  // U(1,0) (resp. D(1,0)) = the coarse triangle + (1,0) coarse = + (2,0) fine: control triangle ρ − (1,0).
  std::map<Tri, double> c;
  for (const auto& [t, v] : m) c[{std::get<0>(t), std::get<1>(t) - 1, std::get<2>(t)}] = v;
  return c;
}

// Stencil of fine control triangle `fine`: coarse triangle → weight (normalised to sum 1).
std::map<Tri, double> stencil(const Tri& fine) {
  std::map<Tri, double> s;
  double sum = 0;
  for (bool up : {true, false})
    for (const auto& [t, c] : mask(up))
      for (int i = -4; i <= 4; ++i)
        for (int j = -4; j <= 4; ++j)
          if (t == Tri{std::get<0>(t), std::get<1>(fine) - 2 * i, std::get<2>(fine) - 2 * j} && std::get<0>(t) == std::get<0>(fine)) {
            s[{up, i, j}] += c;
            sum += c;
          }
  EXPECT_NEAR(sum, 8.0, 1e-15);  // (3.32): every fine function gets mask weight 8
  for (auto& [t, c] : s) c /= sum;
  return s;
}

TEST(HalfBoxSubdivision, MaskFromConvolutionGivesS1AndS2) {
  double total = 0;
  for (const auto& [t, c] : mask(true)) total += c;
  EXPECT_EQ(total, 32.0);
  // Corner child of U(0,0) at (0,0) (fine U(0,0)) = S1 point of face F0 ((0,0)) at v = U(0,0).
  const std::map<Tri, double> s1{{{true, 0, 0}, 0.5}, {{false, -1, 0}, 0.125}, {{false, 0, -1}, 0.125},
                                 {{true, -1, 0}, 0.125}, {{true, 0, -1}, 0.125}};
  EXPECT_EQ(stencil({true, 0, 0}), s1);  // D(-1,-1), the vertex opposite v in F0, gets 0
  // Middle child (fine D(0,0)) = S2 point of v: 1/4 on v and its three neighbours.
  const std::map<Tri, double> s2{{{true, 0, 0}, 0.25}, {{false, 0, -1}, 0.25}, {{false, 0, 0}, 0.25}, {{false, -1, 0}, 0.25}};
  EXPECT_EQ(stencil({false, 0, 0}), s2);
  // Every fine triangle in a window is an S1 (5 weights) or S2 (4 weights) point.
  for (bool up : {true, false})
    for (int i = -3; i <= 3; ++i)
      for (int j = -3; j <= 3; ++j) {
        const auto s = stencil({up, i, j});
        EXPECT_TRUE(s.size() == 4 || s.size() == 5);
        for (const auto& [t, c] : s) EXPECT_TRUE(c == 0.5 || c == 0.25 || c == 0.125);
      }
  // The library's hexagon S1 has the same weights around the face.
  const std::vector<double> w = s1_weights(6);
  EXPECT_EQ(w, (std::vector<double>{0.5, 0.125, 0.125, 0.0, 0.125, 0.125}));
}

TEST(HalfBoxSubdivision, NgonWeightsFollow337) {
  for (int n = 3; n <= 12; ++n) {
    if (n == 6) continue;
    const std::vector<double> w = s1_weights(n);
    double sum = 0;
    for (double x : w) sum += x;
    EXPECT_NEAR(sum, 1.0, 1e-15);
    EXPECT_NEAR(w[0], 0.25 + 1.25 / n, 1e-16);
    // Spectrum of the face block: Σ_k a^k ω^{kl} = 1, 1/2, 1/4, ..., 1/4, 1/2 (3.36).
    for (int l = 0; l < n; ++l) {
      double re = 0;
      for (int k = 0; k < n; ++k) re += w[static_cast<std::size_t>(k)] * std::cos(2 * std::numbers::pi * k * l / n);
      EXPECT_NEAR(re, l == 0 ? 1.0 : (l == 1 || l == n - 1) ? 0.5 : 0.25, 1e-15);
    }
  }
  EXPECT_THROW(s1_weights(2), iga::InputError);
}

TEST(HalfBoxSubdivision, ClosedNetTopologyAndStencils) {
  const iga::mesh::PolyMesh net = half_box_test::torus_net(8, 1, 0.1);
  const NetSubdivision s = subdivide(net);
  const Index v = net.num_vertices(), e = net.num_half_edges() / 2;
  EXPECT_EQ(s.net.num_vertices(), 4 * v);
  EXPECT_EQ(s.net.num_faces(), net.num_faces() + e);
  EXPECT_TRUE(s.net.is_closed());
  for (Index i = 0; i < s.net.num_vertices(); ++i) EXPECT_EQ(s.net.valence(i), 3);
  // Rows sum to 1, and the points are the prolongation applied to the old points.
  Eigen::MatrixXd old(v, 3);
  for (Index i = 0; i < v; ++i) old.row(i) = net.point(i).transpose();
  const Eigen::MatrixXd nw = s.prolongation * old;
  for (Index i = 0; i < s.net.num_vertices(); ++i) {
    EXPECT_NEAR(s.prolongation.row(i).sum(), 1.0, 1e-15);
    EXPECT_LT((nw.row(i).transpose() - s.net.point(i)).norm(), 1e-14);
  }
  // Face sizes: the shrunk faces keep their size, the rest are hexagons.
  for (Index f = 0; f < s.net.num_faces(); ++f)
    EXPECT_EQ(s.net.face_size(f), f < net.num_faces() ? net.face_size(f) : 6);
}

TEST(HalfBoxSubdivision, Errors) {
  // A cube has three-valent vertices but a boundary once a face is removed.
  std::vector<Eigen::Vector3d> p;
  for (int i = 0; i < 8; ++i) p.emplace_back(i & 1, (i >> 1) & 1, (i >> 2) & 1);
  std::vector<std::vector<Index>> cube{{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  EXPECT_NO_THROW(subdivide(iga::mesh::PolyMesh::build(p, cube)));
  auto open = cube;
  open.pop_back();
  try {
    subdivide(iga::mesh::PolyMesh::build(p, open));
    ADD_FAILURE() << "no error for a boundary";
  } catch (const iga::UnsupportedError& e) {
    EXPECT_NE(std::string(e.what()).find("boundary"), std::string::npos) << e.what();
  }
  // An octahedron is four-valent: vertex 1 is named (1-based).
  std::vector<Eigen::Vector3d> q{{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  std::vector<std::vector<Index>> oct{{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4}, {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}};
  try {
    subdivide(iga::mesh::PolyMesh::build(q, oct));
    ADD_FAILURE() << "no error for valence 4";
  } catch (const iga::InputError& e) {
    EXPECT_EQ(std::string(e.what()), "vertex 1 has 4 edges; half-box nets are three-valent");
  }
}

TEST(HalfBoxSubdivision, LocalNetKeepsItsInterior) {
  const iga::mesh::PolyMesh net = ring_net(5);
  const NetSubdivision s = subdivide_local(net);
  // Every vertex with three edges (v_k0, v_k1) has an S2 point; v_k2, v_k3 (two edges) have none.
  for (Index v = 0; v < net.num_vertices(); ++v) EXPECT_EQ(s.vertex_point[static_cast<std::size_t>(v)] >= 0, v % 4 < 2);
  EXPECT_THROW(subdivide(net), iga::UnsupportedError);
}

}  // namespace
