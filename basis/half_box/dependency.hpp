#pragma once
// Global linear dependence of half-box splines. A regular patch has 13 blending functions for the 10-dim space
// of cubics (thesis §3.2.3: half-box patches are overcomplete by 3); one combination of the local kernels is
// global: on a net whose vertices can be coloured with two colours so that neighbours differ (a bipartite net:
// every face has an even number of vertices), c = ±1 by colour gives Σ c_i φ_i ≡ 0 on every regular patch
// (each BB coefficient of Figure 2.24 takes as much from one colour as from the other). Nets of hexagons only
// (tori, planar hexagonal regions) have this dependency; an odd face breaks it, and an even EF patch may.
#include <Eigen/Core>
#include <vector>

#include "mesh/poly_mesh.hpp"

namespace iga::basis::half_box {

/// One patch as the dependency check needs it: its valence (6 = regular) and its control points (net vertex
/// indices, patch_net.hpp order).
struct PatchPoints {
  int valence = 6;
  const std::vector<Index>* points = nullptr;
};

/// c over the net's vertices (±1 by colour, 0 on vertices of no patch) when the net is bipartite and
/// Σ_i c_i φ_i vanishes on every patch (regular patches: exactly by the BB matrix; EF patches: at sample
/// points to 1e-12); an empty vector otherwise.
Eigen::VectorXd alternating_dependency(const mesh::PolyMesh& net, const std::vector<PatchPoints>& patches);

}  // namespace iga::basis::half_box
