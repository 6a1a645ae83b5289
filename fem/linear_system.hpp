#pragma once
// The assembled linear system and its solve behind one interface, chosen by name (DESIGN.md item 7):
// "cholmod" and "cg" hold one process's Eigen matrix (CscSink); "petsc" a PETSc matrix distributed over the
// ranks of PETSC_COMM_WORLD (fem/parallel.hpp; one rank without mpirun), each rank assembling the elements a
// METIS partition gives it (fem/partition.hpp). The conditions are applied one way for both: u = u0 + T w
// (DirichletConditions: T the identity on the free dofs and −coupling on the constrained ones, u0 the prescribed
// values) and the reduced system Tᵀ A T w = Tᵀ (b − A u0), after assembly.
#include <Eigen/Sparse>
#include <exception>
#include <memory>
#include <optional>
#include <string>

#include "core/error.hpp"
#include "fem/assembler.hpp"
#include "fem/dirichlet.hpp"
#include "fem/solver.hpp"
#include "fem/system_sink.hpp"

namespace iga::fem {

class LinearSystem {
 public:
  virtual ~LinearSystem() = default;
  /// Where the element loop writes (Assembler::assemble(forms, sink)); it takes this process's elements.
  virtual SystemSink& sink() = 0;
  /// The element loop's figures over all processes, from this process's own (the same for one process).
  virtual AssemblyStats total(const AssemblyStats& own) const { return own; }
  /// The elements this process integrates (one entry per element, non-zero for its own; null: all of them), and
  /// the sum over all processes of what each integrated: a distributed run's error norms and means.
  virtual const std::vector<char>* own_elements() const { return nullptr; }
  virtual Eigen::VectorXd sum(const Eigen::VectorXd& own) const { return own; }
  /// Runs f, a step that each process does on its own elements and may fail on one of them only (an element
  /// loop, error norms): a failure anywhere is rethrown on every process, so none waits in a later collective
  /// call for one that has given up. Distributed, every process throws the lowest failing rank's message named
  /// "rank R of N: ..." (the process that failed keeps its exception's type, the others throw Error). Serial: f's
  /// exception as it is.
  template <class F>
  void run_everywhere(F&& f) const {
    std::exception_ptr error;
    std::optional<std::string> mine;
    try {
      f();
    } catch (const std::exception& e) {
      error = std::current_exception();
      mine = e.what();
    }
    const std::optional<std::string> first = first_failure(mine);
    if (error && first && *first != *mine) rethrow_with_message(error, *first);
    if (error) std::rethrow_exception(error);
    if (first) throw Error(*first);
  }
  /// The exception `error` (InputError, UnsupportedError, NumericalError or else Error) with `message`.
  [[noreturn]] static void rethrow_with_message(std::exception_ptr error, const std::string& message);
  /// The message of the lowest process whose `mine` is set, on every process (serial: mine; distributed: named
  /// "rank R of N: ...").
  virtual std::optional<std::string> first_failure(const std::optional<std::string>& mine) const { return mine; }
  /// Adds terms every process computed alike (boundary loads, Nitsche's terms: small): a (num_dofs², or 0 × 0 for
  /// none) and b (num_dofs, or empty for none). Each process adds the rows it owns.
  virtual void add(const Eigen::SparseMatrix<double>& a, const Eigen::VectorXd& b) = 0;
  /// Σ_i b_i of the load assembled so far, over all processes.
  virtual double load_sum() = 0;
  /// The assembled matrix and load before the conditions, in dof numbering, on every process (gathered from the
  /// ranks of a distributed system: for tests and small problems). Before solve(): a distributed system frees
  /// them there (InputError after).
  virtual Eigen::SparseMatrix<double> global_matrix() = 0;
  virtual Eigen::VectorXd global_load() = 0;
  /// Applies the conditions, solves the reduced system, and returns the whole solution on every process (x has
  /// num_dofs entries). NumericalError as fem::solve (a KSP that does not converge: its reason, in one line).
  virtual SolveResult solve(const DirichletConditions& bc) = 0;
};

/// The system for the assembler's space and options.kind. For kind Petsc: InputError without an open
/// ParallelSession, or when the space has fewer elements than ranks.
std::unique_ptr<LinearSystem> make_linear_system(const Assembler& assembler, const SolverOptions& options);

/// The PETSc system (fem/petsc_system.cpp); make_linear_system calls it for SolverKind::Petsc.
std::unique_ptr<LinearSystem> make_petsc_system(const Assembler& assembler, const SolverOptions& options);

}  // namespace iga::fem
