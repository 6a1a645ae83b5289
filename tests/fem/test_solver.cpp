// fem::solve's direct path: the fill-reducing ordering it picks (AMD unless AMD's factor would cost more than
// 1e4 flops per non-zero of A, then METIS) and that both give the solution to the residual bound.
#include <gtest/gtest.h>

#include <vector>

#include "fem/solver.hpp"

using namespace iga;

namespace {
// The 7-point (3D) or 5-point (2D, nz = 1) Laplacian on an nx × ny × nz grid with unit diagonal shift.
Eigen::SparseMatrix<double> grid_laplacian(int nx, int ny, int nz) {
  const auto id = [&](int i, int j, int k) { return i + nx * (j + ny * k); };
  std::vector<Eigen::Triplet<double>> t;
  for (int k = 0; k < nz; ++k) {
    for (int j = 0; j < ny; ++j) {
      for (int i = 0; i < nx; ++i) {
        const int a = id(i, j, k);
        t.emplace_back(a, a, 7.0);
        if (i + 1 < nx) t.emplace_back(a, id(i + 1, j, k), -1.0), t.emplace_back(id(i + 1, j, k), a, -1.0);
        if (j + 1 < ny) t.emplace_back(a, id(i, j + 1, k), -1.0), t.emplace_back(id(i, j + 1, k), a, -1.0);
        if (k + 1 < nz) t.emplace_back(a, id(i, j, k + 1), -1.0), t.emplace_back(id(i, j, k + 1), a, -1.0);
      }
    }
  }
  Eigen::SparseMatrix<double> m(nx * ny * nz, nx * ny * nz);
  m.setFromTriplets(t.begin(), t.end());
  return m;
}
}  // namespace

// A 2D grid factorises with few flops per non-zero (AMD); a 3D grid's AMD factor costs far more than 1e4 flops per
// non-zero once it is large enough (3D separators are planes), and then METIS is chosen. Both solve to the default
// residual bound. The full form (label slow, 21 s) takes a 40³ grid; the quick form (the default run) a 30³ grid
// (27,000 unknowns), whose AMD factor is past the threshold too: 1.1 s in all (2026-12-04).
namespace {
void check_orderings(int n3d) {
  fem::SolverOptions cholmod;
  for (const auto& [a, ordering] : {std::pair{grid_laplacian(60, 60, 1), "amd"}, std::pair{grid_laplacian(n3d, n3d, n3d), "metis"}}) {
    const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(a.rows(), -1.0, 1.0);
    const fem::SolveResult r = fem::solve(a, b, cholmod);
    EXPECT_EQ(r.solver, "cholmod-supernodal-llt");
    EXPECT_EQ(r.ordering, ordering) << a.rows() << " unknowns";
    EXPECT_LE((a * r.x - b).norm() / b.norm(), 1e-12);
  }
}
}  // namespace

TEST(SolverSlow, OrderingFollowsTheFlopsPerNonZero) { check_orderings(40); }

TEST(Solver, OrderingFollowsTheFlopsPerNonZero) {
  check_orderings(30);
  fem::SolverOptions cg;
  cg.kind = fem::SolverKind::ConjugateGradient;
  EXPECT_EQ(fem::solve(grid_laplacian(10, 10, 1), Eigen::VectorXd::Ones(100), cg).ordering, "");
}
