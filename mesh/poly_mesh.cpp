#include "mesh/poly_mesh.hpp"

#include <algorithm>
#include <cstddef>
#include <optional>
#include <utility>

namespace iga::mesh {

namespace {

std::size_t at(Index i) { return static_cast<std::size_t>(i); }

std::string edge_text(const std::vector<Index>& v, Index base) {
  if (v.size() < 2) {
    return "(?)";
  }
  std::string text(1, '(');  // built by appending: GCC 12 warns falsely on "(" + std::string&&
  text += std::to_string(v[0] + base);
  text += ',';
  text += std::to_string(v[1] + base);
  text += ')';
  return text;
}

std::string vertex_text(const std::vector<Index>& v, Index base) {
  return v.empty() ? std::string("?") : std::to_string(v[0] + base);
}

std::string render(TopologyProblem problem, const std::vector<Index>& vertices, Index count, Index base) {
  switch (problem) {
    case TopologyProblem::kNoFaces:
      return "mesh has no faces";
    case TopologyProblem::kTooFewVertices:
      return "face has " + std::to_string(vertices.size()) + " vertices; a face needs at least 3";
    case TopologyProblem::kIndexOutOfRange:
      return "vertex index " + vertex_text(vertices, base) + " out of range (" + std::to_string(count) +
             " vertices defined)";
    case TopologyProblem::kRepeatedVertex:
      return "vertex " + vertex_text(vertices, base) + " appears more than once in the face";
    case TopologyProblem::kNonManifoldEdge:
      return "edge " + edge_text(vertices, base) + " is shared by more than two faces";
    case TopologyProblem::kInconsistentOrientation:
      return "face orientation inconsistent with a neighbouring face across edge " + edge_text(vertices, base);
    case TopologyProblem::kNonManifoldVertex:
      return "vertex " + vertex_text(vertices, base) + " is non-manifold: its faces form " +
             std::to_string(count) + " separate fans";
    case TopologyProblem::kOther:
      break;
  }
  return "topology error";
}

std::string structured_message(Index face, TopologyProblem problem, const std::vector<Index>& vertices,
                               Index count) {
  std::string text = render(problem, vertices, count, 0);
  return face >= 0 ? "face " + std::to_string(face) + ": " + text : text;
}

// Candidate error kept while scanning: the one with the lowest face wins.
struct Problem {
  Index face = -1;
  TopologyProblem kind = TopologyProblem::kOther;
  std::vector<Index> vertices;
  Index count = 0;
};

void keep_lowest(std::optional<Problem>& best, Problem candidate) {
  if (!best || candidate.face < best->face) {
    best = std::move(candidate);
  }
}

[[noreturn]] void raise(const Problem& p) { throw TopologyError(p.face, p.kind, p.vertices, p.count); }

// Rotation around the origin of h to the next outgoing half-edge (counter-clockwise), -1 at a boundary.
Index rotate_ccw(const std::vector<HalfEdge>& he, Index h) { return he[at(he[at(h)].prev)].twin; }

// Inverse rotation (clockwise), -1 at a boundary.
Index rotate_cw(const std::vector<HalfEdge>& he, Index h) {
  const Index t = he[at(h)].twin;
  return t < 0 ? -1 : he[at(t)].next;
}

// Fan analysis of a vertex known to be non-manifold; `out` = its outgoing half-edges, ascending. Returns the
// problem with the lowest face outside the fan of the vertex's lowest face, and the number of fans.
Problem non_manifold_vertex_problem(const std::vector<HalfEdge>& he, Index v, std::span<const Index> out) {
  std::vector<char> visited(out.size(), 0);
  auto mark = [&](Index h) {
    const auto it = std::lower_bound(out.begin(), out.end(), h);
    visited[static_cast<std::size_t>(it - out.begin())] = 1;
  };
  Index fans = 0;
  Index offending = -1;
  for (std::size_t i = 0; i < out.size(); ++i) {
    if (visited[i] != 0) {
      continue;
    }
    ++fans;
    if (fans == 2) {
      offending = he[at(out[i])].face;
    }
    const Index start = out[i];
    mark(start);
    for (Index h = rotate_ccw(he, start); h >= 0 && h != start; h = rotate_ccw(he, h)) {
      mark(h);
    }
    for (Index h = rotate_cw(he, start); h >= 0 && h != start; h = rotate_cw(he, h)) {
      mark(h);
    }
  }
  return Problem{offending, TopologyProblem::kNonManifoldVertex, {v}, fans};
}

}  // namespace

TopologyError::TopologyError(Index face, const std::string& reason)
    : InputError(reason), face_(face), text_(reason) {}

TopologyError::TopologyError(Index face, TopologyProblem problem, std::vector<Index> vertices, Index count)
    : InputError(structured_message(face, problem, vertices, count)),
      face_(face),
      problem_(problem),
      vertices_(std::move(vertices)),
      count_(count) {}

std::string TopologyError::describe(Index index_base) const {
  if (problem_ == TopologyProblem::kOther) {
    return text_;
  }
  return render(problem_, vertices_, count_, index_base);
}

PolyMesh PolyMesh::build(std::vector<Eigen::Vector3d> points, std::vector<std::vector<Index>> faces) {
  const Index nv = static_cast<Index>(points.size());
  for (Index v = 0; v < nv; ++v) {
    if (!points[at(v)].allFinite()) {
      throw InputError("vertex " + std::to_string(v + 1) + " has a non-finite coordinate");
    }
  }
  if (faces.empty()) {
    throw TopologyError(-1, TopologyProblem::kNoFaces, {});
  }

  // Per-face checks, in face order.
  const Index nf = static_cast<Index>(faces.size());
  std::size_t total = 0;
  std::vector<Index> sorted;
  for (Index f = 0; f < nf; ++f) {
    const std::vector<Index>& fv = faces[at(f)];
    if (fv.size() < 3) {
      throw TopologyError(f, TopologyProblem::kTooFewVertices, fv);
    }
    for (const Index idx : fv) {
      if (idx < 0 || idx >= nv) {
        throw TopologyError(f, TopologyProblem::kIndexOutOfRange, {idx}, nv);
      }
    }
    sorted.assign(fv.begin(), fv.end());
    std::sort(sorted.begin(), sorted.end());
    const auto dup = std::adjacent_find(sorted.begin(), sorted.end());
    if (dup != sorted.end()) {
      throw TopologyError(f, TopologyProblem::kRepeatedVertex, {*dup});
    }
    total += fv.size();
  }

  PolyMesh m;
  m.points_ = std::move(points);
  m.planar_ = std::all_of(m.points_.begin(), m.points_.end(), [](const Eigen::Vector3d& p) { return p.z() == 0.0; });

  // Flat face storage and the half-edges inside each face.
  m.face_offsets_.reserve(at(nf) + 1);
  m.face_indices_.reserve(total);
  m.half_edges_.reserve(total);
  m.face_offsets_.push_back(0);
  for (Index f = 0; f < nf; ++f) {
    const std::vector<Index>& fv = faces[at(f)];
    const Index n = static_cast<Index>(fv.size());
    const Index base = m.face_offsets_.back();
    for (Index i = 0; i < n; ++i) {
      m.face_indices_.push_back(fv[at(i)]);
      m.half_edges_.push_back(HalfEdge{fv[at(i)], f, base + (i + 1) % n, base + (i + n - 1) % n, -1});
    }
    m.face_offsets_.push_back(base + n);
  }
  faces = {};  // release the input lists early

  std::vector<HalfEdge>& he = m.half_edges_;
  const Index nh = static_cast<Index>(he.size());
  auto target = [&](Index h) { return he[at(he[at(h)].next)].origin; };

  // Group half-edges by undirected edge: counting sort on the smaller vertex, then sort each small bucket by
  // (larger vertex, half-edge). Within a group half-edges are ascending, hence in face order.
  std::vector<Index> bucket(at(nv) + 1, 0);
  for (Index h = 0; h < nh; ++h) {
    ++bucket[at(std::min(he[at(h)].origin, target(h))) + 1];
  }
  for (Index v = 0; v < nv; ++v) {
    bucket[at(v) + 1] += bucket[at(v)];
  }
  std::vector<std::pair<Index, Index>> keyed(at(nh));  // (larger vertex, half-edge)
  {
    std::vector<Index> fill(bucket.begin(), bucket.end() - 1);
    for (Index h = 0; h < nh; ++h) {
      const Index a = he[at(h)].origin;
      const Index b = target(h);
      keyed[at(fill[at(std::min(a, b))]++)] = {std::max(a, b), h};
    }
  }

  std::optional<Problem> edge_problem;
  for (Index v = 0; v < nv; ++v) {
    const auto first = keyed.begin() + bucket[at(v)];
    const auto last = keyed.begin() + bucket[at(v) + 1];
    std::sort(first, last);
    for (auto g = first; g != last;) {
      auto g_end = g;
      while (g_end != last && g_end->first == g->first) {
        ++g_end;
      }
      const auto k = g_end - g;
      if (k >= 2) {
        const Index h0 = g[0].second;
        const Index h1 = g[1].second;
        if (he[at(h0)].origin == he[at(h1)].origin) {
          keep_lowest(edge_problem, Problem{he[at(h1)].face, TopologyProblem::kInconsistentOrientation,
                                            {he[at(h1)].origin, target(h1)}, 0});
        } else {
          he[at(h0)].twin = h1;
          he[at(h1)].twin = h0;
        }
      }
      if (k >= 3) {
        const Index h2 = g[2].second;
        keep_lowest(edge_problem,
                    Problem{he[at(h2)].face, TopologyProblem::kNonManifoldEdge, {he[at(h2)].origin, target(h2)}, 0});
      }
      g = g_end;
    }
  }
  if (edge_problem) {
    raise(*edge_problem);
  }
  keyed = {};

  // Per-vertex data: outgoing half-edge (the boundary one if any), face count, valence.
  m.vertex_half_edge_.assign(at(nv), -1);
  m.num_vertex_faces_.assign(at(nv), 0);
  m.valence_.assign(at(nv), 0);
  std::vector<int> boundary_out(at(nv), 0);
  for (Index h = 0; h < nh; ++h) {
    const Index v = he[at(h)].origin;
    ++m.num_vertex_faces_[at(v)];
    Index& vh = m.vertex_half_edge_[at(v)];
    if (he[at(h)].twin < 0) {
      ++boundary_out[at(v)];
      ++m.valence_[at(target(h))];  // an incoming boundary half-edge is an edge no outgoing one covers
      if (vh < 0 || he[at(vh)].twin >= 0) {
        vh = h;
      }
    } else if (vh < 0) {
      vh = h;
    }
  }
  for (Index v = 0; v < nv; ++v) {
    m.valence_[at(v)] += m.num_vertex_faces_[at(v)];
  }

  // Manifold vertices: all incident faces in a single fan (one chain from the boundary, or one cycle).
  std::vector<Index> bad_vertices;
  for (Index v = 0; v < nv; ++v) {
    const int n = m.num_vertex_faces_[at(v)];
    if (n == 0) {
      continue;
    }
    if (boundary_out[at(v)] > 1) {
      bad_vertices.push_back(v);
      continue;
    }
    const Index start = m.vertex_half_edge_[at(v)];
    int steps = 0;
    Index h = start;
    do {
      ++steps;
      h = rotate_ccw(he, h);
    } while (h >= 0 && h != start && steps <= n);
    if (steps != n) {
      bad_vertices.push_back(v);
    }
  }
  if (!bad_vertices.empty()) {
    std::vector<Index> out_start(at(nv) + 1, 0);
    for (Index v = 0; v < nv; ++v) {
      out_start[at(v) + 1] = out_start[at(v)] + m.num_vertex_faces_[at(v)];
    }
    std::vector<Index> out(at(nh));
    std::vector<Index> fill(out_start.begin(), out_start.end() - 1);
    for (Index h = 0; h < nh; ++h) {
      out[at(fill[at(he[at(h)].origin)]++)] = h;
    }
    std::optional<Problem> vertex_problem;
    for (const Index v : bad_vertices) {
      const std::span<const Index> list(out.data() + out_start[at(v)], out.data() + out_start[at(v) + 1]);
      keep_lowest(vertex_problem, non_manifold_vertex_problem(he, v, list));
    }
    raise(*vertex_problem);
  }

  // Boundary loops, in ascending order of their smallest half-edge.
  std::vector<char> seen(at(nh), 0);
  for (Index h = 0; h < nh; ++h) {
    if (he[at(h)].twin >= 0 || seen[at(h)] != 0) {
      continue;
    }
    std::vector<Index> loop;
    Index g = h;
    do {
      seen[at(g)] = 1;
      loop.push_back(g);
      g = m.vertex_half_edge_[at(target(g))];
    } while (g != h);
    m.boundary_loops_.push_back(std::move(loop));
  }
  return m;
}

std::span<const Index> PolyMesh::face(Index f) const {
  const Index b = face_offsets_[at(f)];
  const Index e = face_offsets_[at(f) + 1];
  return {face_indices_.data() + b, static_cast<std::size_t>(e - b)};
}

Index PolyMesh::face_size(Index f) const { return face_offsets_[at(f) + 1] - face_offsets_[at(f)]; }

bool PolyMesh::is_boundary_vertex(Index v) const {
  const Index h = vertex_half_edge_[at(v)];
  return h >= 0 && half_edges_[at(h)].twin < 0;
}

void PolyMesh::set_source_lines(std::vector<long> vertex_lines, std::vector<long> face_lines) {
  vertex_lines_ = std::move(vertex_lines);
  face_lines_ = std::move(face_lines);
}

long PolyMesh::vertex_line(Index v) const {
  return v >= 0 && static_cast<std::size_t>(v) < vertex_lines_.size() ? vertex_lines_[static_cast<std::size_t>(v)] : 0;
}

long PolyMesh::face_line(Index f) const {
  return f >= 0 && static_cast<std::size_t>(f) < face_lines_.size() ? face_lines_[static_cast<std::size_t>(f)] : 0;
}

}  // namespace iga::mesh
