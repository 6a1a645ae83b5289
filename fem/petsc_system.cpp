// The distributed system on PETSc (fem/linear_system.hpp): an MPIAIJ matrix and an MPI vector in the partition's
// numbering, preallocated from the owned rows' pattern, filled by MatSetValues(ADD_VALUES) from each rank's
// elements; the conditions as u = u0 + T w (when T is a selection, the constrained rows and columns made the
// identity's in place; else MatPtAP); the solve by a KSP (CG + GAMG unless the options say otherwise).
#include <petscksp.h>

#include <algorithm>
#include <cstdlib>
#include <limits>
#include <chrono>
#include <iomanip>
#include <mutex>
#include <sstream>

#include "core/error.hpp"
#include "fem/linear_system.hpp"
#include "fem/parallel.hpp"
#include "fem/partition.hpp"
#include "fem/petsc_multigrid.hpp"
#include "fem/petsc_util.hpp"

namespace iga::fem {

namespace {

using namespace petsc;

class PetscSystem;

// The option database of one solve: PETSC_OPTIONS and then the solver's own options (which win), made the default
// for the objects created while it lives, so options never carry over from one solve into the next.
class SolveOptions {
 public:
  explicit SolveOptions(const std::string& options) {
    check(PetscOptionsCreate(&db_), "PetscOptionsCreate");
    if (const char* env = std::getenv("PETSC_OPTIONS"); env && PetscOptionsInsertString(db_, env) != 0) {
      PetscOptionsDestroy(&db_);
      throw InputError(std::string("PETSC_OPTIONS '") + env + "': not PETSc's option syntax");
    }
    if (!options.empty() && PetscOptionsInsertString(db_, options.c_str()) != 0) {
      PetscOptionsDestroy(&db_);
      throw InputError("PETSc options '" + options + "': not PETSc's option syntax");
    }
    PetscOptionsPush(db_);
  }
  ~SolveOptions() {
    PetscOptionsPop();
    PetscOptionsDestroy(&db_);
  }
  SolveOptions(const SolveOptions&) = delete;
  SolveOptions& operator=(const SolveOptions&) = delete;
  /// An option no object read is a misspelling or one for another solver: named, not silently ignored. Options
  /// that PETSc read at its initialisation (PETSC_OPTIONS' -log_view, -malloc_debug, ...) count as used.
  void check_all_used() const {
    PetscInt left = 0;
    char** names = nullptr;
    char** values = nullptr;
    check(PetscOptionsLeftGet(db_, &left, &names, &values), "PetscOptionsLeftGet");
    std::string unused;
    for (PetscInt k = 0; k < left && unused.empty(); ++k) {
      if (!names[k]) continue;
      PetscBool global = PETSC_FALSE;
      PetscOptionsPop();  // the global database: what PetscInitialize read
      const PetscErrorCode code = PetscOptionsUsed(nullptr, names[k], &global);
      PetscOptionsPush(db_);
      check(code, "PetscOptionsUsed");
      if (!global) unused = names[k];
    }
    PetscOptionsLeftRestore(db_, &left, &names, &values);
    if (!unused.empty()) {
      throw InputError("PETSc option -" + unused + " was not used by the solver (misspelt, or for another KSP/PC?)");
    }
  }

 private:
  PetscOptions db_ = nullptr;
};

class PetscSink final : public SystemSink {
 public:
  explicit PetscSink(PetscSystem& system) : system_(system) {}
  bool takes(Index e) const override;
  void add(Index slot, std::span<const Index> dofs, const Eigen::MatrixXd& k, const Eigen::VectorXd& f) override;

 private:
  PetscSystem& system_;
};

class PetscSystem final : public LinearSystem {
 public:
  PetscSystem(const Assembler& assembler, const SolverOptions& options);
  SystemSink& sink() override { return sink_; }
  AssemblyStats total(const AssemblyStats& own) const override {
    return {sum_over_ranks(own.quadrature_points), sum_over_ranks(own.measure)};
  }
  const std::vector<char>* own_elements() const override { return &own_; }
  std::optional<std::string> first_failure(const std::optional<std::string>& mine) const override {
    const int me = mine ? rank_ : std::numeric_limits<int>::max();
    int first = me;
    MPI_Allreduce(&me, &first, 1, MPI_INT, MPI_MIN, comm_);
    if (first == std::numeric_limits<int>::max()) return std::nullopt;
    std::string text = first == rank_ ? *mine : std::string();
    int length = static_cast<int>(text.size());
    MPI_Bcast(&length, 1, MPI_INT, first, comm_);
    text.resize(static_cast<std::size_t>(length));
    MPI_Bcast(text.data(), length, MPI_CHAR, first, comm_);
    return "rank " + std::to_string(first) + " of " + std::to_string(ranks()) + ": " + text;
  }
  Eigen::VectorXd sum(const Eigen::VectorXd& own) const override {
    Eigen::VectorXd out(own.size());
    MPI_Allreduce(own.data(), out.data(), static_cast<int>(own.size()), MPI_DOUBLE, MPI_SUM, comm_);
    return out;
  }
  void add(const Eigen::SparseMatrix<double>& a, const Eigen::VectorXd& b) override;
  double load_sum() override;
  Eigen::SparseMatrix<double> global_matrix() override;
  Eigen::VectorXd global_load() override;
  SolveResult solve(const DirichletConditions& bc) override;

 private:
  friend class PetscSink;
  void close();
  // The reduced operator and load for u = u0 + T w, and the map back: fills a_red, b_red, and u from w later.
  struct Reduced;
  void reduce(const DirichletConditions& bc, Reduced& r);
  void select_free(const std::vector<char>& fixed, Vec rhs, Reduced& r);  // reduce() when T is a selection
  Eigen::VectorXd gather(Vec v) const;  // a vector in distributed numbering, whole and in dof numbering
  // r.w = the free entries of u (dof numbering, the whole field): the KSP's initial guess.
  void start_from(const Eigen::VectorXd& u, Reduced& r) const;
  // KSP (CG + GAMG unless the options say otherwise) on r.a w = r.b; iterations and name into s.
  void run_ksp(Reduced& r, PetscInt size, SolveResult& s);

  const Assembler& assembler_;
  SolverOptions options_;
  MPI_Comm comm_ = PETSC_COMM_WORLD;
  int rank_ = 0;
  Partition part_;
  std::vector<char> own_;  // per element: 1 for this rank's
  Index lo_ = 0, hi_ = 0;  // owned rows [lo, hi) of the distributed numbering
  MatH a_;
  VecH b_;
  std::mutex insert_;
  PetscSink sink_;
};

bool PetscSink::takes(Index e) const {
  return system_.part_.element_owner[static_cast<std::size_t>(e)] == system_.rank_;
}

void PetscSink::add(Index /*slot*/, std::span<const Index> dofs, const Eigen::MatrixXd& k, const Eigen::VectorXd& f) {
  thread_local std::vector<PetscInt> rows;
  rows.resize(dofs.size());
  for (std::size_t i = 0; i < dofs.size(); ++i) rows[i] = static_cast<PetscInt>(system_.part_.number[static_cast<std::size_t>(dofs[i])]);
  const PetscInt n = static_cast<PetscInt>(rows.size());
  // PETSc's insertion is not thread-safe. Within a colour no two elements share a dof, so every entry still
  // receives its terms in colour order, whatever the threads do.
  std::lock_guard<std::mutex> lock(system_.insert_);
  check(MatSetValues(system_.a_, n, rows.data(), n, rows.data(), k.data(), ADD_VALUES), "MatSetValues");
  check(VecSetValues(system_.b_, n, rows.data(), f.data(), ADD_VALUES), "VecSetValues");
}

PetscSystem::PetscSystem(const Assembler& assembler, const SolverOptions& options)
    : assembler_(assembler), options_(options), sink_(*this) {
  if (!parallel_session_open()) {
    throw InputError("the petsc solver needs PETSc initialised: open a fem::ParallelSession first");
  }
  const basis::Space& space = assembler.geometry().space();
  assembler.plan(false);  // the colouring of the element loop; the pattern is the distributed matrix's own
  rank_ = rank();
  const int d = assembler.components();
  const Partition scalar = partition_elements(assembler.geometry(), parse_partition(options.partition));
  part_ = with_components(scalar, d);
  own_.resize(part_.element_owner.size());
  for (std::size_t e = 0; e < own_.size(); ++e) own_[e] = part_.element_owner[e] == rank_;
  lo_ = part_.offsets[static_cast<std::size_t>(rank_)];
  hi_ = part_.offsets[static_cast<std::size_t>(rank_) + 1];
  // Preallocation from the scalar space's pattern, then per component: a field row couples d columns per scalar one.
  const Index n = space.num_dofs(), local = hi_ - lo_;
  const Index slo = scalar.offsets[static_cast<std::size_t>(rank_)], shi = scalar.offsets[static_cast<std::size_t>(rank_) + 1];
  // Preallocation from the owned rows' pattern: row i's columns are the dofs of the elements that touch dof i.
  std::vector<Index> start(static_cast<std::size_t>(n) + 1, 0), elems;
  for (Index e = 0; e < space.num_elements(); ++e) {
    for (Index d : space.dofs(e)) ++start[static_cast<std::size_t>(d) + 1];
  }
  for (Index d = 0; d < n; ++d) start[static_cast<std::size_t>(d) + 1] += start[static_cast<std::size_t>(d)];
  elems.resize(static_cast<std::size_t>(start.back()));
  std::vector<Index> fill(start.begin(), start.end() - 1);
  for (Index e = 0; e < space.num_elements(); ++e) {
    for (Index d : space.dofs(e)) elems[static_cast<std::size_t>(fill[static_cast<std::size_t>(d)]++)] = e;
  }
  std::vector<PetscInt> d_nnz(static_cast<std::size_t>(local), 0), o_nnz(static_cast<std::size_t>(local), 0);
  std::vector<Index> seen(static_cast<std::size_t>(n), -1);
  for (Index i = 0; i < n; ++i) {
    const Index row = scalar.number[static_cast<std::size_t>(i)];
    if (row < slo || row >= shi) continue;
    PetscInt on = 0, off = 0;
    for (Index k = start[static_cast<std::size_t>(i)]; k < start[static_cast<std::size_t>(i) + 1]; ++k) {
      for (Index c : space.dofs(elems[static_cast<std::size_t>(k)])) {
        if (seen[static_cast<std::size_t>(c)] == i) continue;
        seen[static_cast<std::size_t>(c)] = i;
        const Index col = scalar.number[static_cast<std::size_t>(c)];
        ++(col >= slo && col < shi ? on : off);
      }
    }
    for (int c = 0; c < d; ++c) {
      const std::size_t r = static_cast<std::size_t>(d * row + c - lo_);
      d_nnz[r] = d * on;
      o_nnz[r] = d * off;
    }
  }
  const PetscInt pl = static_cast<PetscInt>(local), pn = static_cast<PetscInt>(d * n);
  check(MatCreateAIJ(comm_, pl, pl, pn, pn, 0, d_nnz.data(), 0, o_nnz.data(), a_.out()), "MatCreateAIJ");
  // Element matrices are column-major (Eigen).
  check(MatSetOption(a_, MAT_ROW_ORIENTED, PETSC_FALSE), "MatSetOption");
  check(MatSetOption(a_, MAT_NEW_NONZERO_ALLOCATION_ERR, PETSC_TRUE), "MatSetOption");
  check(VecCreateMPI(comm_, pl, pn, b_.out()), "VecCreateMPI");
}

void PetscSystem::add(const Eigen::SparseMatrix<double>& a, const Eigen::VectorXd& b) {
  std::vector<PetscInt> cols;
  std::vector<double> vals;
  if (a.nonZeros() > 0) {
    // Each rank adds the rows it owns. The terms lie on the boundary, inside the pattern of the elements there.
    const Eigen::SparseMatrix<double, Eigen::RowMajor> rows = a;
    for (Index i = 0; i < rows.outerSize(); ++i) {
      const PetscInt row = static_cast<PetscInt>(part_.number[static_cast<std::size_t>(i)]);
      if (row < lo_ || row >= hi_) continue;
      cols.clear();
      vals.clear();
      for (Eigen::SparseMatrix<double, Eigen::RowMajor>::InnerIterator it(rows, i); it; ++it) {
        cols.push_back(static_cast<PetscInt>(part_.number[static_cast<std::size_t>(it.col())]));
        vals.push_back(it.value());
      }
      check(MatSetValues(a_, 1, &row, static_cast<PetscInt>(cols.size()), cols.data(), vals.data(), ADD_VALUES),
            "MatSetValues");
    }
  }
  for (Index i = 0; i < b.size(); ++i) {
    const PetscInt row = static_cast<PetscInt>(part_.number[static_cast<std::size_t>(i)]);
    if (row >= lo_ && row < hi_ && b(i) != 0.0) check(VecSetValue(b_, row, b(i), ADD_VALUES), "VecSetValue");
  }
}

void PetscSystem::close() {
  check(MatAssemblyBegin(a_, MAT_FINAL_ASSEMBLY), "MatAssemblyBegin");
  check(MatAssemblyEnd(a_, MAT_FINAL_ASSEMBLY), "MatAssemblyEnd");
  check(VecAssemblyBegin(b_), "VecAssemblyBegin");
  check(VecAssemblyEnd(b_), "VecAssemblyEnd");
}

double PetscSystem::load_sum() {
  close();
  PetscScalar s = 0;
  check(VecSum(b_, &s), "VecSum");
  return s;
}

Eigen::VectorXd PetscSystem::gather(Vec v) const {
  ScatterH scatter;
  VecH all;
  check(VecScatterCreateToAll(v, scatter.out(), all.out()), "VecScatterCreateToAll");
  check(VecScatterBegin(scatter, v, all, INSERT_VALUES, SCATTER_FORWARD), "VecScatterBegin");
  check(VecScatterEnd(scatter, v, all, INSERT_VALUES, SCATTER_FORWARD), "VecScatterEnd");
  const PetscScalar* x = nullptr;
  check(VecGetArrayRead(all, &x), "VecGetArrayRead");
  Eigen::VectorXd out(static_cast<Index>(part_.number.size()));
  for (std::size_t d = 0; d < part_.number.size(); ++d) out(static_cast<Index>(d)) = x[part_.number[d]];
  check(VecRestoreArrayRead(all, &x), "VecRestoreArrayRead");
  return out;
}

Eigen::VectorXd PetscSystem::global_load() {
  if (!b_) throw InputError("the distributed system was solved: its assembled load is gone");
  close();
  return gather(b_);
}

Eigen::SparseMatrix<double> PetscSystem::global_matrix() {
  if (!a_) throw InputError("the distributed system was solved: its assembled matrix is gone");
  close();
  // The owned rows as triplets (dof numbering), gathered on every rank.
  std::vector<Index> inverse(part_.number.size());
  for (std::size_t d = 0; d < part_.number.size(); ++d) inverse[static_cast<std::size_t>(part_.number[d])] = static_cast<Index>(d);
  std::vector<long long> ij;
  std::vector<double> v;
  for (PetscInt row = static_cast<PetscInt>(lo_); row < static_cast<PetscInt>(hi_); ++row) {
    PetscInt nc = 0;
    const PetscInt* cols = nullptr;
    const PetscScalar* vals = nullptr;
    check(MatGetRow(a_, row, &nc, &cols, &vals), "MatGetRow");
    for (PetscInt k = 0; k < nc; ++k) {
      ij.push_back(inverse[static_cast<std::size_t>(row)]);
      ij.push_back(inverse[static_cast<std::size_t>(cols[k])]);
      v.push_back(vals[k]);
    }
    check(MatRestoreRow(a_, row, &nc, &cols, &vals), "MatRestoreRow");
  }
  const int size = ranks();
  std::vector<int> counts(static_cast<std::size_t>(size)), displs(static_cast<std::size_t>(size), 0);
  const int mine = static_cast<int>(v.size());
  MPI_Allgather(&mine, 1, MPI_INT, counts.data(), 1, MPI_INT, comm_);
  for (int r = 1; r < size; ++r) displs[static_cast<std::size_t>(r)] = displs[static_cast<std::size_t>(r) - 1] + counts[static_cast<std::size_t>(r) - 1];
  const int total = displs.back() + counts.back();
  std::vector<double> all_v(static_cast<std::size_t>(total));
  MPI_Allgatherv(v.data(), mine, MPI_DOUBLE, all_v.data(), counts.data(), displs.data(), MPI_DOUBLE, comm_);
  std::vector<int> counts2(counts), displs2(displs);
  for (auto& c : counts2) c *= 2;
  for (auto& d : displs2) d *= 2;
  std::vector<long long> all_ij(2 * static_cast<std::size_t>(total));
  MPI_Allgatherv(ij.data(), 2 * mine, MPI_LONG_LONG, all_ij.data(), counts2.data(), displs2.data(), MPI_LONG_LONG, comm_);
  std::vector<Eigen::Triplet<double>> t;
  t.reserve(static_cast<std::size_t>(total));
  for (int k = 0; k < total; ++k) {
    t.emplace_back(static_cast<Index>(all_ij[2 * static_cast<std::size_t>(k)]),
                   static_cast<Index>(all_ij[2 * static_cast<std::size_t>(k) + 1]), all_v[static_cast<std::size_t>(k)]);
  }
  const Index n = static_cast<Index>(part_.number.size());
  Eigen::SparseMatrix<double> out(n, n);
  out.setFromTriplets(t.begin(), t.end());
  return out;
}

struct PetscSystem::Reduced {
  MatH a, t;      // reduced operator; T (coupled conditions only)
  VecH b, w, u0;  // reduced load and solution; u0 in distributed numbering
  std::vector<PetscInt> fixed_rows;  // selection T: the owned constrained rows, identity rows of a
  Index free_dofs = 0;
  MultigridLevel finest;  // the free dofs' reduced indices and their ranks (the finest level of a multigrid)
};

void PetscSystem::reduce(const DirichletConditions& bc, Reduced& r) {
  const Index n = static_cast<Index>(part_.number.size());
  std::vector<char> fixed(static_cast<std::size_t>(n), 0);
  for (Index d : bc.dofs) fixed[static_cast<std::size_t>(d)] = 1;
  // u0: the prescribed values on the constrained dofs this rank owns.
  check(VecDuplicate(b_, r.u0.out()), "VecDuplicate");
  for (std::size_t k = 0; k < bc.dofs.size(); ++k) {
    const PetscInt row = static_cast<PetscInt>(part_.number[static_cast<std::size_t>(bc.dofs[k])]);
    if (row >= lo_ && row < hi_) check(VecSetValue(r.u0, row, bc.values(static_cast<Index>(k)), INSERT_VALUES), "VecSetValue");
  }
  check(VecAssemblyBegin(r.u0), "VecAssemblyBegin");
  check(VecAssemblyEnd(r.u0), "VecAssemblyEnd");
  VecH rhs;  // b − A u0
  check(VecDuplicate(b_, rhs.out()), "VecDuplicate");
  check(MatMult(a_, r.u0, rhs), "MatMult");
  check(VecAYPX(rhs, -1.0, b_), "VecAYPX");
  // The reduced numbering: free dofs in distributed order, so rank r holds its own free dofs.
  std::vector<Index> inverse(static_cast<std::size_t>(n));
  for (Index d = 0; d < n; ++d) inverse[static_cast<std::size_t>(part_.number[static_cast<std::size_t>(d)])] = d;
  std::vector<PetscInt> reduced(static_cast<std::size_t>(n), -1), owned_free;
  PetscInt next = 0;
  r.finest.offsets.assign(part_.offsets.size(), 0);
  int holder = 0;  // the rank holding distributed row `row`
  for (Index row = 0; row < n; ++row) {
    while (row >= part_.offsets[static_cast<std::size_t>(holder) + 1]) r.finest.offsets[static_cast<std::size_t>(++holder)] = next;
    const Index d = inverse[static_cast<std::size_t>(row)];
    if (fixed[static_cast<std::size_t>(d)]) continue;
    if (row >= lo_ && row < hi_) owned_free.push_back(static_cast<PetscInt>(row));
    reduced[static_cast<std::size_t>(d)] = next++;
  }
  while (static_cast<std::size_t>(holder) + 1 < r.finest.offsets.size()) r.finest.offsets[static_cast<std::size_t>(++holder)] = next;
  r.finest.reduced.assign(reduced.begin(), reduced.end());
  r.free_dofs = static_cast<Index>(next);
  r.finest.constrained = bc.dofs;
  r.finest.coupling = bc.coupling;
  if (bc.coupling.nonZeros() == 0) {
    select_free(fixed, rhs, r);
    return;
  }
  // Coupled conditions: T = identity on the free dofs, −coupling on the constrained ones; Tᵀ A T and Tᵀ (b − A u0).
  const PetscInt local_free = static_cast<PetscInt>(owned_free.size());
  check(MatCreate(comm_, r.t.out()), "MatCreate");
  check(MatSetSizes(r.t, static_cast<PetscInt>(hi_ - lo_), local_free, static_cast<PetscInt>(n), next), "MatSetSizes");
  check(MatSetType(r.t, MATAIJ), "MatSetType");
  Index most = 1;
  for (std::size_t k = 0; k < bc.dofs.size(); ++k) most = std::max<Index>(most, bc.coupling.row(static_cast<Index>(k)).nonZeros());
  check(MatSeqAIJSetPreallocation(r.t, static_cast<PetscInt>(most), nullptr), "MatSeqAIJSetPreallocation");
  check(MatMPIAIJSetPreallocation(r.t, static_cast<PetscInt>(most), nullptr, static_cast<PetscInt>(most), nullptr),
        "MatMPIAIJSetPreallocation");
  for (Index d = 0; d < n; ++d) {
    const PetscInt row = static_cast<PetscInt>(part_.number[static_cast<std::size_t>(d)]);
    if (row < lo_ || row >= hi_ || fixed[static_cast<std::size_t>(d)]) continue;
    check(MatSetValue(r.t, row, reduced[static_cast<std::size_t>(d)], 1.0, INSERT_VALUES), "MatSetValue");
  }
  for (std::size_t k = 0; k < bc.dofs.size(); ++k) {
    const PetscInt row = static_cast<PetscInt>(part_.number[static_cast<std::size_t>(bc.dofs[k])]);
    if (row < lo_ || row >= hi_) continue;
    for (Eigen::SparseMatrix<double, Eigen::RowMajor>::InnerIterator it(bc.coupling, static_cast<Index>(k)); it; ++it) {
      const PetscInt col = reduced[static_cast<std::size_t>(it.col())];
      if (col < 0) throw InputError("coupled Dirichlet conditions: a constrained dof depends on another constrained dof");
      check(MatSetValue(r.t, row, col, -it.value(), INSERT_VALUES), "MatSetValue");
    }
  }
  check(MatAssemblyBegin(r.t, MAT_FINAL_ASSEMBLY), "MatAssemblyBegin");
  check(MatAssemblyEnd(r.t, MAT_FINAL_ASSEMBLY), "MatAssemblyEnd");
  check(MatPtAP(a_, r.t, MAT_INITIAL_MATRIX, PETSC_DEFAULT, r.a.out()), "MatPtAP");
  check(MatCreateVecs(r.t, r.b.out(), nullptr), "MatCreateVecs");
  check(MatMultTranspose(r.t, rhs, r.b), "MatMultTranspose");
}

// T selects the free dofs. Instead of copying A_ff out (MatCreateSubMatrix allocates and fills a second matrix:
// 1.7 s of the multigrid's 7.0 s at 1.05e6 dofs, and its memory), the constrained rows and columns of A become
// those of the identity in place (MatZeroRowsColumns, 0.1 s there) and b − A u0 is zero on them:
// [A_ff 0; 0 I] [w_f; w_c] = [(b − A u0)_f; 0]. Its solution is w_c = 0 and the reduced system's w_f, and its
// residual is the reduced system's; a Krylov solve started from w_c = 0 keeps w_c = 0 (the blocks do not couple).
// The finest multigrid level is then numbered like A: free dofs keep their rows, constrained ones have none
// (their prolongation rows are empty).
void PetscSystem::select_free(const std::vector<char>& fixed, Vec rhs, Reduced& r) {
  const Index n = static_cast<Index>(part_.number.size());
  std::vector<PetscInt> rows;
  for (Index d = 0; d < n; ++d) {
    const PetscInt row = static_cast<PetscInt>(part_.number[static_cast<std::size_t>(d)]);
    if (fixed[static_cast<std::size_t>(d)] && row >= lo_ && row < hi_) rows.push_back(row);
  }
  check(MatZeroRowsColumns(a_, static_cast<PetscInt>(rows.size()), rows.data(), 1.0, nullptr, nullptr),
        "MatZeroRowsColumns");
  *r.a.out() = a_;
  check(PetscObjectReference(reinterpret_cast<PetscObject>(static_cast<Mat>(a_))), "PetscObjectReference");
  check(VecDuplicate(rhs, r.b.out()), "VecDuplicate");
  check(VecCopy(rhs, r.b), "VecCopy");
  for (PetscInt row : rows) check(VecSetValue(r.b, row, 0.0, INSERT_VALUES), "VecSetValue");
  check(VecAssemblyBegin(r.b), "VecAssemblyBegin");
  check(VecAssemblyEnd(r.b), "VecAssemblyEnd");
  r.fixed_rows = std::move(rows);
  r.finest.offsets = part_.offsets;
  for (Index d = 0; d < n; ++d) {
    r.finest.reduced[static_cast<std::size_t>(d)] =
        fixed[static_cast<std::size_t>(d)] ? -1 : part_.number[static_cast<std::size_t>(d)];
  }
}

void PetscSystem::start_from(const Eigen::VectorXd& u, Reduced& r) const {
  if (u.size() != static_cast<Index>(r.finest.reduced.size())) {
    throw InputError("initial guess of " + std::to_string(u.size()) + " entries for a system of " +
                     std::to_string(r.finest.reduced.size()) + " dofs");
  }
  if (!u.allFinite()) throw NumericalError("the initial guess of the solver is not finite");
  const std::size_t me = static_cast<std::size_t>(rank_);
  const Index lo = r.finest.offsets[me], hi = r.finest.offsets[me + 1];
  for (std::size_t d = 0; d < r.finest.reduced.size(); ++d) {
    const Index i = r.finest.reduced[d];
    if (i >= lo && i < hi) check(VecSetValue(r.w, static_cast<PetscInt>(i), u(static_cast<Index>(d)), INSERT_VALUES), "VecSetValue");
  }
  check(VecAssemblyBegin(r.w), "VecAssemblyBegin");
  check(VecAssemblyEnd(r.w), "VecAssemblyEnd");
}

void PetscSystem::run_ksp(Reduced& r, PetscInt size, SolveResult& s) {
  KspH ksp;
  check(KSPCreate(comm_, ksp.out()), "KSPCreate");
  check(KSPSetOperators(ksp, r.a, r.a), "KSPSetOperators");
  check(KSPSetType(ksp, KSPCG), "KSPSetType");
  PC pc = nullptr;
  check(KSPGetPC(ksp, &pc), "KSPGetPC");
  if (options_.kind == SolverKind::Multigrid) {
    set_multigrid(pc, comm_, options_, assembler_.components(), r.finest);
  } else {
    check(PCSetType(pc, PCGAMG), "PCSetType");
  }
  const PetscInt its = static_cast<PetscInt>(options_.max_iterations > 0 ? options_.max_iterations : 10 * size);
  check(KSPSetTolerances(ksp, options_.tolerance, 0.0, PETSC_DEFAULT, its), "KSPSetTolerances");
  check(KSPSetNormType(ksp, KSP_NORM_UNPRECONDITIONED), "KSPSetNormType");
  if (options_.initial_guess) check(KSPSetInitialGuessNonzero(ksp, PETSC_TRUE), "KSPSetInitialGuessNonzero");
  if (const PetscErrorCode code = KSPSetFromOptions(ksp)) throw InputError("PETSc options: " + petsc_message(code));
  check(KSPSolve(ksp, r.b, r.w), "KSPSolve");
  KSPConvergedReason reason;
  check(KSPGetConvergedReason(ksp, &reason), "KSPGetConvergedReason");
  PetscInt iterations = 0;
  check(KSPGetIterationNumber(ksp, &iterations), "KSPGetIterationNumber");
  s.iterations = iterations;
  KSPType kt = nullptr;
  PCType pt = nullptr;
  check(KSPGetType(ksp, &kt), "KSPGetType");
  check(PCGetType(pc, &pt), "PCGetType");
  s.solver = std::string("petsc-") + kt + "-" + pt;
  PetscBool mg = PETSC_FALSE;
  check(PetscObjectTypeCompare(reinterpret_cast<PetscObject>(pc), PCMG, &mg), "PetscObjectTypeCompare");
  if (mg) describe_multigrid(pc, s);
  if (reason < 0) {
    PetscReal rn = 0;
    KSPGetResidualNorm(ksp, &rn);
    std::ostringstream msg;
    msg << std::setprecision(3) << "PETSc KSP " << kt << " + " << pt << " did not converge: "
        << KSPConvergedReasons[reason] << " after " << iterations << " iterations (residual norm " << rn << ")";
    throw NumericalError(msg.str());
  }
}

SolveResult PetscSystem::solve(const DirichletConditions& bc) {
  if (!a_) throw InputError("the distributed system is solved once");
  const auto t0 = std::chrono::steady_clock::now();
  close();
  SolveResult s;
  s.solver = "petsc-cg-gamg";
  s.ranks = ranks();
  s.elements_per_rank = gather_over_ranks(part_.owned_elements(rank_));
  s.dofs_per_rank = gather_over_ranks(hi_ - lo_);
  s.element_owner = part_.element_owner;
  if (part_.parts > 1) s.partition = {part_.method, part_.seconds, part_.interface_dofs / assembler_.components()};
  Reduced r;
  reduce(bc, r);
  // With coupled conditions the reduced system is a copy: the assembled one goes now, before the preconditioner is
  // built (a third less peak memory at 1e6 dofs); with a selection r.a holds it.
  a_.reset();
  b_.reset();
  const PetscInt size = static_cast<PetscInt>(r.free_dofs);
  s.free_dofs = r.free_dofs;
  check(VecDuplicate(r.b, r.w.out()), "VecDuplicate");
  check(VecSet(r.w, 0.0), "VecSet");
  if (options_.initial_guess) start_from(*options_.initial_guess, r);
  if (size > 0) {
    SolveOptions db(options_.petsc_options);
    run_ksp(r, size, s);
    db.check_all_used();
  }
  // w_c = 0 (the identity rows of a selection; kept by the solve, which cannot move them)
  for (PetscInt row : r.fixed_rows) check(VecSetValue(r.w, row, 0.0, INSERT_VALUES), "VecSetValue");
  check(VecAssemblyBegin(r.w), "VecAssemblyBegin");
  check(VecAssemblyEnd(r.w), "VecAssemblyEnd");
  // Residual of the reduced system, as for the other solvers.
  VecH res;
  check(VecDuplicate(r.b, res.out()), "VecDuplicate");
  check(MatMult(r.a, r.w, res), "MatMult");
  check(VecAXPY(res, -1.0, r.b), "VecAXPY");
  PetscReal rn = 0, bn = 0;
  check(VecNorm(res, NORM_2, &rn), "VecNorm");
  check(VecNorm(r.b, NORM_2, &bn), "VecNorm");
  s.residual_norm = rn / (bn > 0 ? bn : 1.0);
  // u = u0 + T w.
  VecH u;
  check(VecDuplicate(r.u0, u.out()), "VecDuplicate");
  if (r.t) {
    check(MatMultAdd(r.t, r.w, r.u0, u), "MatMultAdd");
  } else {
    check(VecWAXPY(u, 1.0, r.w, r.u0), "VecWAXPY");
  }
  s.x = gather(u);
  if (!s.x.allFinite()) throw NumericalError(s.solver + ": the solution is not finite");
  if (!(s.residual_norm <= options_.max_residual)) {
    std::ostringstream msg;
    msg << std::setprecision(3) << s.solver << ": relative residual " << s.residual_norm << " of the solution is above "
        << options_.max_residual << " (" << size << " unknowns)";
    throw NumericalError(msg.str());
  }
  s.seconds = max_over_ranks(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
  return s;
}

}  // namespace

std::unique_ptr<LinearSystem> make_petsc_system(const Assembler& assembler, const SolverOptions& options) {
  return std::make_unique<PetscSystem>(assembler, options);
}

}  // namespace iga::fem
