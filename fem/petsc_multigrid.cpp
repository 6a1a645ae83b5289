#include "fem/petsc_multigrid.hpp"

#include <string>
#include <vector>

#include "core/error.hpp"
#include "fem/petsc_util.hpp"

namespace iga::fem::petsc {

namespace {

// The interpolation from level `coarse` to level `fine` as a distributed AIJ matrix: each rank inserts the rows
// it holds of the fine level, its columns laid out as the coarse level is.
void interpolation(MPI_Comm comm, int rank, const Eigen::SparseMatrix<double, Eigen::RowMajor>& p,
                   const MultigridLevel& coarse, const MultigridLevel& fine, Mat* out) {
  const std::size_t r = static_cast<std::size_t>(rank);
  const Index lo = fine.offsets[r], hi = fine.offsets[r + 1];
  const Index clo = coarse.offsets[r], chi = coarse.offsets[r + 1];
  std::vector<PetscInt> d_nnz(static_cast<std::size_t>(hi - lo), 0), o_nnz(static_cast<std::size_t>(hi - lo), 0);
  for (Index i = lo; i < hi; ++i) {
    for (Eigen::SparseMatrix<double, Eigen::RowMajor>::InnerIterator it(p, i); it; ++it) {
      ++(it.col() >= clo && it.col() < chi ? d_nnz : o_nnz)[static_cast<std::size_t>(i - lo)];
    }
  }
  check(MatCreateAIJ(comm, static_cast<PetscInt>(hi - lo), static_cast<PetscInt>(chi - clo), static_cast<PetscInt>(fine.size()),
                     static_cast<PetscInt>(coarse.size()), 0, d_nnz.data(), 0, o_nnz.data(), out),
        "MatCreateAIJ");
  std::vector<PetscInt> cols;
  for (Index i = lo; i < hi; ++i) {
    const PetscInt row = static_cast<PetscInt>(i);
    const Index begin = p.outerIndexPtr()[i], end = p.outerIndexPtr()[i + 1];
    cols.assign(p.innerIndexPtr() + begin, p.innerIndexPtr() + end);
    check(MatSetValues(*out, 1, &row, static_cast<PetscInt>(cols.size()), cols.data(), p.valuePtr() + begin, INSERT_VALUES),
          "MatSetValues");
  }
  check(MatAssemblyBegin(*out, MAT_FINAL_ASSEMBLY), "MatAssemblyBegin");
  check(MatAssemblyEnd(*out, MAT_FINAL_ASSEMBLY), "MatAssemblyEnd");
}

std::string ksp_and_pc(KSP ksp) {
  KSPType kt = nullptr;
  PC pc = nullptr;
  PCType pt = nullptr;
  check(KSPGetType(ksp, &kt), "KSPGetType");
  check(KSPGetPC(ksp, &pc), "KSPGetPC");
  check(PCGetType(pc, &pt), "PCGetType");
  return std::string(kt ? kt : "?") + "+" + (pt ? pt : "?");
}

}  // namespace

void set_multigrid(PC pc, MPI_Comm comm, const SolverOptions& options, int components, const MultigridLevel& finest) {
  static const std::vector<Eigen::SparseMatrix<double>> none;
  const std::vector<Eigen::SparseMatrix<double>>& hierarchy = options.hierarchy ? *options.hierarchy : none;
  const std::vector<MultigridLevel> levels = multigrid_levels(hierarchy, components, finest);
  int rank = 0;
  MPI_Comm_rank(comm, &rank);
  const PetscInt n = static_cast<PetscInt>(levels.size());
  check(PCSetType(pc, PCMG), "PCSetType");
  check(PCMGSetLevels(pc, n, nullptr), "PCMGSetLevels");
  check(PCMGSetType(pc, PC_MG_MULTIPLICATIVE), "PCMGSetType");
  check(PCMGSetCycleType(pc, PC_MG_CYCLE_V), "PCMGSetCycleType");
  check(PCMGSetGalerkin(pc, PC_MG_GALERKIN_BOTH), "PCMGSetGalerkin");
  for (PetscInt l = 1; l < n; ++l) {
    const std::size_t k = static_cast<std::size_t>(l);
    const Eigen::SparseMatrix<double, Eigen::RowMajor> p =
        reduced_prolongation(hierarchy[k - 1], components, levels[k - 1], levels[k]);
    Mat m = nullptr;
    interpolation(comm, rank, p, levels[k - 1], levels[k], &m);
    const PetscErrorCode code = PCMGSetInterpolation(pc, l, m);  // PCMG keeps a reference
    MatDestroy(&m);
    check(code, "PCMGSetInterpolation");
    KSP smoother = nullptr;
    check(PCMGGetSmoother(pc, l, &smoother), "PCMGGetSmoother");
    check(KSPSetType(smoother, KSPCHEBYSHEV), "KSPSetType");
    PC spc = nullptr;
    check(KSPGetPC(smoother, &spc), "KSPGetPC");
    check(PCSetType(spc, PCJACOBI), "PCSetType");
    check(KSPSetTolerances(smoother, PETSC_DEFAULT, PETSC_DEFAULT, PETSC_DEFAULT, 2), "KSPSetTolerances");
  }
}

void describe_multigrid(PC pc, SolveResult& s) {
  PetscInt n = 0;
  check(PCMGGetLevels(pc, &n), "PCMGGetLevels");
  s.multigrid.levels = static_cast<int>(n);
  KSP coarse = nullptr;
  check(PCMGGetCoarseSolve(pc, &coarse), "PCMGGetCoarseSolve");
  s.multigrid.coarse_solver = ksp_and_pc(coarse);
  if (n > 1) {
    KSP smoother = nullptr;
    check(PCMGGetSmoother(pc, n - 1, &smoother), "PCMGGetSmoother");
    PetscInt steps = 0;
    check(KSPGetTolerances(smoother, nullptr, nullptr, nullptr, &steps), "KSPGetTolerances");
    s.multigrid.smoother = ksp_and_pc(smoother) + " x" + std::to_string(steps);
  }
}

}  // namespace iga::fem::petsc
