#include "basis/half_box/local_net.hpp"

#include <cmath>
#include <numbers>
#include <string>

#include "core/error.hpp"

namespace iga::basis::half_box {

mesh::PolyMesh ring_net(int n) {
  if (n < 3) throw InputError("half-box ring_net: an n-gon needs n >= 3, got " + std::to_string(n));
  const double step = 2.0 * std::numbers::pi / n;
  auto polar = [](double r, double a) { return Eigen::Vector3d(r * std::cos(a), r * std::sin(a), 0.0); };
  std::vector<Eigen::Vector3d> points;
  for (int k = 0; k < n; ++k) {
    points.push_back(polar(1.0, k * step));
    points.push_back(polar(2.0, k * step));
    points.push_back(polar(2.8, (k - 0.25) * step));
    points.push_back(polar(2.8, (k + 0.25) * step));
  }
  auto v = [n](int k, int j) { return static_cast<Index>(4 * ((k % n + n) % n) + j); };
  std::vector<std::vector<Index>> faces;
  std::vector<Index> ngon;
  for (int k = 0; k < n; ++k) ngon.push_back(v(k, 0));
  faces.push_back(ngon);
  for (int k = 0; k < n; ++k) faces.push_back({v(k, 0), v(k - 1, 0), v(k - 1, 1), v(k - 1, 3), v(k, 2), v(k, 1)});
  return mesh::PolyMesh::build(std::move(points), std::move(faces));
}

Index half_edge_of(const mesh::PolyMesh& net, Index face, Index vertex) {
  const Index h0 = net.face_half_edge(face);
  for (Index i = 0; i < net.face_size(face); ++i)
    if (net.half_edge(h0 + i).origin == vertex) return h0 + i;
  throw InputError("face " + std::to_string(face + 1) + " does not contain vertex " + std::to_string(vertex + 1));
}

}  // namespace iga::basis::half_box
