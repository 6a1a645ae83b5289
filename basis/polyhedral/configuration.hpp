#pragma once
// Classification of a polyhedral control net into the layout configurations of Peters, Lo, Karčiauskas,
// "Bi-cubic splines for polyhedral control nets" (Section 2, list (1)–(7); outputs: Section 3, list (1)–(7)).
//
// Which vertex or face of the net produces which configuration:
//   Regular  an interior 4-valent vertex whose four faces are quads, or an interior 4-valent vertex of the
//            ring around a pole (two consecutive triangles of the fan + two quads)   → 1 patch, degree (2,2)
//   Star     an interior vertex of valence n ∈ {3, 5..8} whose n faces are quads    → n (n = 3, 5) or 4n bi-3
//   NGon     an n-gon face, n ∈ {3, 5..8}, every corner interior and 4-valent, every other face at its
//            corners a quad (the 2n quads)                                           → n (n = 3, 5) or 4n bi-3
//   T0       a triangle with corner valences (5, 4, 4), the 7 other faces at its corners quads  → 4 bi-3
//   T1       a pentagon with corner valences (3, 4, 4, 4, 4), 9 quads around                   → 8 bi-3
//   T2       a hexagon with corner valences (3, 4, 3, 4, 4, 4) in face order, 10 quads around   → 16 bi-3
//   Polar    an interior vertex (the pole) of valence n ∈ 3..8 whose n faces are triangles, each neighbour
//            having exactly the two fan triangles (consecutive) and otherwise quads  → n patches, degree (3,2)
// Global boundary: the outermost layer recedes. A boundary vertex and a face with a boundary corner produce
// no configuration, but inner configurations still gather them. Every other (interior) vertex must be
// covered: as the centre of a Regular/Star/Polar configuration, or as a corner of an NGon/T0/T1/T2 face.
// Triangles of a polar fan are covered by the pole. Anything else is unsupported (classify throws) — among
// it an interior corner of a non-quad face that touches the boundary (that face produces no patch, so the
// corner would leave a hole that is not part of the receding outer layer).
//
// Gather orders (faces of the net counter-clockwise; Regular, Star, NGon as in mask.hpp):
//   Regular at a polar ring vertex: a fan triangle (v, a, b) is read as the quad (v, a, P, P) collapsed onto
//     the pole P, i.e. e_k = a and f_k = P (so the entries around the pole read e_k = a, f_k = P and, for the
//     triangle (v, P, b), e_{k+1} = P, f_{k+1} = P).
//   Polar (pole P, n triangles (P, q_k, q_{k+1})):  [P, q_0, …, q_{n−1}]  (n + 1 vertices), q_k counter-
//     clockwise; patch k covers triangle (P, q_k, q_{k+1}).
//   Face configurations are described by the face's corners s_0, …, s_{m−1} in face order and its ring:
//     A_k, the quad across edge s_k s_{k+1}, reads (s_k, x_k, y_k, s_{k+1}) in its own order, so x_k is s_k's
//     neighbour and y_k is s_{k+1}'s neighbour outside the face; d_k is the vertex opposite s_k in the one quad
//     that touches the face only at s_k (4-valent corners). (NGon in mask.hpp: r_k = y_{k−1}, p_k = x_k.)
//   T0 (triangle, s_0 the 5-valent corner; 14 vertices), picture with s_0 = 4, s_1 = 7, s_2 = 8:
//        0 - 1 - 2          [0] g_2  [1] g_1  [2] g_0  [3] x_0  [4] s_0  [5] y_2  [6] y_0
//        |   |   |          [7] s_1  [8] s_2  [9] x_2  [10] d_1 [11] x_1 [12] y_1 [13] d_2
//        3 - 4 - 5          where g_0, g_1, g_2 are the vertices of the two quads at s_0 between A_2 and A_0,
//       /   / \   \         in counter-clockwise order around s_0 from y_2 to x_0 (g_1 is the shared
//      6 - 7 - 8 - 9        neighbour of s_0, g_0 and g_2 are opposite s_0).
//      |   |   |   |
//     10 -11 -12 - 13
//   T1 (pentagon, s_0 the 3-valent corner; 18 vertices), picture with (s_0..s_4) = (10, 9, 5, 6, 11):
//        0 - 1 - 2 - 3      [0] d_2  [1] x_2  [2] y_2  [3] d_3  [4] y_1  [5] s_2  [6] s_3  [7] x_3
//        |   |   |   |      [8] x_1  [9] s_1  [10] s_0 [11] s_4 [12] y_3 [13] d_1 [14] y_0 [15] x_0 (= y_4)
//        4 - 5 - 6 - 7      [16] x_4 [17] d_4
//       /   /     \   \     .
//      8 - 9 -10- 11 - 12
//      |   |   |   |   |
//     13 -14 -15- 16 - 17
//   T2 (hexagon, s_0 and s_2 the 3-valent corners; 20 vertices), picture with (s_0..s_5) = (9,11,12,13,6,5):
//      0 - 1 ------ 2 - 3   [0] d_5  [1] y_4  [2] x_4  [3] d_4  [4] x_5  [5] s_5  [6] s_4  [7] y_3
//      |   |        |   |   [8] x_0 (= y_5)  [9] s_0  [10] y_0  [11] s_1  [12] s_2  [13] s_3  [14] x_3
//      4 - 5 ------ 6 - 7   [15] d_1 [16] x_1 [17] x_2 (= y_1)  [18] y_2  [19] d_3
//      |   |        |   |
//      8 - 9        |   |
//      |   |        |   |
//     10 -11 - 12 - 13 - 14
//      |   |    |    |   |
//     15 -16 - 17 - 18 - 19
//   (These coincide with the column order of the reference implementation's tables, so its mask tables can
//   be compared column by column; the pictures show the layout, mirrored when the net is oriented the other
//   way.)
#include <string>
#include <vector>

#include "basis/polyhedral/mask.hpp"
#include "core/error.hpp"
#include "core/types.hpp"
#include "mesh/poly_mesh.hpp"

namespace iga::basis::polyhedral {

/// One configuration found in the net.
struct ConfigurationSite {
  Configuration type = Configuration::Regular;
  int valence = 4;            ///< Regular 4; Star/Polar: n of the vertex; NGon: n of the face; T0–T2: 0
  bool at_face = false;       ///< centre is a face (NGon, T0, T1, T2) or a vertex (Regular, Star, Polar)
  Index centre = -1;          ///< 0-based vertex or face index
  std::vector<Index> gathered;  ///< 0-based vertex indices in the gather order of `type`
  int num_patches = 1;
  int degree_u = 3;           ///< degree of every patch of the configuration as output by the paper
  int degree_v = 3;
};

/// Number of output patches and their degree for a configuration (paper, Section 3, list (1)–(7)).
int num_patches(Configuration c, int valence);
int patch_degree_u(Configuration c);
int patch_degree_v(Configuration c);
/// Number of gathered vertices (mask columns).
int num_gathered(Configuration c, int valence);
/// The group line the reference writer puts before each patch of the configuration in a .bv file
/// ("Group 0 Regular", "Group 1 ExtraordinaryPoint", "Group 2 T0", "Group 3 T1", "Group 4 T2",
/// "Group 5 Polar", "Group 8 nGon").
std::string bv_group_name(Configuration c);

/// One offending vertex or face of an unsupported net.
struct Offence {
  bool at_face = false;
  Index index = -1;  ///< 0-based
  std::string reason;
};

/// Thrown by classify: names every offending vertex and face (1-based OBJ indices) and what is wrong.
class UnsupportedConfigurationError : public UnsupportedError {
 public:
  explicit UnsupportedConfigurationError(std::vector<Offence> offences);
  const std::vector<Offence>& offences() const { return offences_; }

 private:
  std::vector<Offence> offences_;
};

/// Every configuration of the net: vertex configurations in vertex order, then face configurations in face
/// order. Throws UnsupportedConfigurationError listing each interior vertex that no configuration covers
/// and each non-quad face that is none of the supported ones (with the reason), and suggesting
/// --presubdivide (one Catmull–Clark step makes a net with valences and face sizes <= 8 admissible).
std::vector<ConfigurationSite> classify(const mesh::PolyMesh& net);

/// `steps` uniform Catmull–Clark refinements of the net (basis/catmull_clark/topology.hpp, refine_net).
mesh::PolyMesh presubdivide(const mesh::PolyMesh& net, int steps);

}  // namespace iga::basis::polyhedral
