// The backend registry (basis/registry.hpp): every backend is built from a net and refined through the
// registry alone; options a backend does not take are errors; uniform B-spline refinement through the
// registry equals the refine-and-smooth algorithm's.
#include "support/paths.hpp"
#include <gtest/gtest.h>

#include <numbers>

#include <Eigen/Dense>
#include <cmath>
#include <string>

#include "basis/registry.hpp"
#include "core/error.hpp"
#include "mesh/obj_reader.hpp"
#include "mesh/poly_mesh.hpp"
#include "mesh/three_valent.hpp"
#include "quadrature/rule_provider.hpp"
#include "refine/refine_smooth.hpp"

using namespace iga;
using namespace iga::basis;

namespace {

// A planar nx × ny grid of quads on [0, 1]² (a valid net for every quad backend).
mesh::PolyMesh grid_net(int nx, int ny) {
  std::vector<Eigen::Vector3d> pts;
  for (int j = 0; j <= ny; ++j) {
    for (int i = 0; i <= nx; ++i) pts.emplace_back(double(i) / nx, double(j) / ny, 0.0);
  }
  std::vector<std::vector<Index>> faces;
  for (int j = 0; j < ny; ++j) {
    for (int i = 0; i < nx; ++i) {
      const Index a = j * (nx + 1) + i;
      faces.push_back({a, a + 1, a + nx + 2, a + nx + 1});
    }
  }
  return mesh::PolyMesh::build(std::move(pts), std::move(faces));
}

// The area of a planar geometry by p × p Gauss on every element (exact for polynomial elements of degree < p).
double area(const Geometry& g, int p) {
  const quadrature::Gauss gauss(p);
  double a = 0.0;
  BasisValues bv;
  GeometryValues gv;
  for (Index e = 0; e < g.space().num_elements(); ++e) {
    const quadrature::Rule& r = gauss.rule(g.space().kind(e));
    g.space().evaluate(e, r.points, 1, bv);
    g.evaluate(e, bv, gv);
    a += r.weights.dot(gv.measure);
  }
  return a;
}

// Each quad split into two triangles along its diagonal from its first vertex.
mesh::PolyMesh triangulated(const mesh::PolyMesh& quads) {
  std::vector<std::vector<Index>> faces;
  for (Index f = 0; f < quads.num_faces(); ++f) {
    const auto q = quads.face(f);
    faces.push_back({q[0], q[1], q[2]});
    faces.push_back({q[0], q[2], q[3]});
  }
  return mesh::PolyMesh::build(quads.points(), std::move(faces));
}

}  // namespace

TEST(Registry, ListsTheBackendsInOrder) {
  std::vector<std::string> names;
  for (const Backend& b : backends()) names.push_back(b.name);
  EXPECT_EQ(names, (std::vector<std::string>{"bspline", "cc", "polyhedral", "halfbox"}));
  EXPECT_EQ(backend_names(), "bspline, cc, polyhedral, halfbox");
  try {
    backend("nurbs");
    FAIL() << "no error for an unknown backend";
  } catch (const UnsupportedError& e) {
    EXPECT_NE(std::string(e.what()).find("--basis nurbs: not available in this build (available: bspline, cc, polyhedral, halfbox)"),
              std::string::npos) << e.what();
  }
}

// Every backend from a net of the 4 × 4 grid through the registry alone (the grid itself for the quad
// backends, the dual of its triangulation for half-box): its space has the backend's name, the map covers
// the unit square (area 1: the grid is planar and affine) where the backend interpolates the boundary, and
// one refinement keeps the map.
TEST(Registry, BuildsAndRefinesEveryBackendFromANet) {
  const mesh::PolyMesh quads = grid_net(4, 4);
  const mesh::PolyMesh three_valent = mesh::dual_net(triangulated(quads));
  for (const Backend& b : backends()) {
    SCOPED_TRACE(b.name);
    const mesh::PolyMesh& net = b.name == "halfbox" ? three_valent : quads;
    BackendFacts facts;
    const Geometry g = make_geometry(b, &net, BackendOptions{}, facts);
    EXPECT_EQ(g.space().name(), b.name);
    EXPECT_EQ(&backend_of(g.space()), &b);
    const double a0 = area(g, 6);
    // bspline and cc interpolate the square's boundary (open knots; boundary corners); the polyhedral and
    // half-box surfaces recede from the outer layer of the net, so their area is smaller.
    if (b.name != "polyhedral" && b.name != "halfbox") {
      EXPECT_NEAR(a0, 1.0, 1e-12);
    }
    const Refinement r = refine_uniform(g, 1, facts);
    if (b.nested) {
      EXPECT_TRUE(r.nested);
    }
    EXPECT_EQ(r.geometry.space().name(), b.name);
    EXPECT_GT(r.geometry.space().num_elements(), g.space().num_elements());
    if (r.nested) {
      ASSERT_EQ(r.prolongation.rows(), r.geometry.space().num_dofs());
      ASSERT_EQ(r.prolongation.cols(), g.space().num_dofs());
      EXPECT_LE((r.prolongation * g.control_points() - r.geometry.control_points()).norm(), 1e-14);
      if (g.space().kind(0).shape == Shape::Quad) {
        EXPECT_NEAR(area(r.geometry, 6), a0, 1e-12);
      }
    } else {
      EXPECT_EQ(r.prolongation.size(), 0);
    }
    // Refinement before building (not nested) or after (nested) gives the same space size.
    BackendFacts f2;
    const Refinement direct = make_refined_geometry(b, &net, BackendOptions{}, 1, f2);
    EXPECT_EQ(direct.geometry.space().num_dofs(), r.geometry.space().num_dofs());
    EXPECT_EQ(direct.geometry.space().num_elements(), r.geometry.space().num_elements());
  }
}

TEST(Registry, DefaultGeometryOnlyWhereThereIsOne) {
  BackendFacts facts;
  const Geometry annulus = make_geometry(backend("bspline"), nullptr, BackendOptions{}, facts);
  // The quarter annulus r ∈ [1, 2], exactly (NURBS): 3π/4, to the 16-point rule's error on a rational integrand.
  EXPECT_NEAR(area(annulus, 16), 0.75 * std::numbers::pi, 1e-14);
  try {
    make_geometry(backend("cc"), nullptr, BackendOptions{}, facts);
    FAIL() << "no error without a net";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("--basis cc needs --mesh"), std::string::npos) << e.what();
  }
}

TEST(Registry, OptionsABackendDoesNotTakeAreErrors) {
  EXPECT_NO_THROW(check_options(backend("bspline"), {"degree", "refine-intervals"}));
  EXPECT_NO_THROW(check_options(backend("polyhedral"), {"presubdivide"}));
  try {
    check_options(backend("cc"), {"degree"});
    FAIL() << "--degree accepted for cc";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), "--degree is not an option of --basis cc (its options: --cc-boundary, --cc-enrich, --cc-corners, --grade-evs)");
  }
  try {
    check_options(backend("polyhedral"), {"presubdivide", "degree"});
    FAIL() << "--degree accepted for polyhedral";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()),
              "--degree is not an option of --basis polyhedral (its options: --presubdivide, --degree-raise)");
  }
  BackendOptions o;
  EXPECT_EQ(degree(backend("bspline"), o), 3);
  o.degree = 5;
  EXPECT_EQ(degree(backend("bspline"), o), 5);
}

// Uniform B-spline refinement through the registry (Oslo midpoint insertion) against the refine-and-smooth
// algorithm applied to every interval (an independent algorithm, refine/): same space, same prolongation.
TEST(Registry, BsplineRefinementEqualsRefineAndSmooth) {
  for (int p = 2; p <= 5; ++p) {  // the quarter annulus needs degree >= 2
    SCOPED_TRACE(p);
    BackendOptions o;
    o.degree = p;
    BackendFacts facts;
    const Geometry g = make_geometry(backend("bspline"), nullptr, o, facts);
    const Refinement a = refine_uniform(g, 1, facts);
    const Refinement b = refine::refine_smooth_tensor(g);
    ASSERT_EQ(a.prolongation.rows(), b.prolongation.rows());
    ASSERT_EQ(a.prolongation.cols(), b.prolongation.cols());
    EXPECT_LE(Eigen::MatrixXd(a.prolongation - b.prolongation).cwiseAbs().maxCoeff(), 1e-12);
    EXPECT_LE((a.geometry.control_points() - b.geometry.control_points()).cwiseAbs().maxCoeff(), 1e-12);
  }
}

TEST(Registry, FactsOfTheBuild) {
  // square_evs.obj has faces touching two extraordinary vertices: Catmull–Clark applies one global step
  // first and says so; a plain grid needs none.
  const mesh::PolyMesh net = mesh::read_obj(std::string(IGA_SOURCE_DIR) + "/data/meshes/square_evs.obj");
  BackendFacts facts;
  make_geometry(backend("cc"), &net, BackendOptions{}, facts);
  EXPECT_EQ(facts.counts.at("cc_global_steps"), 1);
  ASSERT_EQ(facts.notes.size(), 1u);
  EXPECT_NE(facts.notes[0].find("applied 1 global Catmull–Clark step(s) first"), std::string::npos) << facts.notes[0];
  BackendFacts grid_facts;
  const mesh::PolyMesh grid = grid_net(3, 3);
  make_geometry(backend("cc"), &grid, BackendOptions{}, grid_facts);
  EXPECT_EQ(grid_facts.counts.at("cc_global_steps"), 0);
  EXPECT_TRUE(grid_facts.notes.empty());
  BackendOptions o;
  o.presubdivide = 1;
  BackendFacts pf;
  const Geometry pg = make_geometry(backend("polyhedral"), &net, o, pf);
  EXPECT_EQ(pf.counts.at("net_catmull_clark_steps"), 1);
  long long patches = 0;
  for (const auto& [key, n] : pf.counts) {
    if (key.starts_with("patches_per_configuration/")) patches += n;
  }
  EXPECT_EQ(patches, pg.space().num_elements());
  // Half-box: the dual of the L-shape triangulation has boundary faces that are not hexagons next to other
  // extraordinary faces, so one subdivision step separates them first (and says so); the square's needs none.
  for (const auto& [file, steps] : {std::pair{"tri_l_shape.obj", 1}, std::pair{"tri_square.obj", 0}}) {
    const mesh::PolyMesh three_valent = mesh::dual_net(mesh::read_obj(std::string(IGA_SOURCE_DIR) + "/data/meshes/" + file));
    BackendFacts hf;
    make_geometry(backend("halfbox"), &three_valent, BackendOptions{}, hf);
    EXPECT_EQ(hf.counts.at("halfbox_separation_steps"), steps) << file;
    EXPECT_GT(hf.counts.at("halfbox_boundary_sides"), 0) << file;
    // One note per separation step, and one saying that the boundary recedes (never silently).
    ASSERT_EQ(hf.notes.size(), static_cast<std::size_t>(steps + 1)) << file;
    EXPECT_NE(hf.notes.back().find("the net has a boundary"), std::string::npos) << hf.notes.back();
  }
}
