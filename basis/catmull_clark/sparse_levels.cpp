#include "basis/catmull_clark/sparse_levels.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <stdexcept>

#include "basis/catmull_clark/ghost_net.hpp"
#include "core/error.hpp"

namespace iga::basis::catmull_clark {

namespace {

constexpr int kLevelCap = 60;

}  // namespace

struct SparseCatmullClarkLevels::Template {
  std::vector<std::vector<Index>> faces;  // the canonical topology it was built for
  std::unique_ptr<CatmullClarkSpace> space;
};

struct SparseCatmullClarkLevels::Cell {
  LocalMesh mesh;
  // Cells of the domain only (ghost cells serve as parents and in support()):
  int rotation = 0;
  ElementKind kind;
  const Template* tmpl = nullptr;
  std::vector<Key> functions;       // in the order of tmpl->space->dofs(0)
  std::vector<int> function_of;     // local vertex -> function index
};

bool SparseCatmullClarkLevels::supports(const CatmullClarkSpace& level0) {
  return level0.boundary_rule() == BoundaryRule::kClamped || level0.control_mesh().is_closed();
}

SparseCatmullClarkLevels::SparseCatmullClarkLevels(std::shared_ptr<const CatmullClarkSpace> level0)
    : CatmullClarkHierarchy(std::move(level0)) {
  static std::atomic<std::uint64_t> instances{0};
  id_ = ++instances;
  if (!supports(*level0_)) {
    throw InputError("Catmull–Clark levels: cell-by-cell levels need the clamped boundary rule (or a closed net)");
  }
  const mesh::PolyMesh& net = level0_->control_mesh();
  // The deepest level whose keys (and the next level's, which support() decodes) stay below 2^120, and whose
  // edges (about 2^-l of the net's shortest) stay 64 rounding units of the net's coordinates long.
  double shortest = HUGE_VAL, largest = 0;
  for (Index f = 0; f < net.num_faces(); ++f) {
    const auto fv = net.face(f);
    for (std::size_t j = 0; j < fv.size(); ++j) {
      shortest = std::min(shortest, (net.point(fv[j]) - net.point(fv[(j + 1) % fv.size()])).norm());
      largest = std::max(largest, net.point(fv[j]).cwiseAbs().maxCoeff());
    }
  }
  const double unit = std::nextafter(largest, HUGE_VAL) - largest;
  const Key limit = Key{1} << 120;
  bounds_ = key_bounds(net.num_faces(), net.num_vertices(), 0);
  while (max_level_ < kLevelCap && bounds_.faces.back() < limit / 8 && bounds_.vertex_bound.back() < limit / 8 &&
         std::ldexp(shortest, -(max_level_ + 1)) >= 64 * unit) {
    bounds_ = key_bounds(net.num_faces(), net.num_vertices(), max_level_ + 2);
    ++max_level_;
  }
  cells_.resize(static_cast<std::size_t>(max_level_) + 1);
  supports_.resize(static_cast<std::size_t>(max_level_) + 1);
  roots_.resize(static_cast<std::size_t>(net.num_faces()));
  root_ready_ = std::make_unique<std::atomic<const Cell*>[]>(roots_.size());
  for (std::size_t f = 0; f < roots_.size(); ++f) root_ready_[f].store(nullptr, std::memory_order_relaxed);

  vertex_faces_.resize(static_cast<std::size_t>(net.num_vertices()));
  for (Index f = 0; f < net.num_faces(); ++f) {
    if (net.face_size(f) != 4) throw std::logic_error("Catmull–Clark levels: the extended net has a non-quad face");
    for (Index v : net.face(f)) vertex_faces_[static_cast<std::size_t>(v)].push_back(f);
  }
  const Index ne = level0_->num_elements(), nv = level0_->num_dofs();
  support_offsets_.assign(static_cast<std::size_t>(nv) + 1, 0);
  for (Index e = 0; e < ne; ++e) {
    for (Index d : level0_->dofs(e)) ++support_offsets_[static_cast<std::size_t>(d) + 1];
  }
  for (Index v = 0; v < nv; ++v) support_offsets_[static_cast<std::size_t>(v) + 1] += support_offsets_[static_cast<std::size_t>(v)];
  support_cells_.resize(static_cast<std::size_t>(support_offsets_.back()));
  std::vector<Index> fill(support_offsets_.begin(), support_offsets_.end() - 1);
  for (Index e = 0; e < ne; ++e) {
    for (Index d : level0_->dofs(e)) support_cells_[static_cast<std::size_t>(fill[static_cast<std::size_t>(d)]++)] = e;
  }
  part_.assign(static_cast<std::size_t>(4 * ne), -1);
  for (const BoundaryEdge& e : level0_->boundary_edges()) {
    part_[static_cast<std::size_t>(4 * e.element + (e.side + level0_->rotation(e.element)) % 4)] = e.part;
  }
}

SparseCatmullClarkLevels::~SparseCatmullClarkLevels() = default;

bool SparseCatmullClarkLevels::in_domain(int level, Key face) const {
  return face < Key{level0_->num_elements()} << (2 * level);
}

std::size_t SparseCatmullClarkLevels::cells_made() const {
  const std::shared_lock<std::shared_mutex> lock(mutex_);
  std::size_t n = 0;
  for (const auto& m : cells_) n += m.size();
  for (const auto& c : roots_) n += c ? 1 : 0;
  return n;
}

const SparseCatmullClarkLevels::Cell& SparseCatmullClarkLevels::cell(int level, Key key) const {
  if (level < 0 || level > max_level_) {
    throw UnsupportedError("Catmull–Clark levels: level " + std::to_string(level) + " is beyond the deepest level " +
                           std::to_string(max_level_) + " (cell keys of 128 bits)");
  }
  if (level == 0) {
    const auto f = static_cast<std::size_t>(key);
    if (const Cell* c = root_ready_[f].load(std::memory_order_acquire)) return *c;
    std::unique_ptr<Cell> made = make_cell(0, key);
    const std::unique_lock<std::shared_mutex> lock(mutex_);
    if (!roots_[f]) {
      roots_[f] = std::move(made);
      root_ready_[f].store(roots_[f].get(), std::memory_order_release);
    }
    return *roots_[f];
  }
  auto& map = cells_[static_cast<std::size_t>(level)];
  {
    const std::shared_lock<std::shared_mutex> lock(mutex_);
    const auto it = map.find(key);
    if (it != map.end()) return *it->second;
  }
  std::unique_ptr<Cell> made = make_cell(level, key);  // may make its ancestors (the lock is not held)
  const std::unique_lock<std::shared_mutex> lock(mutex_);
  return *map.try_emplace(key, std::move(made)).first->second;
}

std::unique_ptr<SparseCatmullClarkLevels::Cell> SparseCatmullClarkLevels::make_cell(int level, Key key) const {
  auto c = std::make_unique<Cell>();
  if (level == 0) {
    const mesh::PolyMesh& net = level0_->control_mesh();
    const Index f0 = static_cast<Index>(key);
    std::vector<Index> faces{f0};
    for (Index v : net.face(f0)) {
      for (Index g : vertex_faces_[static_cast<std::size_t>(v)]) {
        if (std::find(faces.begin(), faces.end(), g) == faces.end()) faces.push_back(g);
      }
    }
    // Local vertex numbers by search among the few found so far (a net-sized table would cost every root cell the
    // whole net).
    for (Index g : faces) {
      std::array<int, 4> q{};
      const auto fv = net.face(g);
      for (int j = 0; j < 4; ++j) {
        const Key v = fv[static_cast<std::size_t>(j)];
        const auto at = std::find(c->mesh.vertex.begin(), c->mesh.vertex.end(), v);
        q[static_cast<std::size_t>(j)] = static_cast<int>(at - c->mesh.vertex.begin());
        if (at == c->mesh.vertex.end()) c->mesh.vertex.push_back(v);
      }
      c->mesh.corner.push_back(q);
      c->mesh.face.push_back(g);
    }
  } else {
    const Cell& parent = cell(level - 1, key / 4);
    const RefinedMesh r = refine_local(parent.mesh, bounds_, level - 1, false);
    c->mesh = extract_ring(r.mesh, static_cast<int>(key % 4));  // the parent is face 0: its children are 0..3
  }
  if (in_domain(level, key)) finish(level, *c);
  return c;
}

void SparseCatmullClarkLevels::finish(int level, Cell& c) const {
  const std::array<int, 4> n = corner_valences(c.mesh);
  for (int j = 0; j < 4; ++j) {
    if (n[static_cast<std::size_t>(j)] != 4) c.rotation = j;
  }
  const CanonicalMesh canonical = canonical_mesh(c.mesh, c.rotation);
  c.tmpl = &template_for(canonical);
  c.kind = c.tmpl->space->kind(0);
  if (c.kind.family == Family::Irregular) {
    // The template's domain is the cell alone; the extraordinary vertex is on the domain's boundary when a face
    // at it is a ghost.
    const int ev = c.mesh.corner[0][static_cast<std::size_t>(c.rotation)];
    c.kind.boundary = false;
    for (std::size_t f = 0; f < c.mesh.face.size(); ++f) {
      const auto& q = c.mesh.corner[f];
      if (std::find(q.begin(), q.end(), ev) != q.end() && !in_domain(level, c.mesh.face[f])) c.kind.boundary = true;
    }
  }
  const auto dofs = c.tmpl->space->dofs(0);
  c.function_of.assign(c.mesh.vertex.size(), -1);
  for (std::size_t i = 0; i < dofs.size(); ++i) {
    const int local = canonical.canonical[static_cast<std::size_t>(dofs[i])];
    c.functions.push_back(c.mesh.vertex[static_cast<std::size_t>(local)]);
    c.function_of[static_cast<std::size_t>(local)] = static_cast<int>(i);
  }
}

const SparseCatmullClarkLevels::Template& SparseCatmullClarkLevels::template_for(const CanonicalMesh& canonical) const {
  const std::lock_guard<std::mutex> lock(template_mutex_);
  for (const auto& t : templates_) {
    if (t->faces == canonical.faces) return *t;
  }
  auto t = std::make_unique<Template>();
  t->faces = canonical.faces;
  std::vector<Eigen::Vector3d> points;
  for (std::size_t i = 0; i < canonical.canonical.size(); ++i) points.emplace_back(static_cast<double>(i), 0.0, 0.0);
  ExtendedNet net{mesh::PolyMesh::build(std::move(points), canonical.faces), 1};
  t->space = std::make_unique<CatmullClarkSpace>(std::move(net), "cell neighbourhood");
  if (t->space->num_elements() != 1 || t->space->rotation(0) != 0 ||
      static_cast<std::size_t>(t->space->dofs(0).size()) != canonical.canonical.size()) {
    throw std::logic_error("Catmull–Clark levels: a cell's neighbourhood is not its one-ring");
  }
  templates_.push_back(std::move(t));
  return *templates_.back();
}


int SparseCatmullClarkLevels::rotation(int l, Key c) const { return cell(l, c).rotation; }

int SparseCatmullClarkLevels::local_functions(int l, Key c, Key* out) const {
  const Cell& x = cell(l, c);
  std::copy(x.functions.begin(), x.functions.end(), out);
  return static_cast<int>(x.functions.size());
}

void SparseCatmullClarkLevels::evaluate(int l, Key c, const Eigen::Matrix2Xd& pts, int derivatives,
                                        BasisValues& out) const {
  cell(l, c).tmpl->space->evaluate(0, pts, derivatives, out);
}

ElementKind SparseCatmullClarkLevels::kind(int l, Key c) const { return cell(l, c).kind; }

int SparseCatmullClarkLevels::native_part(int l, Key c, int native_side) const {
  for (; l > 0; --l) {
    const int slot = static_cast<int>(c % 4);
    if (native_side != slot && native_side != (slot + 3) % 4) return -1;  // inside the parent
    c /= 4;
  }
  return part_[static_cast<std::size_t>(4 * static_cast<Index>(c) + native_side)];
}

int SparseCatmullClarkLevels::boundary_part(int l, Key c, int side) const {
  return native_part(l, c, (side + cell(l, c).rotation) % 4);
}

Key SparseCatmullClarkLevels::neighbour(int l, Key c, int side, int& their_side) const {
  const Cell& x = cell(l, c);
  const int s = (side + x.rotation) % 4;
  const int a = x.mesh.corner[0][static_cast<std::size_t>(s)], z = x.mesh.corner[0][static_cast<std::size_t>((s + 1) % 4)];
  for (std::size_t f = 1; f < x.mesh.face.size(); ++f) {
    const auto& q = x.mesh.corner[f];
    for (int t = 0; t < 4; ++t) {
      if (q[static_cast<std::size_t>(t)] != z || q[static_cast<std::size_t>((t + 1) % 4)] != a) continue;
      const Key g = x.mesh.face[f];
      if (!in_domain(l, g)) break;
      their_side = (t - cell(l, g).rotation + 4) % 4;
      return g;
    }
  }
  their_side = -1;
  return -1;
}

Key SparseCatmullClarkLevels::corner_cell(int l, Key v, int& at) const {
  if (l == 0) {
    const auto& faces = vertex_faces_[static_cast<std::size_t>(v)];
    const auto it = std::find_if(faces.begin(), faces.end(), [&](Index f) { return in_domain(0, f); });
    const Index f = it != faces.end() ? *it : faces.front();
    const auto fv = level0_->control_mesh().face(f);
    at = static_cast<int>(std::find(fv.begin(), fv.end(), static_cast<Index>(v)) - fv.begin());
    return f;
  }
  const VertexOrigin o = vertex_origin(bounds_, l, v);
  switch (o.kind) {
    case VertexOrigin::kFace:  // corner 2 of child 0
      at = 2;
      return 4 * o.key;
    case VertexOrigin::kEdge:  // corner s + 1 of child s
      at = (o.side + 1) % 4;
      return 4 * o.key + o.side;
    case VertexOrigin::kVertex:
      break;
  }
  const Key c = corner_cell(l - 1, o.key, at);  // corner `at` of c is corner `at` of its child `at`
  return 4 * c + at;
}

void SparseCatmullClarkLevels::support(int l, Key function, std::vector<Key>& cells) const {
  cells.clear();
  if (l == 0) {
    const auto f = static_cast<std::size_t>(function);
    cells.assign(support_cells_.begin() + support_offsets_[f], support_cells_.begin() + support_offsets_[f + 1]);
    return;
  }
  auto& known = supports_[static_cast<std::size_t>(l)];
  {
    const std::shared_lock<std::shared_mutex> lock(mutex_);
    const auto it = known.find(function);
    if (it != known.end()) {
      cells.assign(it->second.begin(), it->second.end());
      return;
    }
  }
  // A coarse cell next to the function's vertex: the fine faces whose rings hold the vertex are children of faces
  // in that cell's ring.
  const VertexOrigin o = vertex_origin(bounds_, l, function);
  int at = 0;
  const Key coarse = o.kind == VertexOrigin::kVertex ? corner_cell(l - 1, o.key, at) : o.key;
  const RefinedMesh r = refine_local(cell(l - 1, coarse).mesh, bounds_, l - 1, false);
  const LocalMesh& m = r.mesh;
  const auto v = std::find(m.vertex.begin(), m.vertex.end(), function);
  if (v == m.vertex.end()) throw std::logic_error("Catmull–Clark levels: a function's vertex is not near its origin");
  const int vi = static_cast<int>(v - m.vertex.begin());
  std::vector<char> near(m.vertex.size(), 0);
  for (const auto& q : m.corner) {
    if (std::find(q.begin(), q.end(), vi) == q.end()) continue;
    for (int u : q) near[static_cast<std::size_t>(u)] = 1;
  }
  for (std::size_t f = 0; f < m.face.size(); ++f) {
    const auto& q = m.corner[f];
    const bool touches = std::any_of(q.begin(), q.end(), [&](int u) { return near[static_cast<std::size_t>(u)] != 0; });
    if (touches && in_domain(l, m.face[f])) cells.push_back(m.face[f]);
  }
  const std::unique_lock<std::shared_mutex> lock(mutex_);
  known.try_emplace(function, cells);
}

// The hierarchical builds ask refinement() for the four slots of a cell in turn, with deeper levels in between, and
// for neighbouring cells in between too: the last 16 refined neighbourhoods per level and thread are kept
// (direct-mapped by the cell key's low bits, a few MB per thread), so the local step mostly runs once per cell.
const RefinedMesh& SparseCatmullClarkLevels::refined(int l, Key c) const {
  struct Entry {
    std::uint64_t owner = 0;
    Key cell = -1;
    RefinedMesh mesh;
  };
  constexpr std::size_t kWays = 16;  // per level, direct-mapped by the cell's low bits
  thread_local std::vector<Entry> cache;
  if (cache.size() < kWays * (static_cast<std::size_t>(l) + 1)) cache.resize(kWays * (static_cast<std::size_t>(l) + 1));
  Entry& e = cache[kWays * static_cast<std::size_t>(l) + (static_cast<std::size_t>(c) & (kWays - 1))];
  if (e.owner != id_ || e.cell != c) {
    e.mesh = refine_local(cell(l, c).mesh, bounds_, l);
    e.owner = id_;
    e.cell = c;
  }
  return e.mesh;
}

void SparseCatmullClarkLevels::refinement(int l, Key c, int slot, Eigen::MatrixXd& k) const {
  const Cell& p = cell(l, c);
  const Cell& ch = cell(l + 1, 4 * c + slot);
  const RefinedMesh& r = refined(l, c);
  k.setZero(static_cast<Eigen::Index>(p.functions.size()), static_cast<Eigen::Index>(ch.functions.size()));
  for (std::size_t j = 0; j < ch.functions.size(); ++j) {
    const auto v = std::find(r.mesh.vertex.begin(), r.mesh.vertex.end(), ch.functions[j]);
    const auto stencil = v == r.mesh.vertex.end() ? std::span<const std::pair<int, double>>{}
                                                   : r.stencil(static_cast<int>(v - r.mesh.vertex.begin()));
    if (stencil.empty()) throw std::logic_error("Catmull–Clark levels: a child's function has no stencil in its parent's ring");
    for (const auto& [u, w] : stencil) {
      const int i = p.function_of[static_cast<std::size_t>(u)];
      if (i < 0) throw std::logic_error("Catmull–Clark levels: a stencil reads a vertex outside the parent's ring");
      k(i, static_cast<Eigen::Index>(j)) = w;
    }
  }
}

}  // namespace iga::basis::catmull_clark
