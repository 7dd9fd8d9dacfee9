#include "solvers/linear_solver.hpp"

namespace ryushi::solvers {

namespace {

class ConjugateGradientSolver final : public LinearSolver {
 public:
  explicit ConjugateGradientSolver(SolveOptions o) : options_(o) {}
  std::string name() const override { return "cg"; }
  int work_vectors() const override { return kConjugateGradientWorkVectors; }
  SolveStatus solve(const CsrMatrix<double>& A, std::span<const double> b, std::span<double> x,
                    const Preconditioner& M) const override {
    return conjugate_gradient(A, b, x, M, options_);
  }

 private:
  SolveOptions options_;
};

class BicgstabSolver final : public LinearSolver {
 public:
  explicit BicgstabSolver(SolveOptions o) : options_(o) {}
  std::string name() const override { return "bicgstab"; }
  int work_vectors() const override { return kBicgstabWorkVectors; }
  SolveStatus solve(const CsrMatrix<double>& A, std::span<const double> b, std::span<double> x,
                    const Preconditioner& M) const override {
    return bicgstab(A, b, x, M, options_);
  }

 private:
  SolveOptions options_;
};

}  // namespace

std::unique_ptr<LinearSolver> make_linear_solver(const SolverSpec& spec, bool symmetric) {
  const SolveOptions o{spec.tolerance, spec.max_iterations};
  if (spec.krylov == "bicgstab" || !symmetric) return std::make_unique<BicgstabSolver>(o);
  return std::make_unique<ConjugateGradientSolver>(o);
}

}  // namespace ryushi::solvers
