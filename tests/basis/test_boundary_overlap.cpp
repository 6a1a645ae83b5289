// Slits, cracks and self-overlapping domains (basis/boundary_overlap.hpp): refused with the place; the project's
// own nets and geometries pass.
#include "support/paths.hpp"
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "basis/boundary_overlap.hpp"
#include "basis/bspline/patch_file.hpp"
#include "basis/registry.hpp"
#include "core/error.hpp"
#include "mesh/obj_reader.hpp"

namespace {

using namespace iga;

// The unit square as 2 x 2 quads; with `crack`, the bottom-right face uses a copy of vertex (0.5, 0) (index 9), so
// the edge from (0.5, 0) to (0.5, 0.5) is boundary on both sides.
mesh::PolyMesh square(bool crack) {
  std::vector<Eigen::Vector3d> p;
  for (int j = 0; j < 3; ++j) {
    for (int i = 0; i < 3; ++i) p.emplace_back(0.5 * i, 0.5 * j, 0.0);
  }
  p.emplace_back(0.5, 0.0, 0.0);
  std::vector<std::vector<Index>> f = {{0, 1, 4, 3}, {crack ? 9 : 1, 2, 5, 4}, {3, 4, 7, 6}, {4, 5, 8, 7}};
  return mesh::PolyMesh::build(std::move(p), std::move(f));
}

TEST(BoundaryOverlap, ACrackInTheNetIsRefusedAtItsTip) {
  EXPECT_EQ(basis::net_boundary_overlap(square(false)), "");
  const std::string why = basis::net_boundary_overlap(square(true));
  // The two sides meet along their whole length; the first pair found shares the tip (0.5, 0.5) and turns back.
  EXPECT_EQ(why.rfind("the net's boundary meets itself at (0.5, ", 0), 0U) << why;
  EXPECT_NE(why.find("net edge 2-5 of face 1"), std::string::npos) << why;
  EXPECT_NE(why.find("net edge 5-10 of face 2"), std::string::npos) << why;
  // Every program's way to a geometry refuses it, whatever the backend.
  for (const char* backend : {"cc", "polyhedral", "halfbox"}) {
    basis::BackendFacts facts;
    const mesh::PolyMesh net = square(true);
    EXPECT_THROW(basis::make_refined_geometry(basis::backend(backend), &net, basis::BackendOptions{}, 1, facts),
                 InputError)
        << backend;
  }
}

TEST(BoundaryOverlap, ASelfCrossingPatchBoundaryIsRefusedWhereItCrosses) {
  // A quadratic strip along a spiral wound 1.25 times: its inner side crosses the end side u = 0, which runs along
  // y = 0 from x = 1 to 1.5; the inner curve meets the x axis again inside the control polygon's radius 1.15.
  const basis::Geometry g = basis::bspline::read_patch(std::string(IGA_SOURCE_DIR) + "/tests/bad_input/inputs/spiral_patch.json");
  const std::string why = basis::boundary_overlap(g);
  ASSERT_EQ(why.rfind("the boundary meets itself at (", 0), 0U) << why;
  const double x = std::stod(why.substr(why.find('(') + 1)), y = std::stod(why.substr(why.find(',') + 1));
  EXPECT_EQ(y, 0.0) << why;
  EXPECT_GT(x, 1.0) << why;
  EXPECT_LT(x, 1.15) << why;
}

TEST(BoundaryOverlap, TheProjectsNetsAndGeometriesPass) {
  for (const char* name : {"square_evs.obj", "l_shape.obj", "square_three_holes.obj"}) {
    const mesh::PolyMesh net = mesh::read_obj(std::string(IGA_SOURCE_DIR) + "/data/meshes/" + name);
    EXPECT_EQ(basis::net_boundary_overlap(net), "") << name;
    for (const char* backend : {"cc", "polyhedral"}) {
      basis::BackendFacts facts;
      EXPECT_EQ(basis::boundary_overlap(basis::backend(backend).from_net(net, basis::BackendOptions{}, facts)), "")
          << backend << " " << name;
    }
  }
  for (const char* geometry : {"quarter-annulus", "l-shape", "square"}) {
    basis::BackendOptions o;
    o.geometry = geometry;
    EXPECT_EQ(basis::boundary_overlap(basis::backend("bspline").default_geometry(o)), "") << geometry;
  }
}

}  // namespace
