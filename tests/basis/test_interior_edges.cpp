// Space::interior_edges() of the bspline, Catmull–Clark, half-box and polyhedral backends: counts against
// combinatorics (every element side is boundary or covered exactly once by interior pieces; 2 E_i + E_b = 4 F
// or 3 F; Euler's formula V − E + F = χ of the element mesh, χ from the surface's known topology), the two
// ends of every piece mapped through a geometry to the same physical point (1e-12 of the domain size), and
// the continuity values (bspline: degree − knot multiplicity; cc: 1 at EVs, 2 elsewhere).
#include "support/paths.hpp"
#include <gtest/gtest.h>

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>
#include <random>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "basis/bspline/tensor_space.hpp"
#include "basis/catmull_clark/space.hpp"
#include "basis/half_box/space.hpp"
#include "basis/polyhedral/space.hpp"
#include "mesh/obj_reader.hpp"
#include "mesh/three_valent.hpp"
#include "polyhedral_nets.hpp"

namespace {

using iga::Index;
using iga::basis::BasisValues;
using iga::basis::BoundaryEdge;
using iga::basis::InteriorEdge;
using iga::basis::Shape;
using iga::basis::Space;
namespace mesh = iga::mesh;
namespace bspline = iga::basis::bspline;
using iga::basis::catmull_clark::CatmullClarkSpace;
using iga::basis::half_box::HalfBoxSpace;
using iga::basis::polyhedral::PolyhedralSpace;

mesh::PolyMesh data_mesh(const std::string& file) {
  return mesh::read_obj(std::string(IGA_SOURCE_DIR) + "/data/meshes/" + file);
}

Shape shape_of(const Space& space, Index e) { return space.kind(e).shape; }

// Physical point of element e at reference point p: Σ_a cp(dof_a) N_a(p).
Eigen::VectorXd map_point(const Space& space, const Eigen::MatrixXd& cp, Index e, const Eigen::Vector2d& p) {
  BasisValues v;
  space.evaluate(e, Eigen::Matrix2Xd(p), 0, v);
  const auto dofs = space.dofs(e);
  Eigen::VectorXd x = Eigen::VectorXd::Zero(cp.cols());
  for (std::size_t a = 0; a < dofs.size(); ++a) x += v.value(static_cast<Eigen::Index>(a), 0) * cp.row(dofs[a]).transpose();
  return x;
}

Eigen::VectorXd side_map(const Space& space, const Eigen::MatrixXd& cp, Index e, int side, double t) {
  return map_point(space, cp, e, iga::basis::side_point(shape_of(space, e), side, t));
}

// Checks shared by every backend. Returns the number of element sides that are points in the geometry
// (collapsed polar sides), which are neither boundary nor interior.
//  - the piece's points at s = 0, ½, 1 agree on both elements to 1e-12 × the domain size (cp's extent);
//  - element indices, sides and ranges are valid and the two elements differ;
//  - no side of an interior edge is a boundary side;
//  - every side (except point sides) is boundary or covered by interior pieces whose ranges sum to length 1.
int check_edges(const Space& space, const Eigen::MatrixXd& cp, const std::vector<InteriorEdge>& edges,
                const std::string& what) {
  const double size = (cp.colwise().maxCoeff() - cp.colwise().minCoeff()).maxCoeff();
  const double tol = 1e-12 * size;
  std::set<std::pair<Index, int>> boundary;
  for (const BoundaryEdge& b : space.boundary_edges()) boundary.insert({b.element, b.side});
  std::map<std::pair<Index, int>, double> covered;  // (element, side) → summed length of its pieces
  double worst = 0.0;
  for (const InteriorEdge& edge : edges) {
    bool valid = edge.element[0] != edge.element[1];
    for (int i = 0; i < 2; ++i) {
      valid = valid && edge.element[i] >= 0 && edge.element[i] < space.num_elements() && edge.side[i] >= 0 &&
              edge.side[i] < iga::basis::num_sides(shape_of(space, edge.element[i])) && edge.t0[i] >= 0.0 &&
              edge.t0[i] <= 1.0 && edge.t1[i] >= 0.0 && edge.t1[i] <= 1.0;
    }
    if (!valid) {
      ADD_FAILURE() << what << ": invalid edge between elements " << edge.element[0] << " and " << edge.element[1];
      return -1;
    }
    for (int i = 0; i < 2; ++i) {
      EXPECT_FALSE(boundary.count({edge.element[i], edge.side[i]}))
          << what << ": element " << edge.element[i] << " side " << edge.side[i] << " is also a boundary side";
      covered[{edge.element[i], edge.side[i]}] += std::abs(edge.t1[i] - edge.t0[i]);
    }
    EXPECT_GE(edge.continuity, 0) << what;
    for (double s : {0.0, 0.5, 1.0}) {
      const Eigen::VectorXd a = side_map(space, cp, edge.element[0], edge.side[0], edge.t0[0] + s * (edge.t1[0] - edge.t0[0]));
      const Eigen::VectorXd b = side_map(space, cp, edge.element[1], edge.side[1], edge.t0[1] + s * (edge.t1[1] - edge.t0[1]));
      worst = std::max(worst, (a - b).cwiseAbs().maxCoeff());
    }
  }
  EXPECT_LE(worst, tol) << what << ": the two sides of a piece map to different points";
  int point_sides = 0;
  for (Index e = 0; e < space.num_elements(); ++e) {
    for (int side = 0; side < iga::basis::num_sides(shape_of(space, e)); ++side) {
      const auto it = covered.find({e, side});
      const double length = it == covered.end() ? 0.0 : it->second;
      if (boundary.count({e, side})) continue;
      if (length == 0.0) {
        // Only a side that is a single point may be neither boundary nor interior.
        const Eigen::VectorXd a = side_map(space, cp, e, side, 0.0);
        const bool point = (side_map(space, cp, e, side, 0.5) - a).norm() <= tol && (side_map(space, cp, e, side, 1.0) - a).norm() <= tol;
        EXPECT_TRUE(point) << what << ": element " << e << " side " << side << " is neither boundary nor interior";
        ++point_sides;
        continue;
      }
      EXPECT_NEAR(length, 1.0, 1e-15) << what << ": element " << e << " side " << side;
    }
  }
  return point_sides;
}

// ------------------------------------------------------------------------------------------------ bspline

bspline::KnotVector knots(int p, std::vector<double> interior) {
  std::vector<double> t(static_cast<std::size_t>(p + 1), 0.0);
  t.insert(t.end(), interior.begin(), interior.end());
  t.insert(t.end(), static_cast<std::size_t>(p + 1), 1.0);
  return bspline::KnotVector(p, t);
}

Eigen::MatrixXd random_points(Index n, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> x(-1.0, 1.0);
  Eigen::MatrixXd cp(n, 3);
  for (Index i = 0; i < n; ++i) cp.row(i) << x(rng), x(rng), x(rng);
  return cp;
}

TEST(InteriorEdges, BsplineGridCountsAndGeometry) {
  for (const auto& [nex, ney] : std::vector<std::pair<Index, Index>>{{1, 1}, {1, 4}, {3, 1}, {4, 3}}) {
    const bspline::TensorSpace space(bspline::KnotVector::uniform(2, nex), bspline::KnotVector::uniform(3, ney));
    const auto edges = space.interior_edges();
    const std::string what = std::to_string(nex) + " x " + std::to_string(ney);
    // E_i = nex (ney − 1) + ney (nex − 1), and 2 E_i + E_b = 4 F.
    EXPECT_EQ(static_cast<Index>(edges.size()), nex * (ney - 1) + ney * (nex - 1)) << what;
    EXPECT_EQ(2 * static_cast<Index>(edges.size()) + static_cast<Index>(space.boundary_edges().size()), 4 * space.num_elements()) << what;
    // Random control points in 3D: any spline map is continuous, so both sides must agree.
    EXPECT_EQ(check_edges(space, random_points(space.num_dofs(), 11), edges, what), 0) << what;
  }
}

TEST(InteriorEdges, BsplineContinuityIsDegreeMinusMultiplicity) {
  // u, degree 3: knots 0.25 (double: C1), 0.5 (triple: C0), 0.75 (single: C2); v, degree 2: 0.5 double (C0),
  // 0.25 single (C1).
  const bspline::TensorSpace space(knots(3, {0.25, 0.25, 0.5, 0.5, 0.5, 0.75}), knots(2, {0.25, 0.5, 0.5}));
  ASSERT_EQ(space.num_elements_u(), 4);
  ASSERT_EQ(space.num_elements_v(), 3);
  const auto edges = space.interior_edges();
  EXPECT_EQ(edges.size(), 4u * 2u + 3u * 3u);
  const std::map<double, int> expected_u{{0.25, 1}, {0.5, 0}, {0.75, 2}}, expected_v{{0.25, 1}, {0.5, 0}};
  int zeros = 0;
  for (const InteriorEdge& edge : edges) {
    const Eigen::Vector4d a = space.element_box(edge.element[0]), b = space.element_box(edge.element[1]);
    if (edge.side[0] == 1) {  // the knot line u = a(1) = b(0), element 1 to the right
      ASSERT_EQ(edge.side[1], 3);
      ASSERT_EQ(a(1), b(0));
      EXPECT_EQ(edge.continuity, expected_u.at(a(1))) << "u = " << a(1);
    } else {  // v = a(3) = b(2), element 1 above
      ASSERT_EQ(edge.side[0], 2);
      ASSERT_EQ(edge.side[1], 0);
      ASSERT_EQ(a(3), b(2));
      EXPECT_EQ(edge.continuity, expected_v.at(a(3))) << "v = " << a(3);
    }
    zeros += edge.continuity == 0 ? 1 : 0;
  }
  EXPECT_EQ(zeros, 3 + 4);  // the triple u knot (3 rows) and the double v knot (4 columns)
  EXPECT_EQ(check_edges(space, random_points(space.num_dofs(), 12), edges, "multiple knots"), 0);

  // The brief's case: a knot of multiplicity p in u, C^{p−1} elsewhere.
  const bspline::TensorSpace q(knots(2, {0.3, 0.6, 0.6, 0.8}), bspline::KnotVector::uniform(2, 2));
  for (const InteriorEdge& edge : q.interior_edges()) {
    const bool at_double = edge.side[0] == 1 && q.element_box(edge.element[0])(1) == 0.6;
    EXPECT_EQ(edge.continuity, at_double ? 0 : 1);
  }
}

// --------------------------------------------------------------------------------------- Catmull–Clark

Eigen::MatrixXd net_points(const mesh::PolyMesh& net) {
  Eigen::MatrixXd cp(net.num_vertices(), 3);
  for (Index v = 0; v < net.num_vertices(); ++v) cp.row(v) = net.point(v).transpose();
  return cp;
}

bool cc_ev(const mesh::PolyMesh& net, Index v) {
  if (net.is_boundary_vertex(v)) return net.num_vertex_faces(v) > 2;
  return net.valence(v) != 4;
}

TEST(InteriorEdges, CatmullClarkEulerGeometryAndContinuity) {
  // χ: l_shape and square_evs are discs, torus_evs a torus, cube.obj a closed cube (a sphere).
  const std::vector<std::pair<std::string, int>> meshes{
      {"l_shape.obj", 1}, {"square_evs.obj", 1}, {"torus_evs.obj", 0}, {"cube.obj", 2}};
  for (const auto& [file, chi] : meshes) {
    const CatmullClarkSpace space(data_mesh(file), file);
    const mesh::PolyMesh& net = space.control_mesh();
    const auto edges = space.interior_edges();
    const auto ei = static_cast<Index>(edges.size()), eb = static_cast<Index>(space.boundary_edges().size());
    const Index f = space.num_elements(), v = space.num_dofs();
    EXPECT_EQ(2 * ei + eb, 4 * f) << file;
    EXPECT_EQ(v - (ei + eb) + f, chi) << file;
    EXPECT_EQ(check_edges(space, net_points(net), edges, file), 0) << file;
    // The sides as net edges: corners c_k → c_{k+1} of one are c_{k+1} → c_k of the other; continuity 1
    // where an end is an EV, else 2.
    int at_ev = 0;
    for (const InteriorEdge& edge : edges) {
      Index ends[2][2];
      for (int i = 0; i < 2; ++i) {
        const auto face = net.face(edge.element[i]);
        const int r = space.rotation(edge.element[i]);
        ends[i][0] = face[static_cast<std::size_t>((edge.side[i] + r) % 4)];
        ends[i][1] = face[static_cast<std::size_t>((edge.side[i] + 1 + r) % 4)];
      }
      EXPECT_EQ(ends[0][0], ends[1][1]) << file;
      EXPECT_EQ(ends[0][1], ends[1][0]) << file;
      const bool ev = cc_ev(net, ends[0][0]) || cc_ev(net, ends[0][1]);
      EXPECT_EQ(edge.continuity, ev ? 1 : 2) << file;
      at_ev += ev ? 1 : 0;
    }
    EXPECT_GT(at_ev, 0) << file;  // every mesh here has EVs
  }
}

// ---------------------------------------------------------------------------------------------- half-box

TEST(InteriorEdges, HalfBoxEulerAndGeometry) {
  // Elements are triangles, one per three-faced net vertex; the element mesh's vertices are the net faces
  // around those vertices (the triangulation the net is dual to). χ from the triangulations' topology.
  const std::vector<std::pair<std::string, int>> meshes{
      {"tri_square.obj", 1}, {"tri_l_shape.obj", 1}, {"tri_sphere.obj", 2}, {"tri_torus.obj", 0}};
  for (const auto& [file, chi] : meshes) {
    const HalfBoxSpace space(mesh::dual_net(data_mesh(file)), file);
    const mesh::PolyMesh& net = space.control_net();
    const auto edges = space.interior_edges();
    const auto ei = static_cast<Index>(edges.size()), eb = static_cast<Index>(space.boundary_edges().size());
    const Index f = space.num_elements();
    EXPECT_EQ(2 * ei + eb, 3 * f) << file;
    std::set<Index> corners;  // net faces at the elements' corners
    for (Index e = 0; e < f; ++e) {
      const Index v = space.element_vertex(e);
      Index h = net.vertex_half_edge(v);
      for (int k = 0; k < 3; ++k) {
        corners.insert(net.half_edge(h).face);
        h = net.half_edge(net.half_edge(h).prev).twin;  // the next outgoing half-edge around v
        ASSERT_GE(h, 0) << file;
      }
    }
    EXPECT_EQ(static_cast<Index>(corners.size()) - (ei + eb) + f, chi) << file;
    Eigen::MatrixXd cp(space.num_dofs(), 3);
    for (Index d = 0; d < space.num_dofs(); ++d) cp.row(d) = net.point(space.vertex(d)).transpose();
    EXPECT_EQ(check_edges(space, cp, edges, file), 0) << file;
    for (const InteriorEdge& edge : edges) EXPECT_EQ(edge.continuity, 1) << file;
  }
}

// -------------------------------------------------------------------------------------------- polyhedral

TEST(InteriorEdges, PolyhedralCoverageAndGeometry) {
  using namespace polyhedral_nets;
  std::vector<std::pair<std::string, mesh::PolyMesh>> nets;
  for (int n : {3, 5, 6}) nets.emplace_back("star " + std::to_string(n), star_net(n));
  for (int n : {3, 5}) nets.emplace_back("ngon " + std::to_string(n), ngon_net(n));
  for (int n : {3, 5}) nets.emplace_back("polar " + std::to_string(n), polar_net(n));
  nets.emplace_back("t0", t0_net(false));
  nets.emplace_back("t1", t1_net(false));
  nets.emplace_back("t2", t2_net(true));
  {
    // The closed cube of eight 3-valent vertices: star caps only, no boundary.
    std::vector<Eigen::Vector3d> p;
    for (int i = 0; i < 8; ++i) p.emplace_back(i & 1, (i >> 1) & 1, (i >> 2) & 1);
    nets.emplace_back("closed cube", mesh::PolyMesh::build(p, {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4},
                                                                 {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}}));
  }
  for (const auto& [name, net] : nets) {
    const PolyhedralSpace space(net);
    const auto edges = space.interior_edges();
    Eigen::MatrixXd cp(space.num_dofs(), 3);
    for (Index d = 0; d < space.num_dofs(); ++d) cp.row(d) = net.point(space.vertex(d)).transpose();
    const int points = check_edges(space, cp, edges, name);
    // Only polar patches have a collapsed side (one each, at the pole).
    int polar = 0;
    for (Index e = 0; e < space.num_elements(); ++e) polar += space.kind(e).family == iga::basis::Family::Polar ? 1 : 0;
    EXPECT_EQ(points, polar) << name;
    for (const InteriorEdge& edge : edges) EXPECT_EQ(edge.continuity, 1) << name;
    if (name == "closed cube") {
      EXPECT_TRUE(space.boundary_edges().empty());
      // 24 patches meeting whole: 2 E_i = 4 F, and χ = 2 with V = 8 cap centres + 6 face centres + 12 edge midpoints.
      EXPECT_EQ(2 * static_cast<Index>(edges.size()), 4 * space.num_elements());
      EXPECT_EQ(26 - static_cast<Index>(edges.size()) + space.num_elements(), 2);
    }
  }
}

TEST(InteriorEdges, PolyhedralSplitSidesHaveHalfRanges) {
  // T-junction caps meet a bi-2 patch side in two halves (tjunction_cap.hpp): pieces with range length ½ on
  // the long side (and 1 on the short one). The code nets above are too small to contain such a bi-2 patch,
  // so this uses the paper's reference nets (skipped without them): T012 and tee have T-junctions, tricube
  // too, cylinder has polar caps. Coverage (lengths summing to 1 per side) and geometry as above.
  using namespace polyhedral_nets;
  const auto dir = reference_dir() / "testfile";
  if (!std::filesystem::exists(dir)) GTEST_SKIP() << "reference nets not found at " << dir;
  for (const std::string name : {"T012", "tee", "tricube", "cylinder"}) {
    const mesh::PolyMesh net = mesh::read_obj((dir / (name + ".obj")).string());
    const PolyhedralSpace space(net);
    const auto edges = space.interior_edges();
    Eigen::MatrixXd cp(space.num_dofs(), 3);
    for (Index d = 0; d < space.num_dofs(); ++d) cp.row(d) = net.point(space.vertex(d)).transpose();
    const int points = check_edges(space, cp, edges, name);
    int polar = 0;
    for (Index e = 0; e < space.num_elements(); ++e) polar += space.kind(e).family == iga::basis::Family::Polar ? 1 : 0;
    EXPECT_EQ(points, polar) << name;
    int halves = 0;
    for (const InteriorEdge& edge : edges) {
      const double l0 = std::abs(edge.t1[0] - edge.t0[0]), l1 = std::abs(edge.t1[1] - edge.t0[1]);
      EXPECT_EQ(l0, 1.0) << name;  // the short side first
      EXPECT_TRUE(l1 == 1.0 || l1 == 0.5) << name;
      halves += l1 == 0.5 ? 1 : 0;
    }
    if (name == "cylinder") {
      EXPECT_GT(polar, 0);
      EXPECT_EQ(halves, 0);
    } else {
      EXPECT_GT(halves, 0) << name;
      EXPECT_EQ(halves % 2, 0) << name;  // a long side is covered by two halves
    }
  }
}

}  // namespace
