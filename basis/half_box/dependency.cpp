#include "basis/half_box/dependency.hpp"

#include <queue>

#include "basis/basis_values.hpp"
#include "basis/half_box/irregular_patch.hpp"
#include "basis/half_box/regular_patch.hpp"

namespace iga::basis::half_box {
namespace {

// ±1 by a two-colouring of the net's edge graph (breadth first); empty when an edge joins equal colours.
Eigen::VectorXd two_colouring(const mesh::PolyMesh& net) {
  std::vector<std::vector<Index>> neighbours(static_cast<std::size_t>(net.num_vertices()));
  for (Index f = 0; f < net.num_faces(); ++f) {
    const auto face = net.face(f);
    for (std::size_t i = 0; i < face.size(); ++i) {
      const Index a = face[i], b = face[(i + 1) % face.size()];
      neighbours[static_cast<std::size_t>(a)].push_back(b);
      neighbours[static_cast<std::size_t>(b)].push_back(a);
    }
  }
  Eigen::VectorXd colour = Eigen::VectorXd::Zero(net.num_vertices());
  std::queue<Index> open;
  for (Index start = 0; start < net.num_vertices(); ++start) {
    if (colour(start) != 0.0 || neighbours[static_cast<std::size_t>(start)].empty()) continue;
    colour(start) = 1.0;
    open.push(start);
    while (!open.empty()) {
      const Index v = open.front();
      open.pop();
      for (Index w : neighbours[static_cast<std::size_t>(v)]) {
        if (colour(w) == colour(v)) return {};
        if (colour(w) == 0.0) {
          colour(w) = -colour(v);
          open.push(w);
        }
      }
    }
  }
  return colour;
}

}  // namespace

Eigen::VectorXd alternating_dependency(const mesh::PolyMesh& net, const std::vector<PatchPoints>& patches) {
  Eigen::VectorXd c = two_colouring(net);
  if (c.size() == 0) return {};
  Eigen::Matrix2Xd samples(2, 4);
  samples << 0.6, 0.2, 0.1, 0.3, 0.1, 0.5, 0.15, 0.3;  // points in layers 1 and 2 of an EF patch
  BasisValues bv;
  Eigen::VectorXd local;
  for (const PatchPoints& p : patches) {
    local.resize(static_cast<Eigen::Index>(p.points->size()));
    for (std::size_t i = 0; i < p.points->size(); ++i) local(static_cast<Eigen::Index>(i)) = c((*p.points)[i]);
    if (p.valence == 6) {
      if ((bezier_matrix() * local).cwiseAbs().maxCoeff() > 1e-14) return {};
    } else {
      evaluate_irregular(p.valence, samples, 0, bv);
      if ((bv.value.transpose() * local).cwiseAbs().maxCoeff() > 1e-12) return {};
    }
  }
  return c;
}

}  // namespace iga::basis::half_box
