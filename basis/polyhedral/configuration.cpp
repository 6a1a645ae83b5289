#include "basis/polyhedral/configuration.hpp"

#include <algorithm>
#include <set>
#include <sstream>

#include "basis/catmull_clark/topology.hpp"

namespace iga::basis::polyhedral {

std::string to_string(Configuration c) {
  switch (c) {
    case Configuration::Regular: return "regular";
    case Configuration::Star: return "star";
    case Configuration::NGon: return "ngon";
    case Configuration::Polar: return "polar";
    case Configuration::T0: return "T0";
    case Configuration::T1: return "T1";
    case Configuration::T2: return "T2";
  }
  return "unknown";
}

int num_patches(Configuration c, int valence) {
  switch (c) {
    case Configuration::Regular: return 1;
    case Configuration::Star:
    case Configuration::NGon: return (valence == 3 || valence == 5) ? valence : 4 * valence;  // Section 3 (2), (3)
    case Configuration::Polar: return valence;                                                 // Section 3 (7)
    case Configuration::T0: return 4;                                                          // 2 × 2
    case Configuration::T1: return 8;                                                          // 4 × 2
    case Configuration::T2: return 16;                                                         // 4 × 4
  }
  return 0;
}

int patch_degree_u(Configuration c) { return c == Configuration::Regular ? 2 : 3; }
int patch_degree_v(Configuration c) {
  return (c == Configuration::Regular || c == Configuration::Polar) ? 2 : 3;
}

int num_gathered(Configuration c, int valence) {
  switch (c) {
    case Configuration::Regular: return 9;
    case Configuration::Star: return 2 * valence + 1;
    case Configuration::NGon: return 4 * valence;
    case Configuration::Polar: return valence + 1;
    case Configuration::T0: return 14;
    case Configuration::T1: return 18;
    case Configuration::T2: return 20;
  }
  return 0;
}

std::string bv_group_name(Configuration c) {
  switch (c) {
    case Configuration::Regular: return "Group 0 Regular";
    case Configuration::Star: return "Group 1 ExtraordinaryPoint";
    case Configuration::T0: return "Group 2 T0";
    case Configuration::T1: return "Group 3 T1";
    case Configuration::T2: return "Group 4 T2";
    case Configuration::Polar: return "Group 5 Polar";
    case Configuration::NGon: return "Group 8 nGon";
  }
  return "Group 9 Unknown";
}

namespace {

std::string offences_message(const std::vector<Offence>& offences) {
  std::ostringstream s;
  s << "the control net has " << offences.size() << " unsupported configuration"
    << (offences.size() == 1 ? "" : "s") << " for polyhedral splines: ";
  for (std::size_t i = 0; i < offences.size(); ++i) {
    s << (i ? "; " : "") << (offences[i].at_face ? "face " : "vertex ") << offences[i].index + 1 << ": "
      << offences[i].reason;
  }
  s << ". One Catmull-Clark step makes a net with valences and face sizes <= 8 admissible: use --presubdivide 1";
  return s.str();
}

/// The faces around an interior vertex, counter-clockwise, each with v's outgoing half-edge in it.
struct Fan {
  std::vector<Index> half_edges;  ///< outgoing from v, one per face
  bool closed = true;             ///< false at the boundary
};

Fan fan_from(const mesh::PolyMesh& m, Index h0) {
  Fan fan;
  Index h = h0;
  do {
    fan.half_edges.push_back(h);
    const Index t = m.half_edge(m.half_edge(h).prev).twin;  // prev = w → v, its twin v → w in the next face
    if (t < 0) {
      fan.closed = false;
      break;
    }
    h = t;
  } while (h != h0 && fan.half_edges.size() <= static_cast<std::size_t>(m.num_half_edges()));
  return fan;
}

/// The vertices of h's face after h's origin, in face order (h's target first).
std::vector<Index> face_after(const mesh::PolyMesh& m, Index h) {
  std::vector<Index> out;
  for (Index g = m.half_edge(h).next; g != h; g = m.half_edge(g).next) out.push_back(m.half_edge(g).origin);
  return out;
}

std::string join(const std::vector<int>& v) {
  std::string s;
  for (std::size_t i = 0; i < v.size(); ++i) s += (i ? ", " : "") + std::to_string(v[i]);
  return s;
}

bool all_distinct(std::vector<Index> v) {
  std::sort(v.begin(), v.end());
  return std::adjacent_find(v.begin(), v.end()) == v.end();
}

class Classifier {
 public:
  explicit Classifier(const mesh::PolyMesh& m) : m_(m) {
    const Index nv = m.num_vertices();
    boundary_.resize(static_cast<std::size_t>(nv));
    for (Index v = 0; v < nv; ++v) boundary_[static_cast<std::size_t>(v)] = m.is_boundary_vertex(v) || m.num_vertex_faces(v) == 0;
    face_boundary_.resize(static_cast<std::size_t>(m.num_faces()));
    for (Index f = 0; f < m.num_faces(); ++f) {
      bool b = false;
      for (Index v : m.face(f)) b = b || boundary_[static_cast<std::size_t>(v)];
      face_boundary_[static_cast<std::size_t>(f)] = b;
    }
  }

  std::vector<ConfigurationSite> run() {
    const Index nv = m_.num_vertices();
    const Index nf = m_.num_faces();
    covered_.assign(static_cast<std::size_t>(nv), false);
    std::vector<bool> face_reported(static_cast<std::size_t>(nf), false);
    std::vector<bool> polar_pole(static_cast<std::size_t>(nv), false);
    std::vector<bool> pole_reported(static_cast<std::size_t>(nv), false);
    std::vector<ConfigurationSite> vertex_sites, face_sites;

    // Poles first: their ring vertices become (collapsed) Regular configurations.
    for (Index v = 0; v < nv; ++v) {
      if (is_boundary(v) || !all_faces_of_size(v, 3)) continue;
      std::string why;
      if (valid_pole(v, why)) {
        polar_pole[static_cast<std::size_t>(v)] = true;
      } else {
        offend(false, v, why);
        pole_reported[static_cast<std::size_t>(v)] = true;
        for (Index h : fan(v).half_edges) face_reported[static_cast<std::size_t>(m_.half_edge(h).face)] = true;
      }
    }
    // Face configurations.
    for (Index f = 0; f < nf; ++f) {
      const Index size = m_.face_size(f);
      if (size == 4 || face_boundary_[static_cast<std::size_t>(f)]) continue;
      if (size == 3 && in_valid_polar_fan(f, polar_pole)) continue;
      if (face_reported[static_cast<std::size_t>(f)]) continue;
      std::string why;
      ConfigurationSite site;
      if (face_configuration(f, site, why)) {
        for (Index v : m_.face(f)) covered_[static_cast<std::size_t>(v)] = true;
        face_sites.push_back(std::move(site));
      } else {
        offend(true, f, why);
        face_reported[static_cast<std::size_t>(f)] = true;
      }
    }
    // Vertex configurations, and the interior vertices nothing covers.
    for (Index v = 0; v < nv; ++v) {
      if (is_boundary(v)) continue;
      const int n = m_.valence(v);
      ConfigurationSite site;
      site.at_face = false;
      site.centre = v;
      site.valence = n;
      if (polar_pole[static_cast<std::size_t>(v)]) {
        site.type = Configuration::Polar;
        site.gathered.push_back(v);
        for (Index h : fan(v).half_edges) site.gathered.push_back(m_.half_edge_target(h));
      } else if (all_faces_of_size(v, 4) && n == 4) {
        site.type = Configuration::Regular;
        site.gathered = star_gather(v);
      } else if (all_faces_of_size(v, 4) && n >= 3 && n <= 8) {
        site.type = Configuration::Star;
        site.gathered = star_gather(v);
      } else if (n == 4 && polar_ring_regular(v, polar_pole, site.gathered)) {
        site.type = Configuration::Regular;
      } else {
        if (!covered_[static_cast<std::size_t>(v)] && !pole_reported[static_cast<std::size_t>(v)]) {
          vertex_offence(v, face_reported, polar_pole);
        }
        continue;
      }
      site.num_patches = num_patches(site.type, site.valence);
      site.degree_u = patch_degree_u(site.type);
      site.degree_v = patch_degree_v(site.type);
      if (site.type == Configuration::Regular) site.valence = 4;
      vertex_sites.push_back(std::move(site));
    }
    if (!offences_.empty()) {
      std::sort(offences_.begin(), offences_.end(), [](const Offence& a, const Offence& b) {
        return a.at_face != b.at_face ? !a.at_face : a.index < b.index;
      });
      throw UnsupportedConfigurationError(offences_);
    }
    vertex_sites.insert(vertex_sites.end(), face_sites.begin(), face_sites.end());
    return vertex_sites;
  }

 private:
  bool is_boundary(Index v) const { return boundary_[static_cast<std::size_t>(v)]; }

  Fan fan(Index v) const { return fan_from(m_, m_.vertex_half_edge(v)); }

  bool all_faces_of_size(Index v, Index size) const {
    const Fan f = fan(v);
    if (!f.closed) return false;
    for (Index h : f.half_edges) {
      if (m_.face_size(m_.half_edge(h).face) != size) return false;
    }
    return true;
  }

  void offend(bool at_face, Index index, const std::string& why) { offences_.push_back({at_face, index, why}); }

  /// [v, e_0, f_0, …] (mask.hpp), the link of v counter-clockwise.
  std::vector<Index> star_gather(Index v) const {
    std::vector<Index> g{v};
    for (Index h : fan(v).half_edges) {
      const auto after = face_after(m_, h);
      g.push_back(after[0]);
      g.push_back(after[1]);
    }
    return g;
  }

  bool valid_pole(Index p, std::string& why) const {
    const int n = m_.valence(p);
    if (n < 3 || n > 8) {
      why = "pole of " + std::to_string(n) + " triangles (supported: 3..8)";
      return false;
    }
    for (Index h : fan(p).half_edges) {
      const Index q = m_.half_edge_target(h);
      if (is_boundary(q)) continue;  // the outermost layer recedes: nothing to check there
      const Fan fq = fan(q);
      int triangles = 0, quads = 0;
      for (Index g : fq.half_edges) {
        const Index s = m_.face_size(m_.half_edge(g).face);
        triangles += s == 3;
        quads += s == 4;
      }
      if (m_.valence(q) != 4 || triangles != 2 || quads != 2) {
        why = "pole of " + std::to_string(n) + " triangles whose ring vertex " + std::to_string(q + 1) + " has valence " +
              std::to_string(m_.valence(q)) + " with " + std::to_string(triangles) + " triangles and " +
              std::to_string(quads) + " quads (a polar ring vertex needs valence 4: the two fan triangles and two quads)";
        return false;
      }
    }
    return true;
  }

  bool in_valid_polar_fan(Index f, const std::vector<bool>& polar_pole) const {
    for (Index v : m_.face(f)) {
      if (polar_pole[static_cast<std::size_t>(v)]) return true;
    }
    return false;
  }

  /// A 4-valent vertex of the ring around a valid pole: two consecutive fan triangles and two quads.
  bool polar_ring_regular(Index v, const std::vector<bool>& polar_pole, std::vector<Index>& gathered) const {
    const Fan fv = fan(v);
    if (!fv.closed || fv.half_edges.size() != 4) return false;
    Index pole = -1;
    int triangles = 0;
    for (Index h : fv.half_edges) {
      const Index s = m_.face_size(m_.half_edge(h).face);
      if (s == 3) {
        ++triangles;
        for (Index w : face_after(m_, h)) {
          if (polar_pole[static_cast<std::size_t>(w)]) pole = w;
        }
      } else if (s != 4) {
        return false;
      }
    }
    if (triangles != 2 || pole < 0) return false;
    gathered = {v};
    for (Index h : fv.half_edges) {
      const auto after = face_after(m_, h);
      gathered.push_back(after[0]);
      gathered.push_back(after.size() == 3 ? after[1] : pole);  // triangle (v, a, b) read as (v, a, P, P)
    }
    return true;
  }

  bool face_configuration(Index f, ConfigurationSite& site, std::string& why) const {
    const auto corners = m_.face(f);
    const int size = static_cast<int>(corners.size());
    const std::string name = std::to_string(size) + "-gon";
    if (size > 8) {
      why = name + " (supported: 3..8)";
      return false;
    }
    std::vector<int> val;
    for (Index c : corners) val.push_back(m_.valence(c));
    auto rotated = [&](int r) {
      std::vector<int> v(static_cast<std::size_t>(size));
      for (int k = 0; k < size; ++k) v[static_cast<std::size_t>(k)] = val[static_cast<std::size_t>((k + r) % size)];
      return v;
    };
    auto rotation_of = [&](const std::vector<int>& pattern) {
      for (int r = 0; r < size; ++r) {
        if (rotated(r) == pattern) return r;
      }
      return -1;
    };
    const std::vector<int> all4(static_cast<std::size_t>(size), 4);
    int r = -1;
    Configuration type = Configuration::NGon;
    if (size != 4 && (r = rotation_of(all4)) >= 0) {
      type = Configuration::NGon;
    } else if (size == 3 && (r = rotation_of({5, 4, 4})) >= 0) {
      type = Configuration::T0;
    } else if (size == 5 && (r = rotation_of({3, 4, 4, 4, 4})) >= 0) {
      type = Configuration::T1;
    } else if (size == 6 && (r = rotation_of({3, 4, 3, 4, 4, 4})) >= 0) {
      type = Configuration::T2;
    } else {
      std::string expected = "all 4 (n-gon)";
      if (size == 3) expected += ", (5, 4, 4) (T0) or a polar fan";
      if (size == 5) expected += " or (3, 4, 4, 4, 4) (T1)";
      if (size == 6) expected += " or (3, 4, 3, 4, 4, 4) in face order (T2)";
      why = name + " with corner valences (" + join(val) + ") (supported: " + expected + ")";
      return false;
    }
    // Ring: A_k = (s_k, x_k, y_k, s_{k+1}); corner segments between y_{k-1} and x_k.
    std::vector<Index> x(static_cast<std::size_t>(size)), y(static_cast<std::size_t>(size));
    std::vector<std::vector<Index>> segment(static_cast<std::size_t>(size));
    for (int k = 0; k < size; ++k) {
      const Index hk = m_.face_half_edge(f) + k;  // s_k → s_{k+1}
      const Fan fk = fan_from(m_, hk);           // F, A_{k-1}, corner faces…, A_k
      for (std::size_t i = 1; i < fk.half_edges.size(); ++i) {
        const Index g = m_.half_edge(fk.half_edges[i]).face;
        if (m_.face_size(g) != 4) {
          why = name + " whose neighbouring face " + std::to_string(g + 1) + " at corner vertex " +
                std::to_string(corners[static_cast<std::size_t>(k)] + 1) + " is a " +
                std::to_string(m_.face_size(g)) + "-gon (supported: quads around it)";
          return false;
        }
      }
      const Index t = m_.half_edge(hk).twin;  // s_{k+1} → s_k in A_k
      const auto a = face_after(m_, t);       // s_k, x_k, y_k
      x[static_cast<std::size_t>(k)] = a[1];
      y[static_cast<std::size_t>(k)] = a[2];
      std::vector<Index>& seg = segment[static_cast<std::size_t>(k)];
      for (std::size_t i = 2; i + 1 < fk.half_edges.size(); ++i) {
        const auto after = face_after(m_, fk.half_edges[i]);
        seg.insert(seg.end(), after.begin() + 1, after.end());
      }
      if (!seg.empty()) seg.pop_back();
    }
    // Re-index so that s_0 is corner r.
    auto s = [&](int k) { return corners[static_cast<std::size_t>((k + r) % size)]; };
    auto X = [&](int k) { return x[static_cast<std::size_t>((k + r) % size)]; };
    auto Y = [&](int k) { return y[static_cast<std::size_t>((k + r) % size)]; };
    auto D = [&](int k) -> Index {
      const auto& seg = segment[static_cast<std::size_t>((k + r) % size)];
      return seg.empty() ? -1 : seg[0];
    };
    std::vector<Index> g;
    switch (type) {
      case Configuration::NGon:
        for (int k = 0; k < size; ++k) g.push_back(s(k));
        for (int k = 0; k < size; ++k) {
          g.push_back(Y((k + size - 1) % size));  // r_k
          g.push_back(D(k));                      // d_k
          g.push_back(X(k));                      // p_k
        }
        break;
      case Configuration::T0: {
        const auto& seg0 = segment[static_cast<std::size_t>(r)];
        if (seg0.size() != 3) {
          why = name + ": T0 ring at its 5-valent corner is not two quads";
          return false;
        }
        g = {seg0[2], seg0[1], seg0[0], X(0), s(0), Y(2), Y(0), s(1), s(2), X(2), D(1), X(1), Y(1), D(2)};
        break;
      }
      case Configuration::T1:
        g = {D(2), X(2), Y(2), D(3), Y(1), s(2), s(3), X(3), X(1), s(1), s(0), s(4), Y(3), D(1), Y(0), X(0), X(4), D(4)};
        break;
      case Configuration::T2:
        g = {D(5), Y(4), X(4), D(4), X(5), s(5), s(4), Y(3), X(0), s(0), Y(0), s(1), s(2), s(3), X(3), D(1), X(1), X(2), Y(2), D(3)};
        break;
      default: break;
    }
    if (std::find(g.begin(), g.end(), Index{-1}) != g.end() || !all_distinct(g)) {
      why = name + " whose ring of quads is not simple (a vertex of the ring repeats)";
      return false;
    }
    site.type = type;
    site.valence = type == Configuration::NGon ? size : 0;
    site.at_face = true;
    site.centre = f;
    site.gathered = std::move(g);
    site.num_patches = num_patches(type, size);
    site.degree_u = patch_degree_u(type);
    site.degree_v = patch_degree_v(type);
    return true;
  }

  void vertex_offence(Index v, const std::vector<bool>& face_reported, const std::vector<bool>& polar_pole) {
    const int n = m_.valence(v);
    const Fan fv = fan(v);
    std::vector<int> sizes;
    bool reported_face = false, boundary_face = false;
    Index boundary_face_index = -1;
    for (Index h : fv.half_edges) {
      const Index f = m_.half_edge(h).face;
      sizes.push_back(static_cast<int>(m_.face_size(f)));
      if (m_.face_size(f) != 4) {
        reported_face = reported_face || face_reported[static_cast<std::size_t>(f)];
        if (face_boundary_[static_cast<std::size_t>(f)] && !(m_.face_size(f) == 3 && in_valid_polar_fan(f, polar_pole))) {
          boundary_face = true;
          boundary_face_index = f;
        }
      }
    }
    if (n > 8 || n < 3) {
      offend(false, v, "valence " + std::to_string(n) + " (supported: 3..8)");
    } else if (reported_face) {
      return;  // the offending face names the problem
    } else if (boundary_face) {
      offend(false, v, "corner of the " + std::to_string(m_.face_size(boundary_face_index)) + "-gon face " +
                           std::to_string(boundary_face_index + 1) + ", which touches the boundary (no configuration covers the vertex)");
    } else {
      offend(false, v, "valence " + std::to_string(n) + " with faces of sizes (" + join(sizes) +
                           ") around it is no supported configuration (a star needs " + std::to_string(n) + " quads)");
    }
  }

  const mesh::PolyMesh& m_;
  std::vector<bool> boundary_, face_boundary_, covered_;
  std::vector<Offence> offences_;
};

}  // namespace

UnsupportedConfigurationError::UnsupportedConfigurationError(std::vector<Offence> offences)
    : UnsupportedError(offences_message(offences)), offences_(std::move(offences)) {}

std::vector<ConfigurationSite> classify(const mesh::PolyMesh& net) { return Classifier(net).run(); }

mesh::PolyMesh presubdivide(const mesh::PolyMesh& net, int steps) {
  return catmull_clark::refine_net(net, steps).mesh;
}

}  // namespace iga::basis::polyhedral
