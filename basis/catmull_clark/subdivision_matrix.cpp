#include "basis/catmull_clark/subdivision_matrix.hpp"

#include <algorithm>
#include <array>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/error.hpp"

namespace iga::basis::catmull_clark {
namespace {

// Grid names of the points 2n+1 .. 2n+16 (the last nine exist only after a subdivision step).
constexpr int kGridNames[16][2] = {{2, -1}, {2, 0}, {2, 1}, {2, 2}, {1, 2}, {0, 2}, {-1, 2}, {3, -1},
                                   {3, 0},  {3, 1}, {3, 2}, {3, 3}, {2, 3}, {1, 3}, {0, 3},  {-1, 3}};

using Quad = std::array<int, 4>;

// The quads spanned by the 2n+8 local points, corners counter-clockwise: the n faces around the EV and the
// five regular quads that complete the element's neighbourhood.
std::vector<Quad> local_quads(int n) {
  std::vector<Quad> quads;
  for (int k = 0; k < n; ++k) quads.push_back({0, 2 * k + 1, 2 * k + 2, 2 * ((k + 1) % n) + 1});
  const auto g = [n](int i, int j) { return local_index(n, i, j); };
  quads.push_back({g(1, -1), g(2, -1), g(2, 0), g(1, 0)});
  quads.push_back({g(1, 0), g(2, 0), g(2, 1), g(1, 1)});
  quads.push_back({g(1, 1), g(2, 1), g(2, 2), g(1, 2)});
  quads.push_back({g(0, 1), g(1, 1), g(1, 2), g(0, 2)});
  quads.push_back({g(-1, 1), g(0, 1), g(0, 2), g(-1, 2)});
  return quads;
}

int corner_of(const Quad& q, int v) {
  for (int c = 0; c < 4; ++c) {
    if (q[static_cast<std::size_t>(c)] == v) return c;
  }
  return -1;
}

// One Catmull–Clark step on the local quads, each new point as weights of the old points.
class LocalRules {
 public:
  explicit LocalRules(int n) : n_(n), np_(num_local_points(n)), quads_(local_quads(n)) {}

  // Face point: the centroid of the quad's corners.
  Eigen::RowVectorXd face_point(const Quad& q) const {
    Eigen::RowVectorXd w = Eigen::RowVectorXd::Zero(np_);
    for (int c : q) w(c) += 0.25;
    return w;
  }

  // The quad that has all of a, b, c, d as corners.
  const Quad& quad_with(int a, int b, int c, int d) const {
    for (const Quad& q : quads_) {
      if (corner_of(q, a) >= 0 && corner_of(q, b) >= 0 && corner_of(q, c) >= 0 && corner_of(q, d) >= 0) return q;
    }
    throw std::logic_error("catmull_clark: no local quad with the requested corners");
  }

  // Edge point of the interior edge ab: (a + b + F_1 + F_2) / 4 over the two adjacent face points.
  Eigen::RowVectorXd edge_point(int a, int b) const {
    Eigen::RowVectorXd w = Eigen::RowVectorXd::Zero(np_);
    w(a) += 0.25;
    w(b) += 0.25;
    int faces = 0;
    for (const Quad& q : quads_) {
      const int ca = corner_of(q, a), cb = corner_of(q, b);
      if (ca < 0 || cb < 0 || ((ca - cb + 4) % 4 != 1 && (cb - ca + 4) % 4 != 1)) continue;
      w += 0.25 * face_point(q);
      ++faces;
    }
    if (faces != 2) throw std::logic_error("catmull_clark: local edge is not interior");
    return w;
  }

  // Vertex point of the interior vertex v of valence m: (F + 2R + (m - 3) v) / m, F the mean of the adjacent
  // face points, R the mean of the midpoints of the edges at v (§3.2.2; (3.45) for the EV).
  Eigen::RowVectorXd vertex_point(int v) const {
    std::vector<int> neighbours;
    Eigen::RowVectorXd f = Eigen::RowVectorXd::Zero(np_);
    int m = 0;
    for (const Quad& q : quads_) {
      const int c = corner_of(q, v);
      if (c < 0) continue;
      ++m;
      f += face_point(q);
      for (int side : {1, 3}) {
        const int u = q[static_cast<std::size_t>((c + side) % 4)];
        if (std::find(neighbours.begin(), neighbours.end(), u) == neighbours.end()) neighbours.push_back(u);
      }
    }
    if (m < 3 || static_cast<int>(neighbours.size()) != m) {
      throw std::logic_error("catmull_clark: local vertex is not interior");
    }
    Eigen::RowVectorXd r = Eigen::RowVectorXd::Zero(np_);
    for (int u : neighbours) {
      r(u) += 0.5;
      r(v) += 0.5;
    }
    Eigen::RowVectorXd w = (f / m + 2.0 * r / m) / m;
    w(v) += static_cast<double>(m - 3) / m;
    return w;
  }

  // The new point with (level-1) grid coordinates (i, j): a vertex, edge or face point of the old net by the
  // parity of i and j.
  Eigen::RowVectorXd grid_point(int i, int j) const {
    const auto lo = [](int x) { return (x - (x & 1)) / 2; };  // floor(x / 2)
    const auto hi = [](int x) { return (x + (x & 1)) / 2; };  // ceil(x / 2)
    const auto g = [this](int a, int b) { return local_index(n_, a, b); };
    const bool odd_i = (i & 1) != 0, odd_j = (j & 1) != 0;
    if (!odd_i && !odd_j) return vertex_point(g(i / 2, j / 2));
    if (odd_i && !odd_j) return edge_point(g(lo(i), j / 2), g(hi(i), j / 2));
    if (!odd_i && odd_j) return edge_point(g(i / 2, lo(j)), g(i / 2, hi(j)));
    return face_point(quad_with(g(lo(i), lo(j)), g(hi(i), lo(j)), g(hi(i), hi(j)), g(lo(i), hi(j))));
  }

  const std::vector<Quad>& quads() const { return quads_; }

 private:
  int n_, np_;
  std::vector<Quad> quads_;
};

}  // namespace

void check_valence(int valence) {
  if (valence < kMinValence || valence > kMaxValence) {
    throw InputError("catmull_clark: valence " + std::to_string(valence) + " of an extraordinary vertex is outside " +
                     std::to_string(kMinValence) + ".." + std::to_string(kMaxValence));
  }
}

int num_local_points(int valence) {
  check_valence(valence);
  return 2 * valence + 8;
}

int num_extended_points(int valence) {
  check_valence(valence);
  return 2 * valence + 17;
}

int local_index(int valence, int i, int j) {
  check_valence(valence);
  const int n = valence;
  if (i == 0 && j == 0) return 0;
  if (i == 1 && j == 0) return 1;
  if (i == 1 && j == 1) return 2;
  if (i == 0 && j == 1) return 3;
  if (i == -1 && j == 1) return 4;
  if (i == -1 && j == 0) return 5;
  if (i == 0 && j == -1) return 2 * n - 1;
  if (i == 1 && j == -1) return 2 * n;
  if (i == -1 && j == -1 && n == 4) return 6;
  for (std::size_t r = 0; r < std::size(kGridNames); ++r) {
    if (kGridNames[r][0] == i && kGridNames[r][1] == j) return 2 * n + 1 + static_cast<int>(r);
  }
  throw InputError("catmull_clark: no local point with grid coordinates (" + std::to_string(i) + ", " +
                   std::to_string(j) + ") at valence " + std::to_string(n));
}

Eigen::MatrixXd extended_subdivision_matrix(int valence) {
  check_valence(valence);
  const int n = valence;
  const LocalRules rules(n);
  Eigen::MatrixXd a(num_extended_points(n), num_local_points(n));
  // The one-ring: vertex point of the EV, edge points of its edges, face points of its faces.
  a.row(0) = rules.vertex_point(0);
  for (int k = 0; k < n; ++k) {
    a.row(2 * k + 1) = rules.edge_point(0, 2 * k + 1);
    a.row(2 * k + 2) = rules.face_point(rules.quads()[static_cast<std::size_t>(k)]);
  }
  // The named grid points 2n+1 .. 2n+16 (points at half the old spacing).
  for (std::size_t r = 0; r < std::size(kGridNames); ++r) {
    a.row(2 * n + 1 + static_cast<Eigen::Index>(r)) = rules.grid_point(kGridNames[r][0], kGridNames[r][1]);
  }
  return a;
}

Eigen::MatrixXd subdivision_matrix(int valence) {
  return extended_subdivision_matrix(valence).topRows(num_local_points(valence));
}

Eigen::Vector2i tile_origin(int tile) {
  switch (tile) {
    case 1:
      return {0, -1};
    case 2:
      return {0, 0};
    case 3:
      return {-1, 0};
    default:
      throw InputError("catmull_clark: tile " + std::to_string(tile) + " is not one of 1, 2, 3");
  }
}

Eigen::MatrixXd picking_matrix(int valence, int tile) {
  const Eigen::Vector2i o = tile_origin(tile);
  Eigen::MatrixXd x = Eigen::MatrixXd::Zero(16, num_extended_points(valence));
  for (int b = 0; b < 4; ++b) {
    for (int a = 0; a < 4; ++a) x(a + 4 * b, local_index(valence, o.x() + a, o.y() + b)) = 1.0;
  }
  return x;
}

}  // namespace iga::basis::catmull_clark
