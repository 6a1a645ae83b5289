// Classification of polyhedral control nets (basis/polyhedral/configuration.hpp): hand-built nets of every
// configuration, the reference implementation's input nets (counts derived from their valence statistics and
// the paper's list of outputs; table sizes read from the reference mask tables), unsupported nets, and
// presubdivision.
#include <gtest/gtest.h>

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <random>
#include <vector>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <string>

#include "basis/polyhedral/configuration.hpp"
#include "core/error.hpp"
#include "mesh/obj_reader.hpp"
#include "mesh/poly_mesh.hpp"
#include "basis/polyhedral_nets.hpp"

using namespace polyhedral_nets;

namespace {

using iga::basis::polyhedral::classify;
using iga::basis::polyhedral::Configuration;
using iga::basis::polyhedral::ConfigurationSite;
using iga::basis::polyhedral::presubdivide;
using iga::basis::polyhedral::UnsupportedConfigurationError;

/// A face of m with exactly these vertices in this cyclic order (or the reverse one, with either_way).
bool has_face(const mesh::PolyMesh& m, const std::vector<Index>& verts, bool either_way) {
  const std::size_t n = verts.size();
  for (Index f = 0; f < m.num_faces(); ++f) {
    const auto face = m.face(f);
    if (face.size() != n) continue;
    for (std::size_t r = 0; r < n; ++r) {
      bool fwd = true, bwd = true;
      for (std::size_t i = 0; i < n; ++i) {
        fwd = fwd && face[(r + i) % n] == verts[i];
        bwd = bwd && face[(r + n - i) % n] == verts[i];
      }
      if (fwd || (either_way && bwd)) return true;
    }
  }
  return false;
}

/// The triangle (a, b, c) in this cyclic order, or a quad (v, a, P, P)/(v, P, P, b) collapsed from it.
bool has_quad_or_collapsed(const mesh::PolyMesh& m, const std::vector<Index>& q) {
  if (has_face(m, q, false)) return true;
  std::vector<Index> t;
  for (std::size_t i = 0; i < 4; ++i) {
    if (q[i] != q[(i + 1) % 4]) t.push_back(q[i]);
  }
  return t.size() == 3 && has_face(m, t, false);
}

/// The gather of a site reproduces the layout its gather order documents (configuration.hpp, mask.hpp).
void expect_layout(const mesh::PolyMesh& m, const ConfigurationSite& s) {
  const auto& g = s.gathered;
  ASSERT_EQ(static_cast<int>(g.size()), iga::basis::polyhedral::num_gathered(s.type, s.valence));
  auto picture = [&](const std::vector<std::vector<Index>>& quads, std::vector<Index> special) {
    for (const auto& q : quads) {
      std::vector<Index> v;
      for (Index i : q) v.push_back(g[static_cast<std::size_t>(i)]);
      EXPECT_TRUE(has_face(m, v, true)) << to_string(s.type) << " picture quad " << q[0] << " " << q[1] << " " << q[2] << " " << q[3];
    }
    for (Index& i : special) i = g[static_cast<std::size_t>(i)];
    EXPECT_TRUE(has_face(m, special, true)) << to_string(s.type) << " special face";
    EXPECT_EQ(g[0] >= 0, true);
  };
  switch (s.type) {
    case Configuration::Regular:
    case Configuration::Star: {
      const int n = s.type == Configuration::Regular ? 4 : s.valence;
      EXPECT_EQ(g[0], s.centre);
      for (int k = 0; k < n; ++k) {
        const std::vector<Index> q{g[0], g[static_cast<std::size_t>(1 + 2 * k)], g[static_cast<std::size_t>(2 + 2 * k)],
                                   g[static_cast<std::size_t>(1 + 2 * ((k + 1) % n))]};
        EXPECT_TRUE(has_quad_or_collapsed(m, q)) << "sector " << k << " of vertex " << s.centre;
      }
      break;
    }
    case Configuration::Polar:
      EXPECT_EQ(g[0], s.centre);
      for (int k = 0; k < s.valence; ++k) {
        EXPECT_TRUE(has_face(m, {g[0], g[static_cast<std::size_t>(1 + k)], g[static_cast<std::size_t>(1 + (k + 1) % s.valence)]}, false));
      }
      break;
    case Configuration::NGon: {
      const int n = s.valence;
      std::vector<Index> c(g.begin(), g.begin() + n);
      EXPECT_TRUE(has_face(m, c, false));
      auto at = [&](int k, int which) { return g[static_cast<std::size_t>(n + 3 * ((k % n + n) % n) + which)]; };  // r, d, p
      for (int k = 0; k < n; ++k) {
        EXPECT_TRUE(has_face(m, {c[static_cast<std::size_t>((k + 1) % n)], c[static_cast<std::size_t>(k)], at(k, 2), at(k + 1, 0)}, false)) << "A_" << k;
        EXPECT_TRUE(has_face(m, {c[static_cast<std::size_t>(k)], at(k, 0), at(k, 1), at(k, 2)}, false)) << "B_" << k;
      }
      break;
    }
    case Configuration::T0: picture(t0_picture_quads(), {4, 7, 8}); break;
    case Configuration::T1: picture(t1_picture_quads(), {10, 9, 5, 6, 11}); break;
    case Configuration::T2: picture(t2_picture_quads(), {9, 11, 12, 13, 6, 5}); break;
  }
}

std::map<std::string, int> count_sites(const std::vector<ConfigurationSite>& sites, int* patches = nullptr) {
  std::map<std::string, int> c;
  if (patches) *patches = 0;
  for (const auto& s : sites) {
    std::string key = to_string(s.type);
    if (s.type == Configuration::Star || s.type == Configuration::NGon || s.type == Configuration::Polar) key += std::to_string(s.valence);
    ++c[key];
    if (patches) *patches += s.num_patches;
  }
  return c;
}

std::vector<Index> iota(Index n) {
  std::vector<Index> v(static_cast<std::size_t>(n));
  for (Index i = 0; i < n; ++i) v[static_cast<std::size_t>(i)] = i;
  return v;
}

TEST(PolyhedralConfiguration, StarOfEveryValence) {
  for (int n : {3, 4, 5, 6, 7, 8}) {
    const auto m = star_net(n, 10u + static_cast<unsigned>(n));
    const auto sites = classify(m);
    int patches = 0;
    const auto c = count_sites(sites, &patches);
    if (n == 4) {
      EXPECT_EQ(c, (std::map<std::string, int>{{"regular", 9}}));
      continue;
    }
    // The centre is a star; the 2n interior vertices of the rings are regular (Section 2 (1), (2)).
    EXPECT_EQ(c, (std::map<std::string, int>{{"regular", 2 * n}, {"star" + std::to_string(n), 1}})) << n;
    EXPECT_EQ(patches, 2 * n + (n == 3 || n == 5 ? n : 4 * n)) << n;
    for (const auto& s : sites) {
      expect_layout(m, s);
      if (s.type == Configuration::Star) {
        EXPECT_EQ(s.centre, 0);
        EXPECT_EQ(s.degree_u, 3);
        EXPECT_EQ(s.degree_v, 3);
      } else {
        EXPECT_EQ(s.degree_u, 2);
        EXPECT_EQ(s.degree_v, 2);
      }
    }
  }
}

TEST(PolyhedralConfiguration, NGonOfEveryValence) {
  for (int n : {3, 5, 6, 7, 8}) {
    const auto m = ngon_net(n, 20u + static_cast<unsigned>(n));
    const auto sites = classify(m);
    ASSERT_EQ(sites.size(), 1u) << n;  // the corners are the only interior vertices, covered by the n-gon
    EXPECT_EQ(sites[0].type, Configuration::NGon);
    EXPECT_EQ(sites[0].valence, n);
    EXPECT_EQ(sites[0].num_patches, n == 3 || n == 5 ? n : 4 * n);
    // ngon_net numbers its vertices in the mask.hpp order [c_0..c_{n-1}, r_0, d_0, p_0, …].
    EXPECT_EQ(sites[0].gathered, iota(4 * n)) << n;
    expect_layout(m, sites[0]);
  }
}

TEST(PolyhedralConfiguration, PolarFanOfEveryValence) {
  for (int n = 3; n <= 8; ++n) {
    const auto m = polar_net(n, 30u + static_cast<unsigned>(n));
    const auto sites = classify(m);
    int patches = 0;
    EXPECT_EQ(count_sites(sites, &patches), (std::map<std::string, int>{{"polar" + std::to_string(n), 1}, {"regular", n}})) << n;
    EXPECT_EQ(patches, 2 * n);  // n (3,2) patches and the ring of n bi-2 patches (Section 3 (7))
    for (const auto& s : sites) {
      expect_layout(m, s);
      if (s.type == Configuration::Polar) {
        EXPECT_EQ(s.degree_u, 3);
        EXPECT_EQ(s.degree_v, 2);
      } else {
        // Ring vertex q: the collapsed gather names the pole twice (f of the first triangle, e and f of the
        // second).
        EXPECT_EQ(std::count(s.gathered.begin(), s.gathered.end(), Index{0}), 3) << s.centre;
      }
    }
  }
}

TEST(PolyhedralConfiguration, TJunctionsInBothOrientations) {
  struct Case {
    Configuration type;
    int patches;
    mesh::PolyMesh net[2];
    bool identity_when_mirrored;  // which orientation reproduces the picture's numbering
  };
  Case cases[] = {{Configuration::T0, 4, {t0_net(false), t0_net(true)}, false},
                  {Configuration::T1, 8, {t1_net(false), t1_net(true)}, true},
                  {Configuration::T2, 16, {t2_net(false), t2_net(true)}, false}};
  for (auto& c : cases) {
    for (int mirror = 0; mirror < 2; ++mirror) {
      const auto& m = c.net[mirror];
      const auto sites = classify(m);
      ASSERT_EQ(sites.size(), 1u) << to_string(c.type);
      EXPECT_EQ(sites[0].type, c.type);
      EXPECT_EQ(sites[0].num_patches, c.patches);
      expect_layout(m, sites[0]);
      if ((mirror == 1) == c.identity_when_mirrored) {
        EXPECT_EQ(sites[0].gathered, iota(m.num_vertices())) << to_string(c.type);
      }
    }
  }
}

// --- The reference implementation's input nets -----------------------------------------------------------

struct Expected {
  std::map<std::string, int> sites;
  int patches;
};

// Derived by hand from each net's interior valences and face sizes and the paper's lists (Section 2 (1)–(7),
// Section 3 (1)–(7)): e.g. tee.obj (22 quads, closed) has interior valences 4 ×8, 3 ×12, 5 ×4, so 8 regular
// bi-2 patches + 12·3 + 4·5 bi-3 patches.
const std::map<std::string, Expected>& expected_reference_counts() {
  static const std::map<std::string, Expected> e{
      {"T0.obj", {{{"T0", 1}}, 4}},
      {"T1.obj", {{{"T1", 1}}, 8}},
      {"T2.obj", {{{"T2", 1}}, 16}},
      {"T012.obj", {{{"T0", 1}, {"T1", 1}, {"T2", 1}, {"regular", 12}}, 40}},
      {"cube.obj", {{{"star3", 4}}, 12}},
      {"cylinder.obj", {{{"polar6", 2}, {"regular", 18}}, 30}},
      {"eop3sct.obj", {{{"star3", 1}}, 3}},
      {"eop5sct.obj", {{{"star5", 1}}, 5}},
      {"eop6sct.obj", {{{"star6", 1}}, 24}},
      {"eop7sct.obj", {{{"star7", 1}}, 28}},
      {"eop8sct.obj", {{{"star8", 1}}, 32}},
      {"ngon3.obj", {{{"ngon3", 1}}, 3}},
      {"ngon5.obj", {{{"ngon5", 1}}, 5}},
      {"ngon6.obj", {{{"ngon6", 1}}, 24}},
      {"ngon7.obj", {{{"ngon7", 1}}, 28}},
      {"ngon8.obj", {{{"ngon8", 1}}, 32}},
      {"plane2x2.obj", {{{"regular", 1}}, 1}},
      {"polar3sct.obj", {{{"polar3", 1}}, 3}},
      {"polar4sct.obj", {{{"polar4", 1}}, 4}},
      {"polar5sct.obj", {{{"polar5", 1}}, 5}},
      {"polar6sct.obj", {{{"polar6", 1}}, 6}},
      {"polar7sct.obj", {{{"polar7", 1}}, 7}},
      {"polar8sct.obj", {{{"polar8", 1}}, 8}},
      {"tee.obj", {{{"regular", 8}, {"star3", 12}, {"star5", 4}}, 64}},
      {"tricube.obj", {{{"regular", 3}, {"star3", 13}, {"star5", 3}, {"star6", 1}}, 81}},
  };
  return e;
}

TEST(PolyhedralConfiguration, ReferenceNetsClassify) {
  const auto dir = reference_dir() / "testfile";
  if (!std::filesystem::is_directory(dir)) GTEST_SKIP() << "no reference nets at " << dir;
  int nets = 0;
  for (const auto& entry : std::filesystem::directory_iterator(dir)) {
    if (entry.path().extension() != ".obj") continue;
    const std::string name = entry.path().filename().string();
    SCOPED_TRACE(name);
    const auto m = iga::mesh::read_obj(entry.path().string());
    std::vector<ConfigurationSite> sites;
    ASSERT_NO_THROW(sites = classify(m));
    ++nets;
    int patches = 0;
    const auto c = count_sites(sites, &patches);
    std::string summary;
    for (const auto& [k, v] : c) summary += " " + k + ":" + std::to_string(v);
    std::cout << "[ counts   ] " << name << ":" << summary << " patches:" << patches << std::endl;
    for (const auto& s : sites) expect_layout(m, s);
    const auto it = expected_reference_counts().find(name);
    if (it != expected_reference_counts().end()) {
      EXPECT_EQ(c, it->second.sites);
      EXPECT_EQ(patches, it->second.patches);
    } else {
      // No hand count (hand.obj): every triangle belongs to exactly one polar fan, and every interior
      // vertex is covered exactly once (a vertex site, a pole, or a corner of a face site).
      Index triangles = 0, fan_triangles = 0;
      for (Index f = 0; f < m.num_faces(); ++f) triangles += m.face_size(f) == 3;
      std::set<Index> covered;
      for (const auto& s : sites) {
        if (s.type == Configuration::Polar) fan_triangles += s.valence;
        if (s.at_face) {
          for (Index v : m.face(s.centre)) EXPECT_TRUE(covered.insert(v).second);
        } else {
          EXPECT_TRUE(covered.insert(s.centre).second);
        }
      }
      EXPECT_EQ(fan_triangles, triangles);
      for (Index v = 0; v < m.num_vertices(); ++v) EXPECT_EQ(covered.count(v) == 1, !m.is_boundary_vertex(v)) << v;
    }
    // The reference's numbering of T0.obj and T1.obj is its picture's: the gather is the identity.
    if (name == "T0.obj" || name == "T1.obj") {
      EXPECT_EQ(sites[0].gathered, iota(m.num_vertices()));
    }
  }
  EXPECT_GE(nets, 26);
}

/// Rows and columns of a reference mask table (comment lines skipped).
std::pair<int, int> table_size(const std::filesystem::path& p) {
  std::ifstream in(p);
  std::string line;
  int rows = 0, cols = 0;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    ++rows;
    cols = static_cast<int>(std::count(line.begin(), line.end(), ',')) + 1;
  }
  return {rows, cols};
}

TEST(PolyhedralConfiguration, PatchCountsAndGatherSizesMatchReferenceTables) {
  const auto dir = reference_dir() / "src" / "Patch" / "Table";
  if (!std::filesystem::is_directory(dir)) GTEST_SKIP() << "no reference tables at " << dir;
  using iga::basis::polyhedral::num_gathered;
  using iga::basis::polyhedral::num_patches;
  using iga::basis::polyhedral::patch_degree_u;
  using iga::basis::polyhedral::patch_degree_v;
  auto check = [&](const std::string& file, Configuration c, int n) {
    SCOPED_TRACE(file);
    const auto [rows, cols] = table_size(dir / file);
    EXPECT_EQ(rows, num_patches(c, n) * (patch_degree_u(c) + 1) * (patch_degree_v(c) + 1));
    EXPECT_EQ(cols, num_gathered(c, n));
  };
  for (int n : {3, 5, 6, 7, 8}) {
    check("eopSct" + std::to_string(n) + ".csv", Configuration::Star, n);
    check("ngonSct" + std::to_string(n) + ".csv", Configuration::NGon, n);
  }
  for (int n = 3; n <= 8; ++n) check("polarSct" + std::to_string(n) + ".csv", Configuration::Polar, n);
  check("T0.csv", Configuration::T0, 0);
  check("T1.csv", Configuration::T1, 0);
  check("T2.csv", Configuration::T2, 0);
}

// --- Unsupported nets ----------------------------------------------------------------------------------------

/// 5 × 5 vertices, 4 × 4 quads; the quad with corners (1,1), (2,1), (2,2), (1,2) split into two triangles along
/// its diagonal (1,1)–(2,2).
mesh::PolyMesh split_quad_grid() {
  std::vector<Eigen::Vector3d> p;
  for (int j = 0; j < 5; ++j) {
    for (int i = 0; i < 5; ++i) p.push_back(Eigen::Vector3d(i, j, 0.1 * ((i * 7 + j * 3) % 5)));
  }
  auto v = [](int i, int j) -> Index { return i + 5 * j; };
  std::vector<std::vector<Index>> faces;
  for (int j = 0; j < 4; ++j) {
    for (int i = 0; i < 4; ++i) {
      if (i == 1 && j == 1) {
        faces.push_back({v(1, 1), v(2, 1), v(2, 2)});
        faces.push_back({v(1, 1), v(2, 2), v(1, 2)});
      } else {
        faces.push_back({v(i, j), v(i + 1, j), v(i + 1, j + 1), v(i, j + 1)});
      }
    }
  }
  return mesh::PolyMesh::build(std::move(p), std::move(faces));
}

TEST(PolyhedralConfiguration, ValenceNineIsNamedAndNotCuredByPresubdivision) {
  const auto m = star_net(9);
  try {
    classify(m);
    FAIL() << "valence 9 classified";
  } catch (const UnsupportedConfigurationError& e) {
    ASSERT_EQ(e.offences().size(), 1u);
    EXPECT_FALSE(e.offences()[0].at_face);
    EXPECT_EQ(e.offences()[0].index, 0);
    const std::string what = e.what();
    EXPECT_NE(what.find("vertex 1: valence 9 (supported: 3..8)"), std::string::npos) << what;
    EXPECT_NE(what.find("--presubdivide"), std::string::npos) << what;
    EXPECT_EQ(what.find('\n'), std::string::npos) << "one line";
  }
  // Catmull–Clark keeps the valence of the old vertices: still unsupported (the paper's code stops at 8).
  EXPECT_THROW(classify(presubdivide(m, 1)), iga::UnsupportedError);
}

TEST(PolyhedralConfiguration, SplitQuadNamesBothTrianglesAndPresubdivisionCures) {
  const auto m = split_quad_grid();
  try {
    classify(m);
    FAIL() << "split quad classified";
  } catch (const UnsupportedConfigurationError& e) {
    // The triangles are faces 6 and 7 (1-based); corner valences (5, 4, 5) and (5, 5, 4): neither an n-gon nor T0.
    ASSERT_EQ(e.offences().size(), 2u) << e.what();
    for (const auto& o : e.offences()) EXPECT_TRUE(o.at_face);
    const std::string what = e.what();
    EXPECT_NE(what.find("face 6: 3-gon with corner valences (5, 4, 5)"), std::string::npos) << what;
    EXPECT_NE(what.find("face 7: 3-gon with corner valences (5, 5, 4)"), std::string::npos) << what;
  }
  // One Catmull–Clark step: V + E + F vertices, all faces quads, only regular and star configurations.
  const auto fine = presubdivide(m, 1);
  EXPECT_EQ(fine.num_vertices(), 25 + (40 + 1) + 17);
  std::vector<ConfigurationSite> sites;
  ASSERT_NO_THROW(sites = classify(fine));
  int interior = 0;
  for (Index v = 0; v < fine.num_vertices(); ++v) interior += !fine.is_boundary_vertex(v);
  EXPECT_EQ(static_cast<int>(sites.size()), interior);
  for (const auto& s : sites) {
    EXPECT_TRUE(s.type == Configuration::Regular || s.type == Configuration::Star);
    expect_layout(fine, s);
  }
  const auto c = count_sites(sites);
  EXPECT_EQ(c.at("star3"), 2);  // the two triangles' face points
  EXPECT_EQ(c.at("star5"), 2);  // the two ends of the diagonal
}

TEST(PolyhedralConfiguration, NGonTouchingTheBoundaryNamesItsInteriorCorners) {
  // ngon_net(5) without B_0: corner c_0 lies on the boundary, so the pentagon touches it and produces no
  // patch; its corners c_1..c_4 stay interior and nothing covers them.
  const auto full = ngon_net(5);
  std::vector<std::vector<Index>> faces;
  for (Index f = 0; f < full.num_faces(); ++f) {
    if (f == 2) continue;  // B_0 = (c_0, r_0, d_0, p_0), the third face
    faces.emplace_back(full.face(f).begin(), full.face(f).end());
  }
  const auto m = mesh::PolyMesh::build(full.points(), faces);
  try {
    classify(m);
    FAIL() << "classified";
  } catch (const UnsupportedConfigurationError& e) {
    ASSERT_EQ(e.offences().size(), 4u) << e.what();
    for (std::size_t i = 0; i < 4; ++i) {
      EXPECT_FALSE(e.offences()[i].at_face);
      EXPECT_EQ(e.offences()[i].index, static_cast<Index>(i + 1));
    }
    EXPECT_NE(std::string(e.what()).find("vertex 2: corner of the 5-gon face 1, which touches the boundary"), std::string::npos) << e.what();
  }
}

}  // namespace
