#include "basis/hierarchical/hierarchical_space.hpp"

#include <algorithm>
#include <cmath>

#include "core/error.hpp"

namespace iga::basis::hierarchical {

std::string to_string(Key k) {
  if (k == 0) return "0";
  const bool negative = k < 0;
  std::string digits;
  for (Key v = negative ? -k : k; v > 0; v /= 10) digits.insert(digits.begin(), static_cast<char>('0' + static_cast<int>(v % 10)));
  return negative ? "-" + digits : digits;
}

HierarchicalSpace::HierarchicalSpace(std::shared_ptr<const LevelHierarchy> hierarchy, RefinedCells refined)
    : hierarchy_(std::move(hierarchy)), refined_(std::move(refined)) {
  if (!hierarchy_) throw InputError("hierarchical space: no level hierarchy given");
  trim_and_check_depth();
  for (std::size_t l = 0; l < refined_.size(); ++l) {
    for (Key c : refined_[l]) {
      if (!exists(static_cast<int>(l), c)) {
        throw InputError("hierarchical space: refined cell " + to_string(c) + " of level " + std::to_string(l) +
                         " lies outside the refined region of level " + std::to_string(l));
      }
    }
  }
  build();
}

void HierarchicalSpace::trim_and_check_depth() {
  while (!refined_.empty() && refined_.back().empty()) refined_.pop_back();
  if (static_cast<int>(refined_.size()) > hierarchy_->max_level()) {
    throw UnsupportedError("hierarchical space: level " + std::to_string(refined_.size()) +
                           " is deeper than the " + std::to_string(hierarchy_->max_level()) + " levels the '" +
                           hierarchy_->name() + "' hierarchy " + hierarchy_->depth_limit());
  }
}

bool HierarchicalSpace::exists(int level, Key cell) const {
  if (level == 0) return cell >= 0 && cell < hierarchy_->num_root_cells();
  int slot = 0;
  return is_refined(level - 1, hierarchy_->parent(level, cell, slot));
}

bool HierarchicalSpace::is_refined(int level, Key cell) const {
  return level >= 0 && level < static_cast<int>(refined_.size()) &&
         refined_[static_cast<std::size_t>(level)].count(cell) > 0;
}

Index HierarchicalSpace::element_of(int level, Key cell) const {
  if (level < 0 || level >= static_cast<int>(leaf_index_.size())) return -1;
  const auto& map = leaf_index_[static_cast<std::size_t>(level)];
  const auto it = map.find(cell);
  return it == map.end() ? -1 : it->second;
}

Index HierarchicalSpace::leaf_containing(int level, Key cell) const {
  if (is_refined(level, cell)) return -1;
  int slot = 0;
  while (level > 0 && !exists(level, cell)) {
    cell = hierarchy_->parent(level, cell, slot);
    --level;
  }
  return element_of(level, cell);
}

std::optional<int> HierarchicalSpace::polynomial_degree(Index e) const {
  const Element& el = elements_[static_cast<std::size_t>(e)];
  return hierarchy_->polynomial_degree(el.level, el.cell);
}

ElementKind HierarchicalSpace::kind(Index e) const {
  const Element& el = elements_[static_cast<std::size_t>(e)];
  return hierarchy_->kind(el.level, el.cell);
}

std::span<const Index> HierarchicalSpace::dofs(Index e) const {
  const Element& el = elements_[static_cast<std::size_t>(e)];
  return {dofs_.data() + el.dof_begin, static_cast<std::size_t>(el.dof_end - el.dof_begin)};
}

void HierarchicalSpace::evaluate(Index e, const Eigen::Matrix2Xd& pts, int derivatives, BasisValues& out) const {
  const Element& el = elements_[static_cast<std::size_t>(e)];
  if (el.coeff == nullptr) {
    hierarchy_->evaluate(el.level, el.cell, pts, derivatives, out);
    return;
  }
  thread_local BasisValues local;
  hierarchy_->evaluate(el.level, el.cell, pts, derivatives, local);
  const Eigen::Map<const Eigen::MatrixXd> c(el.coeff, el.dof_end - el.dof_begin, el.num_local);
  out.resize(c.rows(), pts.cols(), derivatives);
  BasisValues::for_each_block(local, out, derivatives,
                              [&](const Eigen::MatrixXd& from, Eigen::MatrixXd& to) { to.noalias() = c * from; });
}

std::vector<BoundaryEdge> HierarchicalSpace::boundary_edges() const {
  std::vector<BoundaryEdge> edges;
  for (Index e = 0; e < num_elements(); ++e) {
    const Element& el = elements_[static_cast<std::size_t>(e)];
    for (int side = 0; side < 4; ++side) {
      const int part = hierarchy_->boundary_part(el.level, el.cell, side);
      if (part >= 0) edges.push_back({e, side, part});
    }
  }
  std::stable_sort(edges.begin(), edges.end(), [](const BoundaryEdge& a, const BoundaryEdge& b) { return a.part < b.part; });
  return edges;
}

namespace {
// Side and side parameter of a point on the boundary of the unit square (side_point's inverse).
bool square_side_parameter(const Eigen::Vector2d& p, int side, double& t) {
  constexpr double tol = 1e-12;
  switch (side) {
    case 0: t = p.x(); return std::abs(p.y()) < tol;
    case 1: t = p.y(); return std::abs(p.x() - 1) < tol;
    case 2: t = 1 - p.x(); return std::abs(p.y() - 1) < tol;
    default: t = 1 - p.y(); return std::abs(p.x()) < tol;
  }
}
}  // namespace

std::vector<InteriorEdge> HierarchicalSpace::interior_edges() const {
  const LevelHierarchy& h = *hierarchy_;
  std::vector<InteriorEdge> edges;
  Eigen::Matrix2d a;
  Eigen::Vector2d b;
  for (Index e = 0; e < num_elements(); ++e) {
    const Element& el = elements_[static_cast<std::size_t>(e)];
    for (int side = 0; side < 4; ++side) {
      if (h.boundary_part(el.level, el.cell, side) >= 0) continue;
      int their = 0;
      const Key n = h.neighbour(el.level, el.cell, side, their);
      InteriorEdge edge;
      edge.element[0] = e;
      edge.side[0] = side;
      edge.continuity = h.continuity(el.level, el.cell, side);
      if (exists(el.level, n)) {
        if (is_refined(el.level, n) || n < el.cell) continue;  // the finer side, or the other element, lists it
        edge.element[1] = element_of(el.level, n);
        edge.side[1] = their;
        edges.push_back(edge);
        continue;
      }
      // A coarser leaf: map the ends of the shared side (s = 0 is the neighbour's side parameter 1) up to it.
      Eigen::Vector2d p0 = side_point(Shape::Quad, their, 1.0), p1 = side_point(Shape::Quad, their, 0.0);
      int level = el.level;
      Key cell = n;
      while (!exists(level, cell)) {
        int slot = 0;
        cell = h.parent(level, cell, slot);
        --level;
        h.child_map(level, cell, slot, a, b);
        p0 = a * p0 + b;
        p1 = a * p1 + b;
      }
      edge.element[1] = element_of(level, cell);
      for (int s = 0; s < 4; ++s) {
        double t0 = 0, t1 = 0;
        if (square_side_parameter(p0, s, t0) && square_side_parameter(p1, s, t1)) {
          edge.side[1] = s;
          edge.t0[1] = t0;
          edge.t1[1] = t1;
          break;
        }
      }
      edges.push_back(edge);
    }
  }
  return edges;
}

Eigen::MatrixXd HierarchicalSpace::coefficients_by_descent(
    Index columns, const std::function<bool(int, Key, Eigen::MatrixXd&)>& source) const {
  const LevelHierarchy& h = *hierarchy_;
  Eigen::MatrixXd out = Eigen::MatrixXd::Zero(num_dofs(), columns);
  Eigen::MatrixXd k;
  // v: a spline's local coefficients (level-local functions × columns) on the cell, from the first cell where
  // `source` knows them, refined down the forest; at a leaf, the coefficient of each dof at home there is its
  // local coefficient (the dual functional).
  auto visit = [&](auto&& self, int level, Key cell, const Eigen::MatrixXd* v) -> void {
    Eigen::MatrixXd here;
    if (!v && source(level, cell, here)) v = &here;
    const Index e = element_of(level, cell);
    if (e >= 0) {
      if (!v) throw InputError("hierarchical coefficients: the spaces are not nested");
      const Element& el = elements_[static_cast<std::size_t>(e)];
      for (Index i = el.dof_begin; i < el.dof_end; ++i) {
        const Index d = dofs_[static_cast<std::size_t>(i)];
        if (dof_home_[static_cast<std::size_t>(d)] == e) out.row(d) = v->row(dof_home_local_[static_cast<std::size_t>(d)]);
      }
      return;
    }
    for (int slot = 0; slot < 4; ++slot) {
      if (v) {
        h.refinement(level, cell, slot, k);
        const Eigen::MatrixXd next = k.transpose() * *v;
        self(self, level + 1, h.child(level, cell, slot), &next);
      } else {
        self(self, level + 1, h.child(level, cell, slot), nullptr);
      }
    }
  };
  for (Index r = 0; r < h.num_root_cells(); ++r) visit(visit, 0, Key{r}, nullptr);
  return out;
}

Eigen::MatrixXd HierarchicalSpace::from_level0(const Eigen::MatrixXd& c0, Index level0_functions) const {
  if (c0.rows() != level0_functions) {
    throw InputError("hierarchical space: " + std::to_string(c0.rows()) + " level-0 coefficients for " +
                     std::to_string(level0_functions) + " level-0 functions");
  }
  std::vector<Key> fbuf(static_cast<std::size_t>(hierarchy_->max_local_functions()));
  return coefficients_by_descent(c0.cols(), [&](int level, Key cell, Eigen::MatrixXd& v) {
    if (level != 0) return false;
    const int n = hierarchy_->local_functions(0, cell, fbuf.data());
    v.resize(n, c0.cols());
    for (int j = 0; j < n; ++j) v.row(j) = c0.row(static_cast<Index>(fbuf[static_cast<std::size_t>(j)]));
    return true;
  });
}

Eigen::SparseMatrix<double> HierarchicalSpace::prolongation_from(const HierarchicalSpace& coarse) const {
  if (built_from(coarse)) return prolongation_from_previous(coarse);
  const LevelHierarchy& h = *hierarchy_;
  std::vector<Eigen::Triplet<double>> entries;
  Eigen::MatrixXd k;
  // w: the coarse functions that do not vanish on the cell (ids) in the cell level's local functions, known
  // from the coarse leaf down.
  auto visit = [&](auto&& self, int level, Key cell, std::span<const Index> ids, const Eigen::MatrixXd& w) -> void {
    std::span<const Index> rows = ids;
    Eigen::MatrixXd here;
    const Eigen::MatrixXd* cur = &w;
    if (rows.empty()) {
      const Index ce = coarse.element_of(level, cell);
      if (ce >= 0) {
        const Element& cel = coarse.elements_[static_cast<std::size_t>(ce)];
        rows = coarse.dofs(ce);
        here = coarse.element_coefficients(cel);
        cur = &here;
      }
    }
    const Index e = element_of(level, cell);
    if (e >= 0) {
      if (rows.empty()) {
        throw InputError("hierarchical prolongation: the spaces are not nested (the coarse space refines cell " +
                         to_string(cell) + " of level " + std::to_string(level) + ", the fine one does not)");
      }
      const Element& el = elements_[static_cast<std::size_t>(e)];
      for (Index i = el.dof_begin; i < el.dof_end; ++i) {
        const Index d = dofs_[static_cast<std::size_t>(i)];
        if (dof_home_[static_cast<std::size_t>(d)] != e) continue;
        const int j = dof_home_local_[static_cast<std::size_t>(d)];
        for (std::size_t r = 0; r < rows.size(); ++r) {
          const double v = (*cur)(static_cast<Index>(r), j);
          if (std::abs(v) > 1e-15) entries.emplace_back(d, rows[r], v);
        }
      }
      return;
    }
    for (int slot = 0; slot < 4; ++slot) {
      Eigen::MatrixXd next;
      if (!rows.empty()) {
        h.refinement(level, cell, slot, k);
        next = *cur * k;
      }
      self(self, level + 1, h.child(level, cell, slot), rows, next);
    }
  };
  for (Index c = 0; c < h.num_root_cells(); ++c) visit(visit, 0, Key{c}, {}, Eigen::MatrixXd());
  Eigen::SparseMatrix<double> p(num_dofs(), coarse.num_dofs());
  p.setFromTriplets(entries.begin(), entries.end());
  return p;
}

Eigen::MatrixXd HierarchicalSpace::coefficients_from(const HierarchicalSpace& coarse, const Eigen::MatrixXd& c) const {
  if (c.rows() != coarse.num_dofs()) throw InputError("hierarchical coefficients: size mismatch");
  return coefficients_by_descent(c.cols(), [&](int level, Key cell, Eigen::MatrixXd& v) {
    const Index ce = coarse.element_of(level, cell);
    if (ce < 0) return false;
    const Element& cel = coarse.elements_[static_cast<std::size_t>(ce)];
    const auto rows = coarse.dofs(ce);
    Eigen::MatrixXd local(static_cast<Index>(rows.size()), c.cols());
    for (std::size_t r = 0; r < rows.size(); ++r) local.row(static_cast<Index>(r)) = c.row(rows[r]);
    if (cel.coeff == nullptr) {
      v = local;
    } else {
      v = Eigen::Map<const Eigen::MatrixXd>(cel.coeff, cel.dof_end - cel.dof_begin, cel.num_local).transpose() * local;
    }
    return true;
  });
}

}  // namespace iga::basis::hierarchical
