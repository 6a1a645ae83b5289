#include "basis/catmull_clark/space.hpp"

#include "basis/catmull_clark/exact_view.hpp"

#include <algorithm>
#include <array>
#include <stdexcept>

#include "basis/catmull_clark/quad_mesh.hpp"
#include "basis/catmull_clark/regular_patch.hpp"
#include "core/error.hpp"

namespace iga::basis::catmull_clark {

namespace {

bool is_extraordinary(const mesh::PolyMesh& m, Index v) {
  if (m.is_boundary_vertex(v)) return m.num_vertex_faces(v) >= 3;
  return m.valence(v) != 4;
}

int ev_valence(const mesh::PolyMesh& m, Index v) {
  return m.is_boundary_vertex(v) ? m.num_vertex_faces(v) + 1 : m.valence(v);
}

// Boundary vertices with more faces than this are refused (clamped: k faces become interior valence k + 2).
int max_boundary_faces(BoundaryRule rule) { return rule == BoundaryRule::kClamped ? 14 : 15; }

void validate(const mesh::PolyMesh& m, const std::string& name, BoundaryRule rule) {
  check_no_isolated_vertices(m, name);
  for (Index v = 0; v < m.num_vertices(); ++v) {
    if (!m.is_boundary_vertex(v)) {
      if (m.valence(v) < 3) {
        throw InputError(name, m.vertex_line(v), "interior vertex " + std::to_string(v + 1) + " has valence " +
                         std::to_string(m.valence(v)) + " (at least 3 needed)");
      }
      if (m.valence(v) > 16) {
        throw InputError(name, m.vertex_line(v), "interior vertex " + std::to_string(v + 1) + " has valence " +
                         std::to_string(m.valence(v)) + " (at most 16 supported)");
      }
    } else if (m.num_vertex_faces(v) > max_boundary_faces(rule)) {
      throw InputError(name, m.vertex_line(v), "boundary vertex " + std::to_string(v + 1) + " has " +
                       std::to_string(m.num_vertex_faces(v)) + " faces (at most " +
                       std::to_string(max_boundary_faces(rule)) + " supported" +
                       (rule == BoundaryRule::kClamped ? " with the clamped boundary" : "") + ")");
    }
  }
}

// Stam's 2n+8 points (stam.hpp ordering) of face 0 of a one-ring with the EV at corner 0, or empty if the EV
// is not interior or a corner c1..c3 is not a regular interior vertex.
std::vector<int> stam_points(const QuadMesh& m) {
  std::vector<int> idx{0};
  int h = 0, n = 0;
  do {
    idx.push_back(m.target(h));
    idx.push_back(m.origin(QuadMesh::next(QuadMesh::next(h))));
    h = m.ccw(h);
    ++n;
  } while (h > 0 && n <= 16);
  if (h != 0) return {};
  std::array<std::array<int, 3>, 4> outer{};
  for (int i = 1; i <= 3; ++i) {
    if (!is_regular_corner(m, i)) return {};
    outer[static_cast<std::size_t>(i)] = corner_outer_points(m, i);
    for (int v : outer[static_cast<std::size_t>(i)]) {
      if (v < 0) return {};
    }
  }
  // (2,-1), (2,0) from c1; (2,1), (2,2), (1,2) from c2; (0,2), (-1,2) from c3 (each corner's A, D, B).
  idx.insert(idx.end(), {outer[1][1], outer[1][2], outer[2][0], outer[2][1], outer[2][2], outer[3][0], outer[3][1]});
  return idx;
}

// Whether some face of [0, faces) is not a quad or touches more than one EV.
bool needs_global_step(const mesh::PolyMesh& m, Index faces) {
  for (Index f = 0; f < faces; ++f) {
    if (m.face_size(f) != 4) return true;
    int evs = 0;
    for (Index v : m.face(f)) evs += is_extraordinary(m, v) ? 1 : 0;
    if (evs > 1) return true;
  }
  return false;
}

}  // namespace

BoundaryRule boundary_rule(const std::string& word) {
  if (word == "natural") return BoundaryRule::kNatural;
  if (word == "clamped") return BoundaryRule::kClamped;
  throw InputError("Catmull–Clark boundary rule '" + word + "': unknown (known: natural, clamped)");
}

std::string to_string(BoundaryRule rule) { return rule == BoundaryRule::kClamped ? "clamped" : "natural"; }

CatmullClarkSpace::CatmullClarkSpace(const mesh::PolyMesh& mesh, const std::string& name, IrregularMethod method,
                                     BoundaryRule boundary)
    : boundary_(boundary) {
  validate(mesh, name, boundary);
  const bool clamped = boundary == BoundaryRule::kClamped;
  ExtendedNet ext = clamped ? extend_net(mesh, name) : ExtendedNet{mesh, mesh.num_faces()};
  if (needs_global_step(ext.mesh, ext.domain_faces)) {
    for (Index f = 0; f < mesh.num_faces(); ++f) {
      if (mesh.face_size(f) > 16) {
        throw InputError(name, mesh.face_line(f), "face " + std::to_string(f + 1) + " has " + std::to_string(mesh.face_size(f)) +
                         " sides (at most 16 supported: its face point becomes an EV of that valence)");
      }
    }
  }
  // One step makes every face a quad and separates EVs that share an edge or a quad; a face that was not a
  // quad and had an EV corner gives a child with two EVs (its face point and the vertex): a second step.
  while (needs_global_step(ext.mesh, ext.domain_faces)) {
    if (steps_ == 2) throw std::logic_error("catmull_clark: EVs not separated after two steps");
    if (clamped) {
      ext = refine_extended(ext, 1).net;
    } else {
      ext.mesh = refine_net(ext.mesh, 1).mesh;
      ext.domain_faces = ext.mesh.num_faces();
    }
    ++steps_;
  }
  net_ = std::move(ext.mesh);
  build(name, method, ext.domain_faces);
}

CatmullClarkSpace::CatmullClarkSpace(ExtendedNet net, const std::string& name) : boundary_(BoundaryRule::kClamped) {
  if (needs_global_step(net.mesh, net.domain_faces)) {
    throw std::logic_error("catmull_clark: an extended net given to the space needs a global step");
  }
  net_ = std::move(net.mesh);
  build(name, IrregularMethod::kStam, net.domain_faces);
}

void CatmullClarkSpace::build(const std::string& name, IrregularMethod method, Index domain_faces) {
  if (boundary_ == BoundaryRule::kClamped) {
    std::vector<std::vector<Index>> faces;
    for (Index f = 0; f < domain_faces; ++f) {
      const auto fv = net_.face(f);
      faces.emplace_back(fv.begin(), fv.end());
    }
    domain_ = mesh::PolyMesh::build(net_.points(), std::move(faces));
  }
  build_elements(name, method, domain_faces);
  build_boundary();
  find_twins();
}

void CatmullClarkSpace::find_twins() {
  // Compared against at most 64 distinct operators, so an irregularly numbered net costs O(64) per element and
  // finds fewer twins. Operators are 0/1 gather matrices times the grid operator: equal means bitwise equal.
  twin_.resize(elements_.size());
  std::vector<Index> distinct;
  for (std::size_t e = 0; e < elements_.size(); ++e) {
    twin_[e] = static_cast<Index>(e);
    const Element& el = elements_[e];
    if (el.kind.family != Family::Regular) continue;
    for (Index d : distinct) {
      const Eigen::MatrixXd& other = elements_[static_cast<std::size_t>(d)].regular;
      if (other.cols() == el.regular.cols() && other == el.regular) {
        twin_[e] = d;
        break;
      }
    }
    if (twin_[e] == static_cast<Index>(e) && distinct.size() < 64) distinct.push_back(twin_[e]);
  }
}

void CatmullClarkSpace::build_elements(const std::string& name, IrregularMethod method, Index domain_faces) {
  const QuadMesh qm = quad_mesh_from(net_);
  elements_.resize(static_cast<std::size_t>(domain_faces));
  for (Index f = 0; f < domain_faces; ++f) {
    Element& el = elements_[static_cast<std::size_t>(f)];
    const auto fv = net_.face(f);
    for (int i = 0; i < 4; ++i) {
      if (is_extraordinary(net_, fv[i])) {
        el.rotation = i;
        // boundary: the EV lies on the domain's boundary, its ring of elements is not closed (with the clamped
        // rule it is an interior vertex of the extended net, valence faces + 2; rules that assume a closed ring,
        // such as the folded macro rules, must not be used there).
        el.kind = {Shape::Quad, Family::Irregular, ev_valence(net_, fv[i]), domain_mesh().is_boundary_vertex(fv[i]),
                   Scheme::CatmullClark};
      }
    }
    try {
      const OneRing ring = unfold_one_ring(qm, static_cast<int>(f), el.rotation);
      std::vector<Index> d(ring.parent.begin(), ring.parent.end());
      std::sort(d.begin(), d.end());
      d.erase(std::unique(d.begin(), d.end()), d.end());
      Eigen::MatrixXd to_dofs = Eigen::MatrixXd::Zero(ring.mesh.num_vertices, static_cast<Eigen::Index>(d.size()));
      for (int i = 0; i < ring.mesh.num_vertices; ++i) {
        const auto it = std::lower_bound(d.begin(), d.end(), ring.parent[static_cast<std::size_t>(i)]);
        to_dofs(i, it - d.begin()) = 1.0;
      }
      el.dof_offset = static_cast<Index>(dofs_.size());
      el.num_dofs = static_cast<Index>(d.size());
      dofs_.insert(dofs_.end(), d.begin(), d.end());
      max_local_dofs_ = std::max(max_local_dofs_, el.num_dofs);
      if (el.kind.family == Family::Regular) {
        el.regular = grid_operator(ring.mesh, 0, 0) * to_dofs;
      } else {
        const std::vector<int> stam = (method == IrregularMethod::kStam && !net_.is_boundary_vertex(fv[el.rotation]))
                                          ? stam_points(ring.mesh)
                                          : std::vector<int>{};
        if (!stam.empty()) {
          el.stam = &stam_evaluator(el.kind.valence);
          el.stam_map.resize(static_cast<Eigen::Index>(stam.size()), to_dofs.cols());
          for (std::size_t i = 0; i < stam.size(); ++i) el.stam_map.row(static_cast<Eigen::Index>(i)) = to_dofs.row(stam[i]);
        } else {
          el.irregular = std::make_unique<IrregularElement>(make_irregular_element(ring, to_dofs));
        }
      }
    } catch (const std::logic_error& e) {
      throw UnsupportedError(name + ": face " + std::to_string(f) + " of the control net: its neighbourhood is not " +
                             "a disc of the expected kind (" + e.what() + ")");
    }
  }
}

void CatmullClarkSpace::build_boundary() {
  const mesh::PolyMesh& dm = domain_mesh();
  const auto& loops = dm.boundary_loops();
  for (std::size_t l = 0; l < loops.size(); ++l) {
    const auto& loop = loops[l];
    const std::size_t n = loop.size();
    std::size_t start = 0;
    bool has_corner = false;
    for (std::size_t k = 0; k < n; ++k) {
      if (dm.num_vertex_faces(dm.half_edge(loop[k]).origin) == 1) {
        start = k;
        has_corner = true;
        break;
      }
    }
    int segment = -1;
    for (std::size_t k = 0; k < n; ++k) {
      const Index h = loop[(start + k) % n];
      const Index v = dm.half_edge(h).origin;
      if (segment < 0 || (has_corner && dm.num_vertex_faces(v) == 1)) {
        ++segment;
        std::string part = "b";
        part += std::to_string(l);
        part += '.';
        part += std::to_string(segment);
        part_names_.push_back(std::move(part));
      }
      const Index f = dm.half_edge(h).face;
      const int j = static_cast<int>(h - dm.face_half_edge(f));
      const int side = (j - elements_[static_cast<std::size_t>(f)].rotation + 4) % 4;
      boundary_edges_.push_back({f, side, static_cast<int>(part_names_.size()) - 1});
    }
  }
}

std::vector<InteriorEdge> CatmullClarkSpace::interior_edges() const {
  // Side of the rotated element f that half-edge h (of face f) is, as in build_boundary().
  const mesh::PolyMesh& dm = domain_mesh();
  auto side_of = [&](Index h, Index f) {
    const int j = static_cast<int>(h - dm.face_half_edge(f));
    return (j - elements_[static_cast<std::size_t>(f)].rotation + 4) % 4;
  };
  // An element's EV is its corner c0, on its sides 0 (c0 → c1) and 3 (c3 → c0).
  auto at_ev = [&](Index f, int side) {
    return elements_[static_cast<std::size_t>(f)].kind.family == Family::Irregular && (side == 0 || side == 3);
  };
  std::vector<InteriorEdge> edges;
  edges.reserve(static_cast<std::size_t>(dm.num_half_edges() / 2));
  for (Index h = 0; h < dm.num_half_edges(); ++h) {
    const mesh::HalfEdge& he = dm.half_edge(h);
    if (he.twin < h) continue;  // a boundary edge (twin -1) or listed from its twin
    const Index f0 = he.face, f1 = dm.half_edge(he.twin).face;
    const int s0 = side_of(h, f0), s1 = side_of(he.twin, f1);
    const int continuity = at_ev(f0, s0) || at_ev(f1, s1) ? 1 : 2;
    edges.push_back({{f0, f1}, {s0, s1}, {0.0, 1.0}, {1.0, 0.0}, continuity});
  }
  return edges;
}

std::span<const Index> CatmullClarkSpace::dofs(Index e) const {
  const Element& el = elements_[static_cast<std::size_t>(e)];
  return {dofs_.data() + el.dof_offset, static_cast<std::size_t>(el.num_dofs)};
}

void CatmullClarkSpace::evaluate(Index e, const Eigen::Matrix2Xd& pts, int derivatives, BasisValues& out) const {
  const Element& el = elements_[static_cast<std::size_t>(e)];
  if (el.irregular) {
    evaluate_irregular(*el.irregular, pts, derivatives, out);
    return;
  }
  thread_local BasisValues bic;
  if (el.stam != nullptr) el.stam->evaluate(pts, derivatives, bic);
  else bicubic_values(pts, derivatives, 1.0, bic);
  const auto gt = (el.stam != nullptr ? el.stam_map : el.regular).transpose();
  out.value.noalias() = gt * bic.value;
  if (derivatives >= 1) {
    out.du.noalias() = gt * bic.du;
    out.dv.noalias() = gt * bic.dv;
  }
  if (derivatives >= 2) {
    out.duu.noalias() = gt * bic.duu;
    out.duv.noalias() = gt * bic.duv;
    out.dvv.noalias() = gt * bic.dvv;
  }
}

Geometry make_catmull_clark_geometry(const mesh::PolyMesh& mesh, const std::string& name, BoundaryRule boundary) {
  auto space = std::make_shared<const CatmullClarkSpace>(mesh, name, IrregularMethod::kStam, boundary);
  const mesh::PolyMesh& net = space->control_mesh();
  const int dim = net.is_planar() ? 2 : 3;
  Eigen::MatrixXd cp(net.num_vertices(), dim);
  for (Index v = 0; v < net.num_vertices(); ++v) cp.row(v) = net.point(v).head(dim).transpose();
  return Geometry(space, std::move(cp));
}

std::optional<SubdivisionElement> CatmullClarkSpace::subdivision_element(Index e) const {
  const Element& el = elements_[static_cast<std::size_t>(e)];
  if (el.stam) return SubdivisionElement{&stam_view(el.stam->valence()), el.stam_map, 0, {}};
  if (!el.irregular) return std::nullopt;
  SubdivisionElement s{&el.irregular->config->view, el.irregular->level1, 1, {}};
  for (const auto& t : el.irregular->level0) s.explicit_tiles.push_back({t, 2.0 * Eigen::Matrix2d::Identity()});
  return s;
}


SpaceRefinement refine_space(const CatmullClarkSpace& space, int steps) {
  if (space.boundary_rule() == BoundaryRule::kClamped) {
    ExtendedRefinement r = refine_extended({space.control_mesh(), space.num_elements()}, steps);
    return {std::make_shared<const CatmullClarkSpace>(std::move(r.net), "refined net"), std::move(r.prolongation)};
  }
  NetRefinement r = refine_net(space.control_mesh(), steps);
  return {std::make_shared<const CatmullClarkSpace>(r.mesh, "refined net"), std::move(r.prolongation)};
}

}  // namespace iga::basis::catmull_clark
