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

// A 2D grid factorises with few flops per non-zero (AMD); a 40³ grid's AMD factor costs far more than 1e4 flops per
// non-zero (3D separators are planes), so METIS is chosen. Both solve to the default residual bound.
TEST(Solver, OrderingFollowsTheFlopsPerNonZero) {
  fem::SolverOptions cholmod;
  for (const auto& [a, ordering] : {std::pair{grid_laplacian(60, 60, 1), "amd"}, std::pair{grid_laplacian(40, 40, 40), "metis"}}) {
    const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(a.rows(), -1.0, 1.0);
    const fem::SolveResult r = fem::solve(a, b, cholmod);
    EXPECT_EQ(r.solver, "cholmod-supernodal-llt");
    EXPECT_EQ(r.ordering, ordering) << a.rows() << " unknowns";
    EXPECT_LE((a * r.x - b).norm() / b.norm(), 1e-12);
  }
  fem::SolverOptions cg;
  cg.kind = fem::SolverKind::ConjugateGradient;
  EXPECT_EQ(fem::solve(grid_laplacian(10, 10, 1), Eigen::VectorXd::Ones(100), cg).ordering, "");
}
