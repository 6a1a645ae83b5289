#include "fem/linear_system.hpp"

namespace iga::fem {

void LinearSystem::rethrow_with_message(std::exception_ptr error, const std::string& message) {
  try {
    std::rethrow_exception(error);
  } catch (const InputError&) {
    throw InputError(message);
  } catch (const UnsupportedError&) {
    throw UnsupportedError(message);
  } catch (const NumericalError&) {
    throw NumericalError(message);
  } catch (...) {
    throw Error(message);
  }
}

namespace {

// One process's system: the plan's CSC pattern, the conditions by eliminate(), the solve by fem::solve.
class EigenSystem final : public LinearSystem {
 public:
  EigenSystem(const Assembler& assembler, const SolverOptions& options)
      : options_(options), sink_(assembler.plan(), a_, b_) {}
  SystemSink& sink() override { return sink_; }
  void add(const Eigen::SparseMatrix<double>& a, const Eigen::VectorXd& b) override {
    if (a.nonZeros() > 0) {
      a_ += a;
      a_.makeCompressed();
    }
    if (b.size() > 0) b_ += b;
  }
  double load_sum() override { return b_.sum(); }
  Eigen::SparseMatrix<double> global_matrix() override { return a_; }
  Eigen::VectorXd global_load() override { return b_; }
  SolveResult solve(const DirichletConditions& bc) override {
    const ReducedSystem reduced = eliminate(a_, b_, bc);
    SolveResult s = fem::solve(reduced.a, reduced.b, options_);
    s.x = expand(reduced, s.x, bc, a_.rows());
    s.free_dofs = static_cast<Index>(reduced.free.size());
    return s;
  }

 private:
  SolverOptions options_;
  Eigen::SparseMatrix<double> a_;
  Eigen::VectorXd b_;
  CscSink sink_;
};

}  // namespace

std::unique_ptr<LinearSystem> make_linear_system(const Assembler& assembler, const SolverOptions& options) {
  if (uses_petsc(options.kind)) return make_petsc_system(assembler, options);
  return std::make_unique<EigenSystem>(assembler, options);
}

}  // namespace iga::fem
