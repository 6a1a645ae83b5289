// A priori grading toward the irregular elements planned on the cells (basis/hierarchical/graded.hpp, the cc
// backend's refine_graded) against the same grading done step by step through refine_marked on built spaces, with
// the marking written out here: step k marks the elements within rings(k) rings of the irregular ones (ring 1
// shares a dof with one, ring j + 1 with one of ring j), admissibility class 2. Both must give the same refined
// cells, hence the same space; with keep_steps, the steps' prolongations must compose to the whole one and carry
// the control points.
#include "support/paths.hpp"
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "basis/hierarchical/hierarchical_space.hpp"
#include "basis/registry.hpp"
#include "mesh/obj_reader.hpp"

namespace {

using namespace iga;
using basis::hierarchical::HierarchicalSpace;

int rings(int k) { return std::max(1, static_cast<int>(std::lround(std::ldexp(3.0, -k)))); }

std::vector<Index> near_irregular(const basis::Space& s, int rings) {
  std::vector<char> near(static_cast<std::size_t>(s.num_dofs()), 0);
  for (Index e = 0; e < s.num_elements(); ++e) {
    if (s.kind(e).family != basis::Family::Irregular) continue;
    for (Index d : s.dofs(e)) near[static_cast<std::size_t>(d)] = 1;
  }
  std::vector<Index> marked;
  for (int ring = 0; ring < rings; ++ring) {
    marked.clear();
    for (Index e = 0; e < s.num_elements(); ++e) {
      const auto dofs = s.dofs(e);
      if (std::any_of(dofs.begin(), dofs.end(), [&](Index d) { return near[static_cast<std::size_t>(d)] != 0; })) {
        marked.push_back(e);
      }
    }
    for (Index e : marked) {
      for (Index d : s.dofs(e)) near[static_cast<std::size_t>(d)] = 1;
    }
  }
  return marked;
}

basis::Geometry clamped(const std::string& net, int refine) {
  basis::BackendOptions o;
  o.cc_boundary = "clamped";
  basis::BackendFacts facts;
  const mesh::PolyMesh m = mesh::read_obj(std::string(IGA_SOURCE_DIR) + "/data/meshes/" + net);
  return basis::make_refined_geometry(basis::backend("cc"), &m, o, refine, facts).geometry;
}

void expect_same_cells(const HierarchicalSpace& a, const HierarchicalSpace& b) {
  ASSERT_EQ(a.refined().size(), b.refined().size());
  for (std::size_t l = 0; l < a.refined().size(); ++l) {
    EXPECT_EQ(a.refined()[l].size(), b.refined()[l].size()) << "level " << l;
    for (auto c : a.refined()[l]) EXPECT_EQ(b.refined()[l].count(c), 1u) << "level " << l;
  }
  EXPECT_EQ(a.num_elements(), b.num_elements());
  EXPECT_EQ(a.num_dofs(), b.num_dofs());
}

class GradedCells : public ::testing::TestWithParam<std::string> {};

TEST_P(GradedCells, EqualTheStepByStepGrading) {
  const basis::Geometry coarse = clamped(GetParam(), 1);
  const basis::Backend& cc = basis::backend("cc");
  const int levels = 4;
  basis::BackendFacts facts;
  const basis::Refinement planned = cc.refine_graded(coarse, levels, rings, 2, facts, false);
  EXPECT_EQ(facts.counts["graded_levels"], levels);
  basis::Geometry stepped = coarse;
  for (int k = 0; k < levels; ++k) {
    const std::vector<Index> marked = near_irregular(stepped.space(), rings(k));
    ASSERT_FALSE(marked.empty());
    basis::BackendFacts step_facts;
    stepped = cc.refine_marked(stepped, marked, 2, step_facts, false).geometry;
  }
  const auto a = std::dynamic_pointer_cast<const HierarchicalSpace>(planned.geometry.space_ptr());
  const auto b = std::dynamic_pointer_cast<const HierarchicalSpace>(stepped.space_ptr());
  ASSERT_TRUE(a && b);
  expect_same_cells(*a, *b);
  // The same space, so the same control points (both prolongated exactly from the coarse net's).
  ASSERT_EQ(planned.geometry.control_points().rows(), stepped.control_points().rows());
  EXPECT_LT((planned.geometry.control_points() - stepped.control_points()).cwiseAbs().maxCoeff(), 1e-12);
}

TEST_P(GradedCells, StepsComposeToTheProlongation) {
  const basis::Geometry coarse = clamped(GetParam(), 1);
  basis::BackendFacts facts;
  const basis::Refinement r = basis::backend("cc").refine_graded(coarse, 3, rings, 2, facts, true);
  ASSERT_EQ(r.steps.size(), 3u);
  Eigen::SparseMatrix<double> product = r.steps[0];
  for (std::size_t k = 1; k < r.steps.size(); ++k) product = Eigen::SparseMatrix<double>(r.steps[k] * product);
  ASSERT_EQ(product.rows(), r.prolongation.rows());
  ASSERT_EQ(product.cols(), coarse.space().num_dofs());
  EXPECT_LT(Eigen::MatrixXd(product - r.prolongation).cwiseAbs().maxCoeff(), 1e-13);
  EXPECT_LT((r.prolongation * coarse.control_points() - r.geometry.control_points()).cwiseAbs().maxCoeff(), 1e-12);
}

INSTANTIATE_TEST_SUITE_P(Nets, GradedCells, ::testing::Values("fan_5.obj", "fan_8.obj", "square_evs.obj"),
                         [](const ::testing::TestParamInfo<std::string>& i) {
                           return i.param.substr(0, i.param.find('.'));
                         });

TEST(GradedCellsWithoutIrregularElements, TakeNoStep) {
  const basis::Geometry coarse = clamped("square_6x6.obj", 0);
  basis::BackendFacts facts;
  const basis::Refinement r = basis::backend("cc").refine_graded(coarse, 3, rings, 2, facts, false);
  EXPECT_EQ(facts.counts["graded_levels"], 0);
  EXPECT_EQ(r.geometry.space().num_elements(), coarse.space().num_elements());
}

}  // namespace
