// Issue 14, classes 1 and 2: folded planar maps are refused with the element and the physical point;
// clockwise maps are a consistent orientation (solved, the same answer as counter-clockwise); degeneracy is
// judged relative to the element's size, so the unit square in units of 1e±100 is no different from the unit
// square.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "basis/bspline/patches.hpp"
#include "core/error.hpp"
#include "fem/assembler.hpp"
#include "fem/poisson.hpp"
#include "fem/problems.hpp"
#include "quadrature/rule_provider.hpp"
#include "refine/uniform.hpp"

using namespace iga;

namespace {
// The bi-quadratic unit square refined twice (4 × 4 elements), its control points transformed by f.
template <class F>
basis::Geometry square(F f) {
  const basis::Geometry g = refine::refine_uniform(basis::bspline::make_rectangle(2), 2).geometry;
  Eigen::MatrixXd cp = g.control_points();
  for (Index i = 0; i < cp.rows(); ++i) cp.row(i) = f(Eigen::Vector2d(cp.row(i).transpose())).transpose();
  return basis::Geometry(g.space_ptr(), cp);
}

double area(const basis::Geometry& g) {
  const quadrature::Gauss rules(4);
  return fem::Assembler(g, rules).integrate(1, [](const fem::ElementContext& c, Eigen::Ref<Eigen::VectorXd> out) {
    out(0) = c.weight.sum();
  })(0);
}

fem::PoissonProblem sine_problem() {
  const fem::ManufacturedProblem mp = fem::manufactured_problem("sine", 0.0);
  fem::PoissonProblem p;
  p.source = mp.source;
  p.exact = mp.exact;
  p.dirichlet = mp.exact;
  return p;
}
}  // namespace

// A control point dragged across its neighbours: det J changes sign inside the domain. ∫|det J| would still be
// a positive "area"; the evaluation refuses the fold instead, naming the element and the point.
TEST(GeometryGuards, FoldIsRefusedWithElementAndPoint) {
  const basis::Geometry g = square([](const Eigen::Vector2d& x) { return x; });
  Eigen::MatrixXd cp = g.control_points();
  // Control point (1, 1) of the 6 × 6 net sits at (1/8, 1/8): move it beyond (2, 2) at (3/8, 3/8) and further.
  cp.row(1 + 6 * 1) << 0.7, 0.7;
  const basis::Geometry folded(g.space_ptr(), cp);
  EXPECT_EQ(folded.orientation(), 1);
  try {
    area(folded);
    FAIL() << "a folded map was integrated";
  } catch (const NumericalError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("element "), std::string::npos) << what;
    EXPECT_NE(what.find("folds over"), std::string::npos) << what;
    EXPECT_NE(what.find(" at ("), std::string::npos) << what;
  }
}

// The same square traversed clockwise (x ↔ y swapped): det J < 0 everywhere, orientation −1, and the solve gives
// the counter-clockwise result (stiffness and load use |det J|; the outward conormal comes from the normal).
TEST(GeometryGuards, ClockwiseIsAnOrientationNotAFold) {
  const basis::Geometry ccw = square([](const Eigen::Vector2d& x) { return x; });
  const basis::Geometry cw = square([](const Eigen::Vector2d& x) { return Eigen::Vector2d(x.y(), x.x()); });
  EXPECT_EQ(ccw.orientation(), 1);
  EXPECT_EQ(cw.orientation(), -1);
  EXPECT_NEAR(area(cw), 1.0, 1e-14);
  const quadrature::Gauss rules(3);
  const fem::PoissonResult a = fem::solve_poisson(ccw, rules, sine_problem(), {});
  const fem::PoissonResult b = fem::solve_poisson(cw, rules, sine_problem(), {});
  ASSERT_TRUE(a.errors && b.errors);
  // sin πx sin πy is symmetric in x and y: the two maps describe the same problem; the errors agree to rounding.
  EXPECT_NEAR(a.errors->l2, b.errors->l2, 1e-14);
  EXPECT_NEAR(a.errors->h1, b.errors->h1, 1e-12);
}

// The unit square in units of 1e100 and 1e-100: its area is 1e±200 (exactly: the scaled formulas differ from
// the unscaled ones by powers of two only, up to the rounding of the scale itself), not "degenerate".
TEST(GeometryGuards, DegeneracyIsRelativeToTheElement) {
  for (const double s : {1e100, 1e-100, 1e150, 1e-150}) {
    const basis::Geometry g = square([s](const Eigen::Vector2d& x) { return Eigen::Vector2d(s * x); });
    EXPECT_NEAR(area(g) / (s * s), 1.0, 1e-13) << "scale " << s;
  }
  // All control points on a line: |x_u × x_v| = 0 in any units: refused.
  const basis::Geometry line = square([](const Eigen::Vector2d& x) { return Eigen::Vector2d(x.x() + x.y(), x.x() + x.y()); });
  EXPECT_THROW(area(line), NumericalError);
}

// Poisson on the square in units of 1e-100: -Δu = f scales as 1e200 f; the relative errors are those of the unit
// square.
TEST(GeometryGuards, PoissonIsScaleInvariant) {
  const double s = 1e-100;
  const basis::Geometry unit = square([](const Eigen::Vector2d& x) { return x; });
  const basis::Geometry tiny = square([s](const Eigen::Vector2d& x) { return Eigen::Vector2d(s * x); });
  const quadrature::Gauss rules(3);
  const fem::PoissonResult a = fem::solve_poisson(unit, rules, sine_problem(), {});
  fem::PoissonProblem scaled;
  scaled.exact = fem::make_function([s](const Eigen::Vector3d& x) { return std::sin(M_PI * x.x() / s) * std::sin(M_PI * x.y() / s); });
  scaled.source = fem::make_function([s](const Eigen::Vector3d& x) {
    return 2 * M_PI * M_PI / (s * s) * std::sin(M_PI * x.x() / s) * std::sin(M_PI * x.y() / s);
  });
  scaled.dirichlet = scaled.exact;
  const fem::PoissonResult b = fem::solve_poisson(tiny, rules, scaled, {});
  ASSERT_TRUE(a.errors && b.errors);
  EXPECT_NEAR(b.errors->l2 / b.errors->l2_exact, a.errors->l2 / a.errors->l2_exact, 1e-10);
  EXPECT_NEAR(b.domain_measure / (s * s), 1.0, 1e-13);
}
