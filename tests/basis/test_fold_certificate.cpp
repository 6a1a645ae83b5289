// The fold certificate (basis/fold_certificate.hpp): folds between the points a rule samples are found, with the
// det J of the closed form; valid geometries of every backend are proved.
#include "support/paths.hpp"
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <string>

#include "basis/bspline/rational_space.hpp"
#include "basis/bspline/tensor_space.hpp"
#include "basis/fold_certificate.hpp"
#include "basis/registry.hpp"
#include "core/error.hpp"
#include "mesh/obj_reader.hpp"

namespace {

using namespace iga;

// One bicubic Bézier element on the unit square whose control point P_01 (u index 0, v index 1) is moved to
// (0.2, -0.001): det J(0, 0) = 9 (P_10 - P_00) × (P_01 - P_00) = 9 (1/3 · (-0.001) - 0 · 0.2) = -0.003, positive a
// few hundredths away from the corner (the 4 × 4 Gauss points, the nearest 0.069 from it, all see det J > 0).
Eigen::MatrixXd corner_fold_points() {
  Eigen::MatrixXd p(16, 2);
  for (int j = 0; j < 4; ++j) {
    for (int i = 0; i < 4; ++i) p.row(i + 4 * j) << i / 3.0, j / 3.0;
  }
  p.row(4) << 0.2, -0.001;
  return p;
}

basis::bspline::KnotVector bezier3() { return basis::bspline::KnotVector(3, {0, 0, 0, 0, 1, 1, 1, 1}); }

TEST(FoldCertificate, FindsACornerFoldTheRuleDoesNotSample) {
  const basis::Geometry g(std::make_shared<basis::bspline::TensorSpace>(bezier3(), bezier3()), corner_fold_points());
  EXPECT_EQ(g.validity(), "");  // the 4 x 4 Gauss points see det J > 0
  const std::string why = basis::fold_certificate(g);
  EXPECT_EQ(why, "element 0: det J = -0.003 < 0 where most of the domain has det J > 0: the geometry map folds over at (0, 0)");
}

TEST(FoldCertificate, FindsItInRationalElementsToo) {
  // Weights 2 at the four inner points: det J(0, 0) = (w_10 w_01 / w_00²) · 9 (P_10 - P_00) × (P_01 - P_00) = -0.003
  // (both neighbours of the corner keep weight 1).
  Eigen::VectorXd w = Eigen::VectorXd::Ones(16);
  for (int k : {5, 6, 9, 10}) w(k) = 2;
  const auto space = std::make_shared<basis::bspline::RationalSpace>(
      std::make_shared<basis::bspline::TensorSpace>(bezier3(), bezier3()), w);
  const basis::Geometry g(space, corner_fold_points());
  const std::string why = basis::fold_certificate(g);
  EXPECT_EQ(why, "element 0: det J = -0.003 < 0 where most of the domain has det J > 0: the geometry map folds over at (0, 0)");
}

TEST(FoldCertificate, ProvesTheValidGeometriesOfEveryBackend) {
  // Default geometries (the quarter annulus, NURBS of degrees 2 to 12 by elevation) and the project's nets.
  for (int degree : {2, 3, 6, 12}) {
    basis::BackendOptions o;
    o.degree = degree;
    basis::BackendFacts facts;
    const basis::Geometry g = basis::backend("bspline").default_geometry(o);
    EXPECT_EQ(basis::fold_certificate(g), "") << "degree " << degree;
  }
  for (const char* mesh : {"square_evs.obj", "l_shape.obj", "square_three_holes.obj"}) {
    const mesh::PolyMesh net = mesh::read_obj(std::string(IGA_SOURCE_DIR) + "/data/meshes/" + mesh);
    for (const char* backend : {"cc", "polyhedral"}) {
      basis::BackendFacts facts;
      const basis::Geometry g = basis::backend(backend).from_net(net, basis::BackendOptions{}, facts);
      EXPECT_EQ(basis::fold_certificate(g), "") << backend << " " << mesh;
    }
  }
}

TEST(FoldCertificate, ProgramsRefuseTheFold) {
  // make_geometry (every program's way to a geometry) runs the certificate.
  basis::BackendOptions o;
  o.geometry = std::string(IGA_SOURCE_DIR) + "/tests/bad_input/inputs/patch_corner_fold.json";
  basis::BackendFacts facts;
  try {
    (void)basis::make_geometry(basis::backend("bspline"), nullptr, o, facts);
    FAIL() << "the folded patch was accepted";
  } catch (const NumericalError& e) {
    EXPECT_NE(std::string(e.what()).find("folds over"), std::string::npos) << e.what();
  }
}

TEST(FoldCertificate, FindsCrossedBoundaryTangentsAtACatmullClarkCorner) {
  // A 3 x 3 grid of the unit square whose vertex (0, 1/3) is moved to (0.05, -0.002): the boundary tangents at the
  // corner (0, 0) cross, det J < 0 in a sliver a few thousandths wide there, > 0 at every Gauss point.
  std::vector<Eigen::Vector3d> points;
  for (int j = 0; j < 4; ++j) {
    for (int i = 0; i < 4; ++i) points.emplace_back(i / 3.0, j / 3.0, 0.0);
  }
  points[4] = Eigen::Vector3d(0.05, -0.002, 0.0);
  std::vector<std::vector<Index>> faces;
  for (Index j = 0; j < 3; ++j) {
    for (Index i = 0; i < 3; ++i) faces.push_back({4 * j + i, 4 * j + i + 1, 4 * j + i + 5, 4 * j + i + 4});
  }
  const mesh::PolyMesh net = mesh::PolyMesh::build(std::move(points), std::move(faces));
  for (const char* rule : {"natural", "clamped"}) {
    basis::BackendOptions o;
    o.cc_boundary = rule;
    basis::BackendFacts facts;
    const basis::Geometry g = basis::backend("cc").from_net(net, o, facts);
    EXPECT_EQ(g.validity(), "") << rule;
    const std::string why = basis::fold_certificate(g);
    EXPECT_EQ(why.rfind("element 0: det J = -", 0), 0U) << rule << ": " << why;
    EXPECT_NE(why.find("folds over"), std::string::npos) << rule << ": " << why;
  }
}

}  // namespace
