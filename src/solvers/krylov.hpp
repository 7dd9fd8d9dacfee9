#pragma once
// Krylov methods with explicit outcomes: CG, diagonally scaled CG (CG with the Jacobi
// preconditioner) and BiCGSTAB for non-symmetric systems (the corrected-ISPH matrix). Every
// solve returns a SolveStatus and stops at max_iterations: it never hangs and never returns
// garbage silently. Non-finite input, a zero diagonal under Jacobi, and breakdowns (p.Ap <= 0 in
// CG, rho or omega vanishing in BiCGSTAB) end the solve with converged = false and a reason.
// relative_residual is recomputed from the returned x: |b - A x| / |b|.
#include <limits>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "solvers/csr_matrix.hpp"

namespace ryushi::solvers {

struct SolveOptions {
  double tolerance = 1e-8;  // on |b - A x| / |b|
  int max_iterations = 1000;
};

struct SolveStatus {
  bool converged = false;
  int iterations = 0;
  double relative_residual = std::numeric_limits<double>::quiet_NaN();
  std::string reason;  // empty when converged
};

class Preconditioner {
 public:
  virtual ~Preconditioner() = default;
  // z = M^-1 r
  virtual void apply(std::span<const double> r, std::span<double> z) const = 0;
  virtual std::string name() const = 0;
};

class IdentityPreconditioner final : public Preconditioner {
 public:
  void apply(std::span<const double> r, std::span<double> z) const override;
  std::string name() const override { return "none"; }
};

// z_i = r_i / A_ii. Construction throws std::invalid_argument at a zero or non-finite diagonal.
class JacobiPreconditioner final : public Preconditioner {
 public:
  explicit JacobiPreconditioner(const CsrMatrix<double>& A);
  void apply(std::span<const double> r, std::span<double> z) const override;
  std::string name() const override { return "jacobi"; }

 private:
  std::vector<double> inverse_diagonal_;
};

// The n-vectors each method holds at its peak (the residual check's A x included), for the
// memory accounting of summary.json: CG r, z, p, q; BiCGSTAB r, r0, p, v, s, t, y, z.
inline constexpr int kConjugateGradientWorkVectors = 5;
inline constexpr int kBicgstabWorkVectors = 9;

SolveStatus conjugate_gradient(const CsrMatrix<double>& A, std::span<const double> b, std::span<double> x,
                               const Preconditioner& M, const SolveOptions& options = {});
SolveStatus bicgstab(const CsrMatrix<double>& A, std::span<const double> b, std::span<double> x,
                     const Preconditioner& M, const SolveOptions& options = {});

}  // namespace ryushi::solvers
