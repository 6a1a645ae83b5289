// THB splines (basis/thb, basis/hierarchical) against their definition, computed a second way: global knot
// vectors of every level (insert_midpoints), global refinement matrices and global truncation, evaluated with
// TensorSpace. Random markings of 3–5 levels, degrees 2 and 3, non-uniform coarse knots with a repeated knot.
#include <gtest/gtest.h>

#include <Eigen/QR>
#include <Eigen/SVD>
#include <random>

#include "basis/bspline/knot_insertion.hpp"
#include "basis/bspline/tensor_space.hpp"
#include "basis/hierarchical/refine.hpp"
#include "basis/thb/dyadic_levels.hpp"

namespace {

using namespace iga;
using basis::bspline::KnotVector;
using basis::hierarchical::HierarchicalSpace;

KnotVector coarse_u(int p) {
  std::vector<double> t(static_cast<std::size_t>(p + 1), 0.0);
  for (double x : {0.2, 0.5, 0.5, 0.7}) t.push_back(x);  // non-uniform, one double knot
  t.insert(t.end(), static_cast<std::size_t>(p + 1), 1.0);
  return KnotVector(p, t);
}
KnotVector coarse_v(int p) {
  std::vector<double> t(static_cast<std::size_t>(p + 1), -1.0);
  for (double x : {-0.4, 0.1}) t.push_back(x);
  t.insert(t.end(), static_cast<std::size_t>(p + 1), 2.0);
  return KnotVector(p, t);
}

const basis::thb::DyadicBsplineLevels& levels(const HierarchicalSpace& s) {
  return static_cast<const basis::thb::DyadicBsplineLevels&>(s.hierarchy());
}

// Element and reference point of knot-parameter point (u, v).
std::pair<Index, Eigen::Vector2d> locate(const HierarchicalSpace& s, double u, double v) {
  const auto& h = levels(s);
  basis::hierarchical::Key ix = 0, iy = 0;
  while (ix + 1 < h.knots_u().num_intervals(0) && h.knots_u().breakpoint(0, ix + 1) <= u) ++ix;
  while (iy + 1 < h.knots_v().num_intervals(0) && h.knots_v().breakpoint(0, iy + 1) <= v) ++iy;
  int level = 0;
  basis::hierarchical::Key cell = ix + h.knots_u().num_intervals(0) * iy;
  while (s.is_refined(level, cell)) {
    const Eigen::Vector4d box = h.cell_box(level, cell);
    const int slot = (u >= 0.5 * (box(0) + box(1)) ? 1 : 0) + (v >= 0.5 * (box(2) + box(3)) ? 2 : 0);
    cell = h.child(level, cell, slot);
    ++level;
  }
  const Eigen::Vector4d box = h.cell_box(level, cell);
  return {s.element_of(level, cell), Eigen::Vector2d((u - box(0)) / (box(1) - box(0)), (v - box(2)) / (box(3) - box(2)))};
}

// All THB functions at (u, v): a dense vector over the dofs.
Eigen::VectorXd values_at(const HierarchicalSpace& s, double u, double v) {
  const auto [e, ref] = locate(s, u, v);
  basis::BasisValues bv;
  Eigen::Matrix2Xd pts(2, 1);
  pts.col(0) = ref;
  s.evaluate(e, pts, 0, bv);
  Eigen::VectorXd out = Eigen::VectorXd::Zero(s.num_dofs());
  const auto dofs = s.dofs(e);
  for (std::size_t a = 0; a < dofs.size(); ++a) out(dofs[a]) += bv.value(static_cast<Index>(a), 0);
  return out;
}

std::shared_ptr<const HierarchicalSpace> random_space(int p, int steps, unsigned seed, int admissibility,
                                                      std::vector<std::shared_ptr<const HierarchicalSpace>>* chain = nullptr) {
  std::mt19937 rng(seed);
  auto space = basis::thb::coarse_thb_space(coarse_u(p), coarse_v(p));
  if (chain) chain->push_back(space);
  for (int s = 0; s < steps; ++s) {
    std::vector<Index> marked;
    std::bernoulli_distribution pick(0.3);
    for (Index e = 0; e < space->num_elements(); ++e) {
      if (space->level(e) == s && pick(rng)) marked.push_back(e);
    }
    if (marked.empty()) marked.push_back(space->num_elements() - 1);
    space = basis::hierarchical::refine_marked(*space, marked, admissibility).space;
    if (chain) chain->push_back(space);
  }
  return space;
}

std::vector<Eigen::Vector2d> sample_points(unsigned seed, int n) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> du(0.0, 1.0), dv(-1.0, 2.0);
  std::vector<Eigen::Vector2d> pts;
  for (int i = 0; i < n; ++i) pts.emplace_back(du(rng), dv(rng));
  return pts;
}

class ThbDegree : public ::testing::TestWithParam<int> {};

TEST_P(ThbDegree, PartitionOfUnityAndNonNegativity) {
  const int p = GetParam();
  for (unsigned seed : {1u, 2u, 3u}) {
    const auto space = random_space(p, 4, seed, 2);
    ASSERT_GE(space->num_levels(), 4);
    for (const Eigen::Vector2d& x : sample_points(seed, 400)) {
      const Eigen::VectorXd v = values_at(*space, x(0), x(1));
      EXPECT_NEAR(v.sum(), 1.0, 1e-13);
      EXPECT_GE(v.minCoeff(), -1e-14);
    }
  }
}

TEST_P(ThbDegree, LinearIndependenceOnAFineSample) {
  const int p = GetParam();
  const auto space = random_space(p, 3, 7, 2);
  // (p+1)^2 interior points on every element: the collocation matrix must have full column rank.
  const int s = p + 1;
  Eigen::MatrixXd a = Eigen::MatrixXd::Zero(space->num_elements() * s * s, space->num_dofs());
  Eigen::Matrix2Xd pts(2, s * s);
  for (int j = 0; j < s; ++j) {
    for (int i = 0; i < s; ++i) pts.col(i + s * j) = Eigen::Vector2d((i + 0.5) / s, (j + 0.5) / s);
  }
  basis::BasisValues bv;
  for (Index e = 0; e < space->num_elements(); ++e) {
    space->evaluate(e, pts, 0, bv);
    const auto dofs = space->dofs(e);
    for (std::size_t l = 0; l < dofs.size(); ++l) {
      a.block(e * s * s, dofs[l], s * s, 1) = bv.value.row(static_cast<Index>(l)).transpose();
    }
  }
  Eigen::JacobiSVD<Eigen::MatrixXd> svd(a);
  const Eigen::VectorXd sv = svd.singularValues();
  EXPECT_GT(sv(sv.size() - 1) / sv(0), 1e-8) << space->num_dofs() << " dofs";
}

TEST_P(ThbDegree, EqualsTheGlobalTruncationOfEachFunction) {
  const int p = GetParam();
  const auto space = random_space(p, 3, 11, 2);
  const auto& h = levels(*space);
  const int top = space->num_levels() - 1;
  // Global level spaces and refinement matrices.
  std::vector<basis::bspline::TensorSpace> level;
  level.emplace_back(coarse_u(p), coarse_v(p));
  for (int l = 1; l <= top; ++l) {
    level.emplace_back(basis::bspline::insert_midpoints(level.back().knots_u()),
                       basis::bspline::insert_midpoints(level.back().knots_v()));
  }
  ASSERT_EQ(level[top].num_dofs(), static_cast<Index>(h.knots_u().num_functions(top) * h.knots_v().num_functions(top)));
  // Each THB function by the definition: e_f at its level, then refine and truncate level by level.
  // The level-l function index (jx + nfx jy) equals TensorSpace's dof index, so the levels agree.
  std::vector<basis::hierarchical::Key> support;
  auto inside = [&](int l, Index f) {
    h.support(l, f, support);
    for (auto c : support) {
      if (!space->exists(l, c)) return false;
    }
    return true;
  };
  // Independent selection: enumerate every active (level, function) pair and build its truncated vector.
  std::vector<Eigen::VectorXd> functions;
  for (int l = 0; l <= top; ++l) {
    for (Index f = 0; f < level[l].num_dofs(); ++f) {
      if (!inside(l, f)) continue;
      h.support(l, f, support);
      bool all_refined = true;
      for (auto c : support) all_refined = all_refined && space->is_refined(l, c);
      if (all_refined) continue;
      Eigen::VectorXd c = Eigen::VectorXd::Unit(level[l].num_dofs(), f);
      for (int m = l; m < top; ++m) {
        Eigen::VectorXd fine = basis::bspline::refinement_matrix(level[m], level[m + 1]) * c;
        for (Index g = 0; g < fine.size(); ++g) {
          if (inside(m + 1, g)) fine(g) = 0.0;
        }
        c = fine;
      }
      functions.push_back(c);
    }
  }
  ASSERT_EQ(static_cast<Index>(functions.size()), space->num_dofs());
  // Compare at sample points: the set of values must agree function by function after matching each THB dof
  // to the global function with the same values at the points.
  const auto pts = sample_points(5, 300);
  Eigen::MatrixXd mine(pts.size(), space->num_dofs()), theirs(pts.size(), space->num_dofs());
  for (std::size_t k = 0; k < pts.size(); ++k) {
    mine.row(static_cast<Index>(k)) = values_at(*space, pts[k](0), pts[k](1)).transpose();
    const Index span_u = level[top].knots_u().span(pts[k](0)), span_v = level[top].knots_v().span(pts[k](1));
    const Eigen::MatrixXd nu = basis::bspline::basis_functions(level[top].knots_u(), span_u, pts[k](0), 0);
    const Eigen::MatrixXd nv = basis::bspline::basis_functions(level[top].knots_v(), span_v, pts[k](1), 0);
    for (std::size_t i = 0; i < functions.size(); ++i) {
      double v = 0;
      for (int b = 0; b <= p; ++b) {
        for (int a = 0; a <= p; ++a) {
          v += functions[i]((span_u - p + a) + level[top].num_basis_u() * (span_v - p + b)) * nu(0, a) * nv(0, b);
        }
      }
      theirs(static_cast<Index>(k), static_cast<Index>(i)) = v;
    }
  }
  // Match columns.
  std::vector<bool> used(functions.size(), false);
  for (Index d = 0; d < space->num_dofs(); ++d) {
    double best = 1e300;
    Index arg = -1;
    for (Index i = 0; i < static_cast<Index>(functions.size()); ++i) {
      if (used[static_cast<std::size_t>(i)]) continue;
      const double diff = (mine.col(d) - theirs.col(i)).cwiseAbs().maxCoeff();
      if (diff < best) {
        best = diff;
        arg = i;
      }
    }
    ASSERT_GE(arg, 0);
    used[static_cast<std::size_t>(arg)] = true;
    EXPECT_LT(best, 1e-12) << "dof " << d;
  }
}

TEST_P(ThbDegree, NestedSpacesReproduceTheCoarseFunctions) {
  const int p = GetParam();
  std::vector<std::shared_ptr<const HierarchicalSpace>> chain;
  random_space(p, 4, 21, 2, &chain);
  const auto pts = sample_points(9, 200);
  for (std::size_t s = 1; s < chain.size(); ++s) {
    const Eigen::SparseMatrix<double> pr = chain[s]->prolongation_from(*chain[s - 1]);
    ASSERT_EQ(pr.rows(), chain[s]->num_dofs());
    ASSERT_EQ(pr.cols(), chain[s - 1]->num_dofs());
    // The matrix-free path gives the same coefficients.
    const Eigen::MatrixXd c = Eigen::MatrixXd::Random(chain[s - 1]->num_dofs(), 2);
    EXPECT_LT((chain[s]->coefficients_from(*chain[s - 1], c) - pr * c).cwiseAbs().maxCoeff(), 1e-13);
    for (const Eigen::Vector2d& x : pts) {
      const Eigen::VectorXd coarse = values_at(*chain[s - 1], x(0), x(1));
      const Eigen::VectorXd fine = values_at(*chain[s], x(0), x(1));
      EXPECT_LT((pr.transpose() * fine - coarse).cwiseAbs().maxCoeff(), 1e-12);
    }
  }
}

TEST_P(ThbDegree, CoarseSplineCoefficientsAreExact) {
  const int p = GetParam();
  const auto space = random_space(p, 4, 31, 2);
  const basis::bspline::TensorSpace coarse(coarse_u(p), coarse_v(p));
  std::mt19937 rng(3);
  std::normal_distribution<double> n01;
  Eigen::MatrixXd c0(coarse.num_dofs(), 2);
  for (Index i = 0; i < c0.size(); ++i) c0.data()[i] = n01(rng);
  const Eigen::MatrixXd c = space->from_level0(c0, coarse.num_dofs());
  for (const Eigen::Vector2d& x : sample_points(4, 200)) {
    const Eigen::VectorXd mine = values_at(*space, x(0), x(1));
    // The coarse spline by Cox–de Boor on the coarse knots (dof i + nu j = level-0 function index).
    const Index su = coarse.knots_u().span(x(0)), sv = coarse.knots_v().span(x(1));
    const Eigen::MatrixXd nu = basis::bspline::basis_functions(coarse.knots_u(), su, x(0), 0);
    const Eigen::MatrixXd nv = basis::bspline::basis_functions(coarse.knots_v(), sv, x(1), 0);
    Eigen::RowVector2d ref = Eigen::RowVector2d::Zero();
    for (int b = 0; b <= p; ++b) {
      for (int a = 0; a <= p; ++a) ref += nu(0, a) * nv(0, b) * c0.row((su - p + a) + coarse.num_basis_u() * (sv - p + b));
    }
    EXPECT_LT((mine.transpose() * c - ref).cwiseAbs().maxCoeff(), 1e-12);
  }
}

TEST_P(ThbDegree, AdmissibleRefinementBoundsTheLevelsPerElement) {
  const int p = GetParam();
  for (int m : {2, 3}) {
    const auto space = random_space(p, 5, 41, m);
    EXPECT_LE(basis::hierarchical::admissibility_class(*space), m);
  }
  // Without the closure a corner refined five times has functions of many levels on one element.
  auto space = basis::thb::coarse_thb_space(coarse_u(p), coarse_v(p));
  for (int s = 0; s < 5; ++s) {
    space = basis::hierarchical::refine_marked(*space, std::vector<Index>{space->element_of(s, 0)}, 0).space;
  }
  EXPECT_GT(basis::hierarchical::admissibility_class(*space), 2);
  const auto closed = basis::hierarchical::refine_marked(*space, std::vector<Index>{space->element_of(5, 0)}, 2);
  EXPECT_GT(closed.added, 0);
  EXPECT_LE(basis::hierarchical::admissibility_class(*closed.space), 2);
}

TEST_P(ThbDegree, UniformRefinementIsTheTensorSpace) {
  const int p = GetParam();
  auto space = basis::thb::coarse_thb_space(coarse_u(p), coarse_v(p));
  space = basis::hierarchical::refine_all(*space).space;
  space = basis::hierarchical::refine_all(*space).space;
  const basis::bspline::TensorSpace t(basis::bspline::insert_midpoints(basis::bspline::insert_midpoints(coarse_u(p))),
                                      basis::bspline::insert_midpoints(basis::bspline::insert_midpoints(coarse_v(p))));
  EXPECT_EQ(space->num_dofs(), t.num_dofs());
  EXPECT_EQ(space->num_elements(), t.num_elements());
  EXPECT_EQ(space->max_local_dofs(), (p + 1) * (p + 1));
}

TEST_P(ThbDegree, InteriorEdgesTileTheSkeleton) {
  const int p = GetParam();
  const auto space = random_space(p, 3, 51, 2);
  const auto& h = levels(*space);
  const auto edges = space->interior_edges();
  // Each piece: the same knot-parameter points from both sides; the lengths add up to the interior skeleton of
  // the coarse mesh plus the new lines inside refined cells.
  double length = 0;
  for (const auto& edge : edges) {
    Eigen::Vector2d ends[2][2];
    for (int i = 0; i < 2; ++i) {
      const Index e = edge.element[i];
      const Eigen::Vector4d box = h.cell_box(space->level(e), space->cell(e));
      for (int k = 0; k < 2; ++k) {
        const double t = k == 0 ? edge.t0[i] : edge.t1[i];
        const Eigen::Vector2d r = basis::side_point(basis::Shape::Quad, edge.side[i], t);
        ends[i][k] = Eigen::Vector2d(box(0) + r(0) * (box(1) - box(0)), box(2) + r(1) * (box(3) - box(2)));
      }
    }
    EXPECT_LT((ends[0][0] - ends[1][0]).norm(), 1e-13);
    EXPECT_LT((ends[0][1] - ends[1][1]).norm(), 1e-13);
    length += (ends[0][1] - ends[0][0]).norm();
    // Continuity 0 exactly on the double knot u = 0.5 (degree 2: multiplicity 2 = p gives C0 only for p = 2).
    const bool on_double = std::abs(ends[0][0](0) - 0.5) < 1e-14 && std::abs(ends[0][1](0) - 0.5) < 1e-14;
    EXPECT_EQ(edge.continuity, on_double ? p - 2 : p - 1);
  }
  // Skeleton length: Σ over elements of the perimeter, minus the boundary, halved.
  double perimeter = 0;
  for (Index e = 0; e < space->num_elements(); ++e) {
    const Eigen::Vector4d box = h.cell_box(space->level(e), space->cell(e));
    perimeter += 2 * ((box(1) - box(0)) + (box(3) - box(2)));
  }
  const double boundary = 2 * (1.0 + 3.0);
  EXPECT_NEAR(length, 0.5 * (perimeter - boundary), 1e-12);
}

TEST(DyadicKnots, LevelsStopWhereTheirBreakpointsStopBeingDistinctDoubles) {
  // A coarse interval [1, 1 + 2^-40]: its level-m breakpoints are 1 + r 2^(-40-m), distinct doubles down to
  // m = 12 (spacing 2^-52, one rounding unit); max_level keeps each level's intervals >= 64 units wide (2^-46),
  // so m <= 6. Before, the limit was 44 whatever the width, and refinement "halved" into repeated knots.
  const double a = 1.0, b = 1.0 + std::ldexp(1.0, -40);
  const basis::thb::DyadicKnots narrow(basis::bspline::KnotVector(2, {0, 0, 0, a, b, 2, 2, 2}));
  EXPECT_EQ(narrow.max_level(), 6);
  for (basis::hierarchical::Key j = 0; j < narrow.num_intervals(narrow.max_level()); ++j) {
    EXPECT_LT(narrow.breakpoint(narrow.max_level(), j), narrow.breakpoint(narrow.max_level(), j + 1)) << static_cast<long long>(j);
  }
  // Unit intervals keep the 44 levels.
  EXPECT_EQ(basis::thb::DyadicKnots(basis::bspline::KnotVector(2, {0, 0, 0, 1, 2, 2, 2})).max_level(), 44);
}

INSTANTIATE_TEST_SUITE_P(Degrees, ThbDegree, ::testing::Values(2, 3));

}  // namespace
