// The incremental build of a hierarchical space (HierarchicalSpace from the previous space and the newly refined
// cells, basis/hierarchical/hierarchical_build.cpp) against the whole build of the same refined cells: the same
// elements in the same order, the same dofs (level, function, numbering) on each, the same values of every
// function at sample points, and the same prolongation from the previous space (the incremental one computes only
// the rows of recomputed leaves; the whole build's is the general traversal). THB splines of degrees 2 and 3 on
// non-uniform knots, and hierarchical Catmull–Clark on square_evs.obj (extraordinary vertices of valence 3, 5, 6),
// refined step by step toward a corner and at random, with admissibility classes 0 and 2; and the two properties
// of LevelHierarchy::support_extension the incremental build rests on. Along every chain, the coefficient blocks a
// space shares with its predecessors hold at most twice the coefficients its leaves use.
#include "support/paths.hpp"
#include <gtest/gtest.h>

#include <algorithm>
#include <memory>
#include <random>
#include <vector>

#include "basis/catmull_clark/levels.hpp"
#include "basis/catmull_clark/space.hpp"
#include "basis/hierarchical/refine.hpp"
#include "basis/thb/dyadic_levels.hpp"
#include "mesh/obj_reader.hpp"

namespace {

using namespace iga;
using basis::hierarchical::HierarchicalSpace;

basis::bspline::KnotVector knots(int p, std::vector<double> inner, double a, double b) {
  std::vector<double> t(static_cast<std::size_t>(p + 1), a);
  t.insert(t.end(), inner.begin(), inner.end());
  t.insert(t.end(), static_cast<std::size_t>(p + 1), b);
  return basis::bspline::KnotVector(p, t);
}

Eigen::Matrix2Xd points() {
  Eigen::Matrix2Xd x(2, 9);
  for (int j = 0; j < 3; ++j) {
    for (int i = 0; i < 3; ++i) x.col(3 * j + i) = Eigen::Vector2d(0.15 + 0.35 * i, 0.1 + 0.4 * j);
  }
  return x;
}

// `incremental` was built from `previous`; `whole` from nothing with the same refined cells.
void expect_same(const HierarchicalSpace& previous, const HierarchicalSpace& incremental, const HierarchicalSpace& whole) {
  ASSERT_TRUE(incremental.built_from(previous));
  ASSERT_FALSE(whole.built_from(previous));
  ASSERT_EQ(incremental.num_elements(), whole.num_elements());
  ASSERT_EQ(incremental.num_dofs(), whole.num_dofs());
  EXPECT_EQ(incremental.max_local_dofs(), whole.max_local_dofs());
  EXPECT_EQ(incremental.num_levels(), whole.num_levels());
  for (Index d = 0; d < whole.num_dofs(); ++d) {
    ASSERT_EQ(incremental.dof_level(d), whole.dof_level(d)) << "dof " << d;
    ASSERT_TRUE(incremental.dof_function(d) == whole.dof_function(d)) << "dof " << d;
  }
  const Eigen::Matrix2Xd x = points();
  basis::BasisValues a, b;
  double worst = 0.0;
  for (Index e = 0; e < whole.num_elements(); ++e) {
    ASSERT_EQ(incremental.level(e), whole.level(e)) << "element " << e;
    ASSERT_TRUE(incremental.cell(e) == whole.cell(e)) << "element " << e;
    const auto da = incremental.dofs(e), db = whole.dofs(e);
    ASSERT_EQ(std::vector<Index>(da.begin(), da.end()), std::vector<Index>(db.begin(), db.end())) << "element " << e;
    incremental.evaluate(e, x, 1, a);
    whole.evaluate(e, x, 1, b);
    worst = std::max({worst, (a.value - b.value).cwiseAbs().maxCoeff(), (a.du - b.du).cwiseAbs().maxCoeff(),
                      (a.dv - b.dv).cwiseAbs().maxCoeff()});
  }
  EXPECT_EQ(worst, 0.0);  // the same coefficients, copied or computed by the same operations
  const Eigen::SparseMatrix<double> pi = incremental.prolongation_from(previous), pw = whole.prolongation_from(previous);
  ASSERT_EQ(pi.rows(), pw.rows());
  ASSERT_EQ(pi.cols(), pw.cols());
  EXPECT_LT(Eigen::MatrixXd(pi - pw).cwiseAbs().maxCoeff(), 1e-14);
  EXPECT_EQ(pi.nonZeros(), pw.nonZeros());
}

// Refines `steps` times, each time the elements chosen by `pick` (few enough that refine_marked builds
// incrementally), and compares every step with the whole build.
template <class Pick>
int check_chain(std::shared_ptr<const HierarchicalSpace> space, int steps, int admissibility, Pick pick) {
  int incremental = 0;
  for (int s = 0; s < steps; ++s) {
    const std::vector<Index> marked = pick(*space);
    const auto next = basis::hierarchical::refine_marked(*space, marked, admissibility).space;
    // The coefficient blocks shared along the chain hold at most twice what the leaves use.
    EXPECT_LE(next->coefficients_held(), 2 * next->coefficients_used()) << "step " << s;
    if (next->built_from(*space)) {
      ++incremental;
      const HierarchicalSpace whole(next->hierarchy_ptr(), next->refined());
      expect_same(*space, *next, whole);
      if (::testing::Test::HasFailure()) return incremental;
    }
    space = next;
  }
  return incremental;
}

// The elements of the deepest level touching the corner cell 0 (the corner of the parameter domain).
std::vector<Index> corner(const HierarchicalSpace& s) {
  std::vector<Index> out;
  for (Index e = 0; e < s.num_elements(); ++e) {
    if (s.level(e) == s.num_levels() - 1 && s.cell(e) == 0) out.push_back(e);
  }
  if (out.empty()) out.push_back(0);
  return out;
}

class IncrementalThb : public ::testing::TestWithParam<int> {};

TEST_P(IncrementalThb, TowardACornerEqualsTheWholeBuild) {
  const int p = GetParam();
  auto space = basis::thb::coarse_thb_space(knots(p, {0.2, 0.5, 0.5, 0.7}, 0, 1), knots(p, {-0.4, 0.1, 0.9}, -1, 2));
  for (int m : {0, 2}) EXPECT_EQ(check_chain(space, 12, m, corner), 12) << "admissibility " << m;
}

TEST_P(IncrementalThb, RandomMarkingsEqualTheWholeBuild) {
  const int p = GetParam();
  auto space = basis::thb::coarse_thb_space(knots(p, {0.2, 0.5, 0.5, 0.7}, 0, 1), knots(p, {-0.4, 0.1, 0.9}, -1, 2));
  space = basis::hierarchical::refine_all(*basis::hierarchical::refine_all(*space).space).space;  // 320 elements
  std::mt19937 rng(5);
  auto pick = [&](const HierarchicalSpace& s) {
    std::uniform_int_distribution<Index> any(0, s.num_elements() - 1);
    std::vector<Index> marked;
    for (Index i = 0; i < s.num_elements() / 40 + 1; ++i) marked.push_back(any(rng));
    return marked;
  };
  for (int m : {0, 2}) EXPECT_GE(check_chain(space, 6, m, pick), 5) << "admissibility " << m;
}

INSTANTIATE_TEST_SUITE_P(Degrees, IncrementalThb, ::testing::Values(2, 3));

TEST(IncrementalCatmullClark, TowardAnExtraordinaryVertexEqualsTheWholeBuild) {
  auto level0 = std::make_shared<const basis::catmull_clark::CatmullClarkSpace>(
      mesh::read_obj(std::string(IGA_SOURCE_DIR) + "/data/meshes/square_evs.obj"));
  const auto space = basis::catmull_clark::coarse_hierarchical_space(level0);
  // The first element of the deepest level at an extraordinary vertex.
  auto at_ev = [](const HierarchicalSpace& s) {
    for (Index e = 0; e < s.num_elements(); ++e) {
      if (s.level(e) == s.num_levels() - 1 && s.kind(e).family == basis::Family::Irregular) return std::vector<Index>{e};
    }
    return std::vector<Index>{};
  };
  EXPECT_EQ(check_chain(space, 4, 2, at_ev), 4);
}

// What the incremental build rests on (LevelHierarchy::support_extension): the extension is the union of the
// supports of the cell's functions, and a child's lies in the children of its parent's.
void expect_support_extensions(const basis::hierarchical::LevelHierarchy& h, int levels, unsigned seed) {
  using basis::hierarchical::Key;
  std::mt19937 rng(seed);
  std::vector<Key> cells{0, h.num_root_cells() - 1};
  for (int i = 0; i < 6; ++i) cells.push_back(Key{std::uniform_int_distribution<Index>(0, h.num_root_cells() - 1)(rng)});
  std::vector<Key> ext, generic, child_ext;
  for (int level = 0; level < levels; ++level) {
    std::vector<Key> next;
    for (Key c : cells) {
      h.support_extension(level, c, ext);
      h.LevelHierarchy::support_extension(level, c, generic);
      std::sort(ext.begin(), ext.end());
      ASSERT_EQ(ext, generic) << "level " << level << " cell " << basis::hierarchical::to_string(c);
      for (int slot = 0; slot < 4; ++slot) {
        const Key child = h.child(level, c, slot);
        h.support_extension(level + 1, child, child_ext);
        for (Key f : child_ext) {
          int unused = 0;
          EXPECT_TRUE(std::binary_search(ext.begin(), ext.end(), h.parent(level + 1, f, unused)))
              << "level " << level + 1 << " cell " << basis::hierarchical::to_string(child);
        }
        next.push_back(child);
      }
    }
    std::shuffle(next.begin(), next.end(), rng);
    next.resize(std::min<std::size_t>(next.size(), 12));
    cells = next;
  }
}

TEST(SupportExtension, IsTheUnionOfSupportsAndNested) {
  for (int p : {2, 3}) {
    const auto thb = basis::thb::coarse_thb_space(knots(p, {0.2, 0.5, 0.5, 0.7}, 0, 1), knots(p, {-0.4, 0.1, 0.9}, -1, 2));
    expect_support_extensions(thb->hierarchy(), 6, 3);
  }
  auto level0 = std::make_shared<const basis::catmull_clark::CatmullClarkSpace>(
      mesh::read_obj(std::string(IGA_SOURCE_DIR) + "/data/meshes/square_evs.obj"));
  expect_support_extensions(basis::catmull_clark::coarse_hierarchical_space(level0)->hierarchy(), 3, 4);
}

TEST(IncrementalBuild, RefusesCellsThatAreNotNew) {
  auto space = basis::thb::coarse_thb_space(knots(2, {0.5}, 0, 1), knots(2, {0.5}, 0, 1));
  const auto next = basis::hierarchical::refine_marked(*space, std::vector<Index>{0}, 0).space;
  // Cell 0 of level 0 refined both before and after: not new.
  const auto after = basis::hierarchical::refine_marked(*next, std::vector<Index>{next->num_elements() - 1}, 0).space;
  EXPECT_THROW(HierarchicalSpace(*next, after->refined(), std::vector<basis::hierarchical::LevelCell>{{0, 0}}), InputError);
}

}  // namespace
