#include "basis/catmull_clark/quad_mesh.hpp"

#include <algorithm>
#include <map>
#include <numeric>
#include <stdexcept>
#include <utility>

namespace iga::basis::catmull_clark {

void build_twins(QuadMesh& m) {
  const int nh = 4 * m.num_faces();
  m.twin.assign(static_cast<std::size_t>(nh), -1);
  std::map<std::pair<int, int>, int> directed;
  for (int h = 0; h < nh; ++h) {
    if (!directed.emplace(std::pair{m.origin(h), m.target(h)}, h).second) {
      throw std::logic_error("catmull_clark::build_twins: directed edge occurs twice");
    }
  }
  for (int h = 0; h < nh; ++h) {
    const auto it = directed.find({m.target(h), m.origin(h)});
    if (it != directed.end()) m.twin[static_cast<std::size_t>(h)] = it->second;
  }
}

QuadMesh quad_mesh_from(const mesh::PolyMesh& mesh) {
  QuadMesh m;
  m.num_vertices = static_cast<int>(mesh.num_vertices());
  m.quads.resize(static_cast<std::size_t>(mesh.num_faces()));
  for (Index f = 0; f < mesh.num_faces(); ++f) {
    const auto fv = mesh.face(f);
    if (fv.size() != 4) throw std::logic_error("catmull_clark::quad_mesh_from: face is not a quad");
    for (int i = 0; i < 4; ++i) m.quads[static_cast<std::size_t>(f)][static_cast<std::size_t>(i)] = static_cast<int>(fv[i]);
  }
  m.twin.assign(static_cast<std::size_t>(4 * m.num_faces()), -1);
  for (Index f = 0; f < mesh.num_faces(); ++f) {
    for (int i = 0; i < 4; ++i) {
      const Index h = mesh.face_half_edge(f) + i;
      const Index t = mesh.half_edge(h).twin;
      if (t < 0) continue;
      const Index g = mesh.half_edge(t).face;
      m.twin[static_cast<std::size_t>(4 * f + i)] = static_cast<int>(4 * g + (t - mesh.face_half_edge(g)));
    }
  }
  return m;
}

namespace {

struct UnionFind {
  std::vector<int> up;
  explicit UnionFind(int n) : up(static_cast<std::size_t>(n)) { std::iota(up.begin(), up.end(), 0); }
  int find(int a) {
    while (up[static_cast<std::size_t>(a)] != a) a = up[static_cast<std::size_t>(a)] = up[static_cast<std::size_t>(up[static_cast<std::size_t>(a)])];
    return a;
  }
  void unite(int a, int b) {
    a = find(a);
    b = find(b);
    if (a != b) up[static_cast<std::size_t>(std::max(a, b))] = std::min(a, b);
  }
};

// Half-edges leaving the origin of h, in counter-clockwise order around it, starting with h for an interior
// vertex and with the clockwise-most one at a boundary. `self` receives the position of h.
std::vector<int> fan(const QuadMesh& m, int h, int& self) {
  std::vector<int> ccw_part{h};
  for (int g = m.ccw(h); g >= 0 && g != h; g = m.ccw(g)) ccw_part.push_back(g);
  if (m.ccw(ccw_part.back()) == h) {
    self = 0;
    return ccw_part;
  }
  std::vector<int> out;
  for (int g = m.cw(h); g >= 0; g = m.cw(g)) out.push_back(g);
  std::reverse(out.begin(), out.end());
  self = static_cast<int>(out.size());
  out.insert(out.end(), ccw_part.begin(), ccw_part.end());
  return out;
}

}  // namespace

OneRing unfold_one_ring(const QuadMesh& m, int face, int rotation) {
  // Local faces: (parent face, rotation of its corner order).
  std::vector<std::pair<int, int>> faces{{face, rotation}};
  auto local_corner = [&](int lf, int h) { return (h % 4 - faces[static_cast<std::size_t>(lf)].second + 4) % 4; };
  std::array<int, 4> edge_face{-1, -1, -1, -1};  // local face across edge i of the face (from corner i to i+1)
  struct Member {
    int local_face, half_edge;
  };
  std::array<std::vector<Member>, 4> fans;
  std::array<bool, 4> closed{};
  for (int i = 0; i < 4; ++i) {
    const int h = 4 * face + (i + rotation) % 4;
    int self = 0;
    const std::vector<int> hs = fan(m, h, self);
    const int k = static_cast<int>(hs.size());
    closed[static_cast<std::size_t>(i)] = m.ccw(hs.back()) == hs.front();
    // Visit counter-clockwise from the face, then the rest of the fan.
    std::vector<Member> members(static_cast<std::size_t>(k));
    for (int t = 0; t < k; ++t) {
      const int g = hs[static_cast<std::size_t>(t)];
      int lf = -1;
      if (t == self) {
        lf = 0;
      } else {
        int* shared = nullptr;
        const bool ccw_next = closed[static_cast<std::size_t>(i)] ? (t == (self + 1) % k) : (t == self + 1);
        const bool cw_next = closed[static_cast<std::size_t>(i)] ? (t == (self + k - 1) % k) : (t == self - 1);
        if (ccw_next) shared = &edge_face[static_cast<std::size_t>((i + 3) % 4)];
        else if (cw_next) shared = &edge_face[static_cast<std::size_t>(i)];
        if (shared != nullptr && *shared >= 0) {
          lf = *shared;
        } else {
          lf = static_cast<int>(faces.size());
          faces.emplace_back(g / 4, 0);
          if (shared != nullptr) *shared = lf;
        }
      }
      members[static_cast<std::size_t>(t)] = {lf, g};
    }
    fans[static_cast<std::size_t>(i)] = std::move(members);
  }
  const int nf = static_cast<int>(faces.size());
  UnionFind uf(4 * nf);
  for (int i = 0; i < 4; ++i) {
    const auto& members = fans[static_cast<std::size_t>(i)];
    const int k = static_cast<int>(members.size());
    for (int t = 0; t < k; ++t) {
      const auto& a = members[static_cast<std::size_t>(t)];
      uf.unite(4 * a.local_face + local_corner(a.local_face, a.half_edge), i);
      if (t + 1 < k || closed[static_cast<std::size_t>(i)]) {
        const auto& b = members[static_cast<std::size_t>((t + 1) % k)];
        uf.unite(4 * a.local_face + local_corner(a.local_face, QuadMesh::prev(a.half_edge)),
                 4 * b.local_face + local_corner(b.local_face, QuadMesh::next(b.half_edge)));
      }
    }
  }
  OneRing ring;
  std::vector<int> id(static_cast<std::size_t>(4 * nf), -1);
  ring.mesh.quads.resize(static_cast<std::size_t>(nf));
  for (int lf = 0; lf < nf; ++lf) {
    const auto [g, rot] = faces[static_cast<std::size_t>(lf)];
    for (int j = 0; j < 4; ++j) {
      const int cls = uf.find(4 * lf + j);
      const int pv = m.quads[static_cast<std::size_t>(g)][static_cast<std::size_t>((j + rot) % 4)];
      int& v = id[static_cast<std::size_t>(cls)];
      if (v < 0) {
        v = static_cast<int>(ring.parent.size());
        ring.parent.push_back(pv);
      } else if (ring.parent[static_cast<std::size_t>(v)] != pv) {
        throw std::logic_error("catmull_clark::unfold_one_ring: inconsistent vertex identification");
      }
      ring.mesh.quads[static_cast<std::size_t>(lf)][static_cast<std::size_t>(j)] = v;
    }
  }
  ring.mesh.num_vertices = static_cast<int>(ring.parent.size());
  build_twins(ring.mesh);
  return ring;
}

Subdivided subdivide(const QuadMesh& m) {
  const int nv = m.num_vertices, nf = m.num_faces(), nh = 4 * nf;
  std::vector<int> edge_of(static_cast<std::size_t>(nh), -1);
  int ne = 0;
  for (int h = 0; h < nh; ++h) {
    const int t = m.twin[static_cast<std::size_t>(h)];
    if (t < 0 || h < t) {
      edge_of[static_cast<std::size_t>(h)] = ne;
      if (t >= 0) edge_of[static_cast<std::size_t>(t)] = ne;
      ++ne;
    }
  }
  Subdivided s;
  Eigen::MatrixXd& w = s.weights;
  w.setZero(nv + ne + nf, nv);
  const int f0 = nv + ne;
  for (int f = 0; f < nf; ++f) {
    for (int j = 0; j < 4; ++j) w(f0 + f, m.quads[static_cast<std::size_t>(f)][static_cast<std::size_t>(j)]) += 0.25;
  }
  for (int h = 0; h < nh; ++h) {
    const int t = m.twin[static_cast<std::size_t>(h)];
    const int e = nv + edge_of[static_cast<std::size_t>(h)];
    if (t < 0) {
      w(e, m.origin(h)) += 0.5;
      w(e, m.target(h)) += 0.5;
    } else if (h < t) {
      w(e, m.origin(h)) += 0.25;
      w(e, m.target(h)) += 0.25;
      w.row(e) += 0.25 * (w.row(f0 + h / 4) + w.row(f0 + t / 4));
    }
  }
  // Vertex points.
  std::vector<std::vector<int>> out(static_cast<std::size_t>(nv));
  for (int h = 0; h < nh; ++h) out[static_cast<std::size_t>(m.origin(h))].push_back(h);
  for (int v = 0; v < nv; ++v) {
    const auto& hs = out[static_cast<std::size_t>(v)];
    int next_boundary = -1, prev_boundary = -1, boundary_count = 0;
    for (int h : hs) {
      if (m.twin[static_cast<std::size_t>(h)] < 0) {
        next_boundary = m.target(h);
        ++boundary_count;
      }
      if (m.twin[static_cast<std::size_t>(QuadMesh::prev(h))] < 0) {
        prev_boundary = m.origin(QuadMesh::prev(h));
        ++boundary_count;
      }
    }
    const int n = static_cast<int>(hs.size());
    if (n == 0) {
      w(v, v) = 1.0;
    } else if (boundary_count == 0) {
      const double nn = static_cast<double>(n);
      w(v, v) += (nn - 2.0) / nn;
      for (int h : hs) {
        w(v, m.target(h)) += 1.0 / (nn * nn);
        w.row(v) += w.row(f0 + h / 4) / (nn * nn);
      }
    } else if (n >= 2 && boundary_count == 2 && next_boundary >= 0 && prev_boundary >= 0) {
      w(v, v) += 0.75;
      w(v, next_boundary) += 0.125;
      w(v, prev_boundary) += 0.125;
    } else {
      w(v, v) = 1.0;  // corner (one face); on the rim of a local neighbourhood: not used
    }
  }
  s.mesh.num_vertices = nv + ne + nf;
  s.mesh.quads.resize(static_cast<std::size_t>(4 * nf));
  for (int f = 0; f < nf; ++f) {
    for (int k = 0; k < 4; ++k) {
      s.mesh.quads[static_cast<std::size_t>(4 * f + k)] = {
          m.quads[static_cast<std::size_t>(f)][static_cast<std::size_t>(k)], nv + edge_of[static_cast<std::size_t>(4 * f + k)],
          f0 + f, nv + edge_of[static_cast<std::size_t>(4 * f + (k + 3) % 4)]};
    }
  }
  build_twins(s.mesh);
  return s;
}

}  // namespace iga::basis::catmull_clark
