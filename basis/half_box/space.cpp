#include "basis/half_box/space.hpp"

#include <algorithm>
#include <stdexcept>

#include "basis/half_box/dependency.hpp"
#include "basis/half_box/exact_view.hpp"
#include "basis/half_box/irregular_patch.hpp"
#include "basis/half_box/patch_net.hpp"
#include "basis/half_box/subdivision.hpp"
#include "core/error.hpp"
#include "mesh/three_valent.hpp"

namespace iga::basis::half_box {
namespace {

// The net vertex across side i of a patch: the neighbour of its vertex shared by F_i and F_{i+1}
// (patch_net.hpp orders: regular u0, u1, u2 = points 1, 2, 3; EF patch n − 1, n + 3, 1).
std::array<Index, 3> across_sides(const PatchNet& p) {
  const auto& q = p.points;
  if (p.valence == 6) return {q[1], q[2], q[3]};
  const auto n = static_cast<std::size_t>(p.valence);
  return {q[n - 1], q[n + 3], q[1]};
}

bool has_three_faces(const mesh::PolyMesh& net, Index v) {
  return net.valence(v) == 3 && net.num_vertex_faces(v) == 3;
}

}  // namespace

HalfBoxSpace::HalfBoxSpace(const mesh::PolyMesh& net, const std::string& name) : net_(net) {
  mesh::check_three_valent(net_, name);
  if (!efs_separated(net_)) {
    // Two extraordinary faces at a vertex: one step shrinks every face inside a ring of new hexagons.
    net_ = net_.is_closed() ? subdivide(net_).net : subdivide_local(net_).net;
    steps_ = 1;
  }
  build_elements(name);
  build_boundary();
}

void HalfBoxSpace::build_elements(const std::string& name) {
  std::vector<Index> dof_of_vertex(static_cast<std::size_t>(net_.num_vertices()), -1);
  for (Index v = 0; v < net_.num_vertices(); ++v) {
    if (!has_three_faces(net_, v)) continue;
    PatchNet p;
    try {
      p = patch_net(net_, v);
    } catch (const InputError& e) {
      throw InputError(name, 0, e.what());
    }
    Element el;
    el.vertex = v;
    el.kind = p.valence == 6 ? ElementKind{Shape::Triangle, Family::Regular, 6}
                             : ElementKind{Shape::Triangle, Family::Irregular, p.valence, false, Scheme::HalfBox};
    el.across = across_sides(p);
    el.dofs = std::move(p.points);
    for (Index w : el.dofs) dof_of_vertex[static_cast<std::size_t>(w)] = 0;
    elements_.push_back(std::move(el));
  }
  if (elements_.empty()) throw InputError(name, 0, "no net vertex has three faces: the net has no half-box patch");
  // A global dependency (dependency.hpp): the function of the last used vertex is a combination of the others
  // and is left out, so the remaining functions are a basis of the same space.
  std::vector<PatchPoints> patches;
  for (const Element& el : elements_) patches.push_back({el.kind.valence, &el.dofs});
  const Eigen::VectorXd c = alternating_dependency(net_, patches);
  if (c.size() > 0) {
    for (Index v = net_.num_vertices() - 1; v >= 0 && removed_vertex_ < 0; --v) {
      if (dof_of_vertex[static_cast<std::size_t>(v)] == 0) removed_vertex_ = v;
    }
    dof_of_vertex[static_cast<std::size_t>(removed_vertex_)] = -1;
  }
  for (Index v = 0; v < net_.num_vertices(); ++v) {
    if (dof_of_vertex[static_cast<std::size_t>(v)] < 0) continue;
    dof_of_vertex[static_cast<std::size_t>(v)] = static_cast<Index>(vertex_of_dof_.size());
    vertex_of_dof_.push_back(v);
    if (c.size() > 0) dependency_.push_back(c(v) / c(removed_vertex_));
  }
  for (Element& el : elements_) {
    std::vector<Index> local;
    for (std::size_t i = 0; i < el.dofs.size(); ++i) {
      if (el.dofs[i] == removed_vertex_) {
        el.removed = static_cast<int>(i);
      } else {
        local.push_back(dof_of_vertex[static_cast<std::size_t>(el.dofs[i])]);
      }
    }
    el.dofs = std::move(local);
    max_local_ = std::max(max_local_, static_cast<Index>(el.dofs.size()));
  }
}

Eigen::SparseMatrix<double> HalfBoxSpace::from_vertices() const {
  std::vector<Eigen::Triplet<double>> entries;
  for (Index d = 0; d < num_dofs(); ++d) {
    entries.emplace_back(d, vertex(d), 1.0);
    if (removed_vertex_ >= 0) entries.emplace_back(d, removed_vertex_, -dependency_[static_cast<std::size_t>(d)]);
  }
  Eigen::SparseMatrix<double> r(num_dofs(), net_.num_vertices());
  r.setFromTriplets(entries.begin(), entries.end());
  return r;
}

Eigen::MatrixXd HalfBoxSpace::patch_map(Index e) const {
  const Element& el = elements_[static_cast<std::size_t>(e)];
  const auto n = static_cast<Index>(el.dofs.size());
  Eigen::MatrixXd s = Eigen::MatrixXd::Zero(n + (el.removed >= 0 ? 1 : 0), n);
  for (Index i = 0; i < n; ++i) s(i + (el.removed >= 0 && i >= el.removed ? 1 : 0), i) = 1.0;
  return s;
}

void HalfBoxSpace::build_boundary() {
  for (Index e = 0; e < num_elements(); ++e) {
    for (int side = 0; side < 3; ++side) {
      if (!has_three_faces(net_, elements_[static_cast<std::size_t>(e)].across[static_cast<std::size_t>(side)])) {
        boundary_.push_back({e, side, 0});
      }
    }
  }
}

std::span<const Index> HalfBoxSpace::dofs(Index e) const { return elements_[static_cast<std::size_t>(e)].dofs; }

void HalfBoxSpace::evaluate(Index e, const Eigen::Matrix2Xd& pts, int derivatives, BasisValues& out) const {
  const Element& el = elements_[static_cast<std::size_t>(e)];
  if (el.removed < 0) {
    evaluate_patch(el.kind.valence, pts, derivatives, out);
    return;
  }
  // The patch's functions without the one left out (the space's dependency).
  thread_local BasisValues full;
  evaluate_patch(el.kind.valence, pts, derivatives, full);
  const Eigen::Index m = full.value.rows(), r = el.removed, q = pts.cols();
  out.resize(m - 1, q, derivatives);
  BasisValues::for_each_block(full, out, derivatives, [&](const Eigen::MatrixXd& from, Eigen::MatrixXd& to) {
    to.topRows(r) = from.topRows(r);
    to.bottomRows(m - 1 - r) = from.bottomRows(m - 1 - r);
  });
}

std::optional<SubdivisionElement> HalfBoxSpace::subdivision_element(Index e) const {
  const Element& el = elements_[static_cast<std::size_t>(e)];
  if (el.kind.family != Family::Irregular) return std::nullopt;
  return SubdivisionElement{&half_box_view(el.kind.valence), patch_map(e), 0, {}};
}

Geometry make_half_box_geometry(const mesh::PolyMesh& net, const std::string& name) {
  auto space = std::make_shared<const HalfBoxSpace>(net, name);
  const int dim = net.is_planar() ? 2 : 3;
  const mesh::PolyMesh& n = space->control_net();
  Eigen::MatrixXd positions(n.num_vertices(), dim);
  for (Index v = 0; v < n.num_vertices(); ++v) positions.row(v) = n.point(v).head(dim).transpose();
  Eigen::MatrixXd cp = space->from_vertices() * positions;
  return Geometry(space, std::move(cp));
}

std::vector<InteriorEdge> HalfBoxSpace::interior_edges() const {
  std::vector<Index> element_of(static_cast<std::size_t>(net_.num_vertices()), -1);
  for (Index e = 0; e < num_elements(); ++e) element_of[static_cast<std::size_t>(element_vertex(e))] = e;
  std::vector<InteriorEdge> edges;
  edges.reserve(static_cast<std::size_t>(3 * num_elements() / 2));
  for (Index e = 0; e < num_elements(); ++e) {
    const Element& el = elements_[static_cast<std::size_t>(e)];
    for (int side = 0; side < 3; ++side) {
      const Index o = element_of[static_cast<std::size_t>(el.across[static_cast<std::size_t>(side)])];
      if (o <= e) continue;  // no patch there (a boundary side), or listed from the other element
      const auto& back = elements_[static_cast<std::size_t>(o)].across;
      const auto it = std::find(back.begin(), back.end(), el.vertex);
      if (it == back.end()) throw std::logic_error("half-box: patch sides of a net edge do not match");
      edges.push_back({{e, o}, {side, static_cast<int>(it - back.begin())}, {0.0, 1.0}, {1.0, 0.0}, 1});
    }
  }
  return edges;
}

}  // namespace iga::basis::half_box
