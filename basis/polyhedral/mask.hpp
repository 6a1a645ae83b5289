#pragma once
// Polyhedral bi-3 splines (Peters, Lo, Karčiauskas, "Bi-cubic splines for polyhedral control nets"):
// the shared vocabulary of the configuration classifier (which control-net vertices a configuration gathers,
// in which order) and the mask derivation (the BB-coefficients of the configuration's output patches as
// linear combinations of the gathered vertices).
//
// Gather orders (faces of the net are oriented counter-clockwise seen from outside / from +z):
//   Regular (4-valent vertex v, four quads) and Star (vertex v of valence n = 3, 5..8, n quads):
//     [v, e_0, f_0, e_1, f_1, …, e_{n−1}, f_{n−1}]  (2n + 1 vertices)
//     e_k are v's edge neighbours, counter-clockwise; f_k is the vertex opposite v in the quad
//     (v, e_k, f_k, e_{k+1}) (indices mod n), whose vertex order in the net is exactly that one.
//   NGon (face F = (c_0, …, c_{n−1}), n = 3, 5..8, counter-clockwise; every c_k 4-valent; 2n quads around F):
//     [c_0, …, c_{n−1}, r_0, d_0, p_0, r_1, d_1, p_1, …, r_{n−1}, d_{n−1}, p_{n−1}]  (4n vertices)
//     A_k is the quad on edge c_k c_{k+1}, B_k the quad that touches F only at c_k;
//     r_k: c_k's neighbour outside F on quad A_{k−1}; p_k: c_k's neighbour outside F on quad A_k;
//     d_k: the vertex of B_k opposite c_k.
//   Polar, T0, T1, T2: documented next to their classifier (configuration.hpp).
//
// Patch layout of a mask: patch k of a Star/NGon cap covers sector k (Star: the quad (v, e_k, f_k, e_{k+1});
// NGon: the corner of F at c_k); with 4n patches (n >= 6) sector k is split into 4 patches (2 × 2), listed
// sector by sector, each sector row-major in (u, v). Within a patch, u runs along the first named direction,
// v along the second, counter-clockwise: Star: (0,0) at v, u toward e_k, v toward e_{k+1}; NGon: (0,0) at
// the centre of F, u toward the midpoint of edge c_{k−1}c_k, v toward the midpoint of c_k c_{k+1}, (1,1) at
// the centroid of B_k. BB coefficient b_ij (i along u, j along v) is row  j·(degree_u + 1) + i  of
// PatchMask::coefficients.
#include <string>
#include <vector>

#include <Eigen/Core>

namespace iga::basis::polyhedral {

enum class Configuration { Regular, Star, NGon, Polar, T0, T1, T2 };

std::string to_string(Configuration c);

/// One output patch in Bernstein–Bézier form: its (degree_u+1)(degree_v+1) BB coefficients as rows of
/// `coefficients`, each a linear combination of the configuration's gathered vertices (columns).
struct PatchMask {
  int degree_u = 3;
  int degree_v = 3;
  Eigen::MatrixXd coefficients;  ///< ((degree_u+1)(degree_v+1)) × gathered
};

/// The extraction operator of one configuration and valence: every output patch.
struct ConfigurationMask {
  Configuration configuration = Configuration::Regular;
  int valence = 4;          ///< n (Regular: 4; T0–T2: 0)
  int gathered = 0;         ///< number of gathered control-net vertices (columns of every patch)
  std::vector<PatchMask> patches;
};

}  // namespace iga::basis::polyhedral
