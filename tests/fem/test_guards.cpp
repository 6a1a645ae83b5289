// Issue 14: the solver never returns a solution it cannot vouch for (non-finite input, a relative residual above
// the tolerance), and a run predicted not to fit in memory is refused before it starts, in one line.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "core/error.hpp"
#include "fem/memory.hpp"
#include "fem/solver.hpp"

using namespace iga;

namespace {
// The 1D Laplacian (tridiagonal 2, -1), n × n, both triangles stored: SPD with condition ~ n².
Eigen::SparseMatrix<double> laplacian(Index n) {
  Eigen::SparseMatrix<double> a(n, n);
  std::vector<Eigen::Triplet<double>> t;
  for (Index i = 0; i < n; ++i) {
    t.emplace_back(i, i, 2.0);
    if (i > 0) t.emplace_back(i, i - 1, -1.0);
    if (i + 1 < n) t.emplace_back(i, i + 1, -1.0);
  }
  a.setFromTriplets(t.begin(), t.end());
  a.makeCompressed();
  return a;
}
}  // namespace

TEST(SolverGuards, ResidualAboveTheToleranceIsRefused) {
  const Eigen::SparseMatrix<double> a = laplacian(200);
  const Eigen::VectorXd b = Eigen::VectorXd::Ones(200);
  fem::SolverOptions o;
  const fem::SolveResult ok = fem::solve(a, b, o);
  EXPECT_LE(ok.residual_norm, 1e-12);  // a direct solve of a well-conditioned system
  // The same solve with a tolerance no floating-point solution meets: refused, with the residual in the message.
  o.max_residual = 1e-300;
  try {
    fem::solve(a, b, o);
    FAIL() << "a solution above the residual tolerance was returned";
  } catch (const NumericalError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("relative residual"), std::string::npos) << what;
    EXPECT_NE(what.find("is above 1e-300"), std::string::npos) << what;
  }
  o.kind = fem::SolverKind::ConjugateGradient;
  EXPECT_THROW(fem::solve(a, b, o), NumericalError);
}

TEST(SolverGuards, NonFiniteSystemsAreRefused) {
  Eigen::SparseMatrix<double> a = laplacian(10);
  Eigen::VectorXd b = Eigen::VectorXd::Ones(10);
  b(3) = std::nan("");
  EXPECT_THROW(fem::solve(a, b, {}), NumericalError);
  b(3) = 1.0;
  a.coeffRef(4, 4) = INFINITY;
  EXPECT_THROW(fem::solve(a, b, {}), NumericalError);
}

TEST(MemoryGuards, RefusalNamesWhatItWouldNeedAndTheLimit) {
  const double gib = 1024.0 * 1024.0 * 1024.0;
  EXPECT_NO_THROW(fem::check_memory(0.4 * gib, 0.5 * gib, "this run", "use less"));
  try {
    fem::check_memory(2.0 * gib, 0.5 * gib, "this run (about 1e+06 elements)", "fewer refinement steps");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), "this run (about 1e+06 elements) would need about 2 GiB of memory, more than the "
                                     "0.5 GiB of --max-memory (fewer refinement steps)");
  }
  // The estimates grow with the problem, and 4^14 B-spline elements (issue 14's --refine 14) are far beyond any
  // machine this runs on.
  EXPECT_LT(fem::poisson_memory(1e4, 16), fem::poisson_memory(4e4, 16));
  EXPECT_GT(fem::poisson_memory(std::pow(4.0, 14), 16), 500 * gib);
  EXPECT_GT(fem::available_memory(), 0.0);
}
