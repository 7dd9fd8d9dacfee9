#include "solvers/linear_solver.hpp"

namespace ryushi::solvers {

namespace {

// CG or BiCGSTAB (krylov.hpp) with the spec's tolerance and iteration cap.
class KrylovSolver final : public LinearSolver {
 public:
  using Method = SolveStatus (*)(const CsrMatrix<double>&, std::span<const double>, std::span<double>,
                                 const Preconditioner&, const SolveOptions&);
  KrylovSolver(std::string name, int work_vectors, Method method, SolveOptions options)
      : name_(std::move(name)), work_vectors_(work_vectors), method_(method), options_(options) {}
  std::string name() const override { return name_; }
  int work_vectors() const override { return work_vectors_; }
  SolveStatus solve(const CsrMatrix<double>& A, std::span<const double> b, std::span<double> x,
                    const Preconditioner& M) const override {
    return method_(A, b, x, M, options_);
  }

 private:
  std::string name_;
  int work_vectors_;
  Method method_;
  SolveOptions options_;
};

}  // namespace

std::unique_ptr<LinearSolver> make_linear_solver(const SolverSpec& spec, bool symmetric) {
  const SolveOptions o{spec.tolerance, spec.max_iterations};
  if (spec.krylov == "bicgstab" || !symmetric)
    return std::make_unique<KrylovSolver>("bicgstab", kBicgstabWorkVectors, &bicgstab, o);
  return std::make_unique<KrylovSolver>("cg", kConjugateGradientWorkVectors, &conjugate_gradient, o);
}

}  // namespace ryushi::solvers
