#include "basis/catmull_clark/local_mesh.hpp"

#include <algorithm>
#include <stdexcept>

namespace iga::basis::catmull_clark {

namespace {

// Directed sides of a local mesh, sorted: (from, to) -> (face, side).
class Sides {
 public:
  explicit Sides(const LocalMesh& m) : nv_(static_cast<long long>(m.vertex.size())) {
    sides_.reserve(4 * m.corner.size());
    for (std::size_t f = 0; f < m.corner.size(); ++f) {
      for (int s = 0; s < 4; ++s) {
        sides_.push_back({code(m.corner[f][static_cast<std::size_t>(s)], m.corner[f][static_cast<std::size_t>((s + 1) % 4)]),
                          static_cast<int>(f), s});
      }
    }
    std::sort(sides_.begin(), sides_.end(), [](const Side& a, const Side& b) { return a.code < b.code; });
  }
  // The face and side running from `to` to `from` (the other face of side from -> to), or {-1, -1}.
  std::pair<int, int> twin(int from, int to) const {
    const long long c = code(to, from);
    const auto it = std::lower_bound(sides_.begin(), sides_.end(), c, [](const Side& a, long long k) { return a.code < k; });
    return it == sides_.end() || it->code != c ? std::pair<int, int>{-1, -1} : std::pair<int, int>{it->face, it->side};
  }

 private:
  struct Side {
    long long code;
    int face, side;
  };
  long long code(int a, int b) const { return static_cast<long long>(a) * nv_ + b; }
  long long nv_;
  std::vector<Side> sides_;
};

}  // namespace

KeyBounds key_bounds(Index level0_faces, Index level0_vertices, int levels) {
  KeyBounds b;
  b.faces.push_back(level0_faces);
  b.vertex_bound.push_back(level0_vertices);
  for (int m = 0; m < levels; ++m) {
    b.vertex_bound.push_back(b.vertex_bound.back() + 5 * b.faces.back());
    b.faces.push_back(4 * b.faces.back());
  }
  return b;
}

VertexOrigin vertex_origin(const KeyBounds& b, int fine_level, Key vertex) {
  const Key vb = b.vertex_bound[static_cast<std::size_t>(fine_level) - 1];
  const Key nf = b.faces[static_cast<std::size_t>(fine_level) - 1];
  if (vertex < vb) return {VertexOrigin::kVertex, vertex, 0};
  if (vertex < vb + 4 * nf) return {VertexOrigin::kEdge, (vertex - vb) / 4, static_cast<int>((vertex - vb) % 4)};
  return {VertexOrigin::kFace, vertex - vb - 4 * nf, 0};
}

namespace {

// Vertex points where the fan is closed: (n - 2)/n v + 1/n^2 (the neighbours across the n edges + the n face
// points); an open fan gets an empty stencil.
void vertex_points(const LocalMesh& c, const Sides& sides, RefinedMesh& r) {
  const int nv = static_cast<int>(c.vertex.size());
  std::vector<std::vector<std::pair<int, int>>> at(static_cast<std::size_t>(nv));  // (face, corner) per vertex
  for (int f = 0; f < static_cast<int>(c.corner.size()); ++f) {
    for (int s = 0; s < 4; ++s) at[static_cast<std::size_t>(c.corner[static_cast<std::size_t>(f)][static_cast<std::size_t>(s)])].emplace_back(f, s);
  }
  std::vector<double> w(static_cast<std::size_t>(nv), 0.0);
  std::vector<int> touched;
  r.offsets.push_back(0);
  for (int v = 0; v < nv; ++v) {
    const auto& fan = at[static_cast<std::size_t>(v)];
    bool closed = !fan.empty();
    for (const auto& [f, s] : fan) {
      const auto& cf = c.corner[static_cast<std::size_t>(f)];
      closed = closed && sides.twin(v, cf[static_cast<std::size_t>((s + 1) % 4)]).first >= 0 &&
               sides.twin(cf[static_cast<std::size_t>((s + 3) % 4)], v).first >= 0;
    }
    if (closed) {
      const double n = static_cast<double>(fan.size());
      auto add = [&](int u, double x) {
        if (w[static_cast<std::size_t>(u)] == 0.0) touched.push_back(u);
        w[static_cast<std::size_t>(u)] += x;
      };
      add(v, (n - 2) / n);
      for (const auto& [f, s] : fan) {
        const auto& cf = c.corner[static_cast<std::size_t>(f)];
        add(cf[static_cast<std::size_t>((s + 1) % 4)], 1 / (n * n));  // each edge once: the side leaving v
        for (int u : cf) add(u, 0.25 / (n * n));
      }
      for (int u : touched) {
        r.entries.emplace_back(u, w[static_cast<std::size_t>(u)]);
        w[static_cast<std::size_t>(u)] = 0.0;
      }
      touched.clear();
    }
    r.offsets.push_back(static_cast<int>(r.entries.size()));
  }
}

}  // namespace

RefinedMesh refine_local(const LocalMesh& c, const KeyBounds& b, int level, bool stencils) {
  const Sides sides(c);
  const int nf = static_cast<int>(c.face.size());
  const Key vb = b.vertex_bound[static_cast<std::size_t>(level)], faces = b.faces[static_cast<std::size_t>(level)];
  RefinedMesh r;
  LocalMesh& fm = r.mesh;
  fm.vertex.reserve(c.vertex.size() + 3 * c.face.size());
  fm.vertex = c.vertex;
  if (stencils) {
    r.entries.reserve(16 * c.vertex.size() + 12 * c.face.size());
    vertex_points(c, sides, r);
  }
  for (int f = 0; f < nf; ++f) {
    fm.vertex.push_back(vb + 4 * faces + c.face[static_cast<std::size_t>(f)]);
    if (!stencils) continue;
    for (int v : c.corner[static_cast<std::size_t>(f)]) r.entries.emplace_back(v, 0.25);
    r.offsets.push_back(static_cast<int>(r.entries.size()));
  }
  std::vector<std::array<int, 4>> edge_point(static_cast<std::size_t>(nf), {-1, -1, -1, -1});
  for (int f = 0; f < nf; ++f) {
    const auto& cf = c.corner[static_cast<std::size_t>(f)];
    for (int s = 0; s < 4; ++s) {
      if (edge_point[static_cast<std::size_t>(f)][static_cast<std::size_t>(s)] >= 0) continue;
      const int a = cf[static_cast<std::size_t>(s)], z = cf[static_cast<std::size_t>((s + 1) % 4)];
      const auto [g, t] = sides.twin(a, z);
      Key key = 4 * c.face[static_cast<std::size_t>(f)] + s;
      const int id = static_cast<int>(fm.vertex.size());
      if (g >= 0) {
        key = std::min(key, 4 * c.face[static_cast<std::size_t>(g)] + t);
        edge_point[static_cast<std::size_t>(g)][static_cast<std::size_t>(t)] = id;
        if (stencils) {
          r.entries.insert(r.entries.end(), {{a, 0.375}, {z, 0.375}});
          for (int k : {2, 3}) {
            r.entries.emplace_back(cf[static_cast<std::size_t>((s + k) % 4)], 0.0625);
            r.entries.emplace_back(c.corner[static_cast<std::size_t>(g)][static_cast<std::size_t>((t + k) % 4)], 0.0625);
          }
        }
      }
      if (stencils) r.offsets.push_back(static_cast<int>(r.entries.size()));
      edge_point[static_cast<std::size_t>(f)][static_cast<std::size_t>(s)] = id;
      fm.vertex.push_back(vb + key);
    }
  }
  // Child k: corners k, k+1, k+2, k+3 at the vertex point, edge point k, face point, edge point k+3.
  const int nv = static_cast<int>(c.vertex.size());
  fm.corner.reserve(4 * c.face.size());
  fm.face.reserve(4 * c.face.size());
  for (int f = 0; f < nf; ++f) {
    const auto& cf = c.corner[static_cast<std::size_t>(f)];
    const auto& ep = edge_point[static_cast<std::size_t>(f)];
    for (int k = 0; k < 4; ++k) {
      std::array<int, 4> q{};
      q[static_cast<std::size_t>(k)] = cf[static_cast<std::size_t>(k)];
      q[static_cast<std::size_t>((k + 1) % 4)] = ep[static_cast<std::size_t>(k)];
      q[static_cast<std::size_t>((k + 2) % 4)] = nv + f;
      q[static_cast<std::size_t>((k + 3) % 4)] = ep[static_cast<std::size_t>((k + 3) % 4)];
      fm.corner.push_back(q);
      fm.face.push_back(4 * c.face[static_cast<std::size_t>(f)] + k);
    }
  }
  return r;
}

LocalMesh extract_ring(const LocalMesh& fine, int face) {
  const auto& centre = fine.corner[static_cast<std::size_t>(face)];
  std::vector<int> faces{face};
  for (int f = 0; f < static_cast<int>(fine.face.size()); ++f) {
    if (f == face) continue;
    const auto& cf = fine.corner[static_cast<std::size_t>(f)];
    const bool touches = std::any_of(cf.begin(), cf.end(), [&](int v) {
      return std::find(centre.begin(), centre.end(), v) != centre.end();
    });
    if (touches) faces.push_back(f);
  }
  LocalMesh out;
  std::vector<int> renumber(fine.vertex.size(), -1);
  for (int f : faces) {
    std::array<int, 4> q{};
    for (int j = 0; j < 4; ++j) {
      int& id = renumber[static_cast<std::size_t>(fine.corner[static_cast<std::size_t>(f)][static_cast<std::size_t>(j)])];
      if (id < 0) {
        id = static_cast<int>(out.vertex.size());
        out.vertex.push_back(fine.vertex[static_cast<std::size_t>(fine.corner[static_cast<std::size_t>(f)][static_cast<std::size_t>(j)])]);
      }
      q[static_cast<std::size_t>(j)] = id;
    }
    out.corner.push_back(q);
    out.face.push_back(fine.face[static_cast<std::size_t>(f)]);
  }
  return out;
}

std::array<int, 4> corner_valences(const LocalMesh& m) {
  std::array<int, 4> n{};
  for (const auto& cf : m.corner) {
    for (int v : cf) {
      for (int j = 0; j < 4; ++j) n[static_cast<std::size_t>(j)] += v == m.corner[0][static_cast<std::size_t>(j)];
    }
  }
  return n;
}

CanonicalMesh canonical_mesh(const LocalMesh& m, int start) {
  const Sides sides(m);
  CanonicalMesh out;
  std::vector<int> id(m.vertex.size(), -1), entry(m.face.size(), -1);
  std::vector<int> queue{0};
  entry[0] = start;
  out.faces.reserve(m.face.size());
  for (std::size_t q = 0; q < queue.size(); ++q) {
    const int f = queue[q], s0 = entry[static_cast<std::size_t>(f)];
    const auto& cf = m.corner[static_cast<std::size_t>(f)];
    auto& face = out.faces.emplace_back();
    for (int i = 0; i < 4; ++i) {
      const int v = cf[static_cast<std::size_t>((s0 + i) % 4)];
      if (id[static_cast<std::size_t>(v)] < 0) {
        id[static_cast<std::size_t>(v)] = static_cast<int>(out.canonical.size());
        out.canonical.push_back(v);
      }
      face.push_back(id[static_cast<std::size_t>(v)]);
    }
    for (int i = 0; i < 4; ++i) {
      const int a = cf[static_cast<std::size_t>((s0 + i) % 4)], z = cf[static_cast<std::size_t>((s0 + i + 1) % 4)];
      const auto [g, t] = sides.twin(a, z);
      if (g < 0 || entry[static_cast<std::size_t>(g)] >= 0) continue;
      entry[static_cast<std::size_t>(g)] = t;  // entered at its corner t (the origin of its side z -> a)
      queue.push_back(g);
    }
  }
  if (out.faces.size() != m.face.size()) {
    throw std::logic_error("catmull_clark: a cell's neighbourhood is not connected across sides");
  }
  return out;
}

}  // namespace iga::basis::catmull_clark
