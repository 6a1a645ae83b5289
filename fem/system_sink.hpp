#pragma once
// Where the assembler's element loop writes (DESIGN.md item 7): the Eigen CSC pattern of a serial run
// (CscSink), or a distributed PETSc matrix (fem/petsc_system.cpp). The loop computes the element matrices and
// vectors; the sink alone decides where they go.
#include <Eigen/Sparse>
#include <span>
#include <utility>
#include <vector>

#include "core/types.hpp"
#include "fem/assembly_plan.hpp"

namespace iga::fem {

class SystemSink {
 public:
  virtual ~SystemSink() = default;
  /// Whether this process assembles element e (default: every element; a rank of a distributed run: its own).
  virtual bool takes(Index /*e*/) const { return true; }
  /// Element matrix k (dofs × dofs) and vector f at the global `dofs`. Called concurrently for the elements of one
  /// colour (AssemblyPlan::colors: no two share a dof); `slot` is the element's position in its colour.
  virtual void add(Index slot, std::span<const Index> dofs, const Eigen::MatrixXd& k, const Eigen::VectorXd& f) = 0;
  /// After the elements of a colour (serial): `count` slots were used.
  virtual void end_colour(Index /*count*/) {}
};

/// The serial sink: a (the plan's pattern, values summed) and b (num_dofs). Each entry is summed in colour order,
/// so the result does not depend on the thread count. Entries between two dense dofs (AssemblyPlan::dense) are
/// kept per slot and added after the colour in slot order.
class CscSink final : public SystemSink {
 public:
  /// a ← plan's pattern (zero values), b ← zeros; both are written by the loop.
  CscSink(const AssemblyPlan& plan, Eigen::SparseMatrix<double>& a, Eigen::VectorXd& b);
  void add(Index slot, std::span<const Index> dofs, const Eigen::MatrixXd& k, const Eigen::VectorXd& f) override;
  void end_colour(Index count) override;

 private:
  const AssemblyPlan& plan_;
  Eigen::SparseMatrix<double>& a_;
  Eigen::VectorXd& b_;
  // Per slot: value positions (the load of dof j as −1 − j) and values between dense dofs, added after the colour.
  std::vector<std::vector<std::pair<std::ptrdiff_t, double>>> pending_;
};

}  // namespace iga::fem
