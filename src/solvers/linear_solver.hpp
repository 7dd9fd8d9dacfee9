#pragma once
// One interface for the Krylov solve of an assembled system, chosen once from the options: CG
// (symmetric matrices) or BiCGSTAB, in process. A solver across ranks (PETSc, the distributed
// solve) is a second implementation of this interface, not a second Krylov layer.
#include <memory>
#include <span>
#include <string>

#include "solvers/krylov.hpp"
#include "solvers/solver_options.hpp"

namespace ryushi::solvers {

class LinearSolver {
 public:
  virtual ~LinearSolver() = default;
  virtual std::string name() const = 0;  // "cg", "bicgstab": summary.json's krylov
  virtual int work_vectors() const = 0;  // n-vectors held at its peak, for the memory accounting
  virtual SolveStatus solve(const CsrMatrix<double>& A, std::span<const double> b, std::span<double> x,
                            const Preconditioner& M) const = 0;
};

// The spec's Krylov method for a matrix that is (or is not) symmetric: BiCGSTAB when asked for
// or when the matrix is not symmetric (ISPH's), CG otherwise.
std::unique_ptr<LinearSolver> make_linear_solver(const SolverSpec& spec, bool symmetric);

}  // namespace ryushi::solvers
