#pragma once
// Solves the assembled pressure equation with the scene's Krylov method and preconditioner and
// scatters the solution into the `pressure` column (rows are particles; particles without a row
// keep their Dirichlet value: 0, or the system's fixed_values). The initial guess is the previous
// step's pressure or zero. A solve that does not converge is a numerical failure: the step stops
// with the solver's reason.
#include <algorithm>
#include <cstdio>
#include <stdexcept>

#include "ecs/io.hpp"
#include "solvers/linear_solver.hpp"
#include "systems/pressure/pressure_system.hpp"

namespace ryushi {

template <int D>
class LinearSolve final : public System<D> {
 public:
  // The solvers are built once, here: CG or BiCGSTAB for a symmetric system, BiCGSTAB for one
  // that is not (the system says which each step).
  explicit LinearSolve(const SolverSpec& s)
      : symmetric_(solvers::make_linear_solver(s, true)),
        general_(solvers::make_linear_solver(s, false)),
        preconditioned_(s.preconditioner != "none"),
        multigrid_(s.preconditioner == "multigrid"),
        previous_guess_(s.initial_guess == "previous") {}
  std::string name() const override { return "linear_solve"; }
  auto io() const {
    return Io{reads(pressure_system_resource), writes(components::pressure, solve_statistics_resource),
              optional(preconditioned_, reads(preconditioner_resource))};
  }
  Access access() const override { return io().access(); }
  void initialise(World<D>&, Resources& res) override { res.ensure(solve_statistics_resource); }
  void run(SystemContext<D>& ctx) override {
    auto [sys, p, stats, pre] = io().fetch(ctx);  // pre: null without a preconditioner
    const std::size_t rows = sys.A.rows;
    x_.assign(rows, 0.0);
    if (previous_guess_)
      for (std::size_t r = 0; r < rows; ++r) x_[r] = p[sys.particle_of_row[r]];
    solvers::SolveStatus status;
    status.converged = true;
    std::size_t preconditioner_bytes = 0;
    status.relative_residual = 0;
    if (rows > 0) {
      const solvers::Preconditioner* M = &identity_;
      if (pre) {
        if (pre->M) M = pre->M.get();
        preconditioner_bytes = pre->bytes;
      }
      const solvers::LinearSolver& solver = sys.symmetric ? *symmetric_ : *general_;
      stats.krylov = solver.name();
      work_vectors_ = solver.work_vectors();
      auto solve = [&](std::span<const double> b, std::span<double> x) { return solver.solve(sys.A, b, x, *M); };
      status = solve(sys.b, x_);
      if (!status.converged && multigrid_) {
        // The bucket multigrid assumes rows like a Laplacian's; a corrected-Laplacian row of a
        // particle 0.8 d from a wall at the contact line (diagonal 9x the others', positive
        // off-diagonals of the same size) made it a diverging preconditioner, and BiCGSTAB
        // stopped at 1000 iterations on a system with condition number 1e4 that Jacobi solves in
        // 81 (the ISPH sloshing tank at t = 2.76 s). Such a step is solved again with Jacobi.
        const int wasted = status.iterations;
        x_.assign(rows, 0.0);
        if (previous_guess_)
          for (std::size_t r = 0; r < rows; ++r) x_[r] = p[sys.particle_of_row[r]];
        solvers::JacobiPreconditioner jacobi(sys.A);
        status = solver.solve(sys.A, sys.b, x_, jacobi);
        status.iterations += wasted;
        ++stats.preconditioner_fallbacks;
      }
      if (status.converged && sys.gauge_free && !sys.gauge_exact) {
        // pressure_gauge.hpp: the uniform source beta that makes the pinned row's equation hold.
        uniform_.assign(rows, 1.0);
        uniform_[sys.pinned_row] = 0.0;
        z_.assign(rows, 0.0);
        auto second = solve(uniform_, z_);
        status.iterations += second.iterations;
        if (!second.converged) status = second;
        double ax = 0, az = 0;
        for (auto& [col, val] : sys.pinned_equation) ax += val * x_[col], az += val * z_[col];
        const double beta = (sys.pinned_rhs - ax) / (1.0 - az);
        for (std::size_t r = 0; r < rows; ++r) x_[r] -= beta * z_[r];
      }
      if (!status.converged) {
        char m[256];
        std::snprintf(
            m, sizeof m, "%s on %zu unknowns stopped after %d iterations at relative residual %.3e: %s",
            stats.krylov.c_str(), rows, status.iterations, status.relative_residual, status.reason.c_str());
        throw std::runtime_error(m);
      }
    }
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, p.size(), 4096), [&](auto range) {
      for (std::size_t i = range.begin(); i != range.end(); ++i) p[i] = 0.0;
    });
    if (sys.gauge_free && rows > 0) {
      // The level of a pressure without a Dirichlet value is a convention: the lowest is 0. The
      // difference gradients (MPS, corrected ISPH) do not see it; the symmetric one, (p_i + p_j),
      // pulls particles together where the pressure is negative (a zero mean blew the periodic
      // shear layer up within 22 steps).
      double lowest = *std::min_element(x_.begin(), x_.end());
      for (double& xr : x_) xr -= lowest;
    }
    for (std::size_t r = 0; r < rows; ++r) p[sys.particle_of_row[r]] = x_[r];
    for (auto& [i, value] : sys.fixed_values) p[i] = value;
    const std::size_t matrix_bytes = sys.A.bytes() +
                                     (sys.b.size() + sys.coordinates.size()) * sizeof(double) +
                                     sys.particle_of_row.size() * sizeof(std::uint32_t);
    const std::size_t krylov_bytes =
        (work_vectors_ * rows + x_.capacity() + uniform_.capacity() + z_.capacity()) * sizeof(double);
    record_solve(stats, status, rows, sys.A.nonzeros(), matrix_bytes, preconditioner_bytes, krylov_bytes);
  }

 private:
  std::unique_ptr<solvers::LinearSolver> symmetric_, general_;
  bool preconditioned_, multigrid_, previous_guess_;
  int work_vectors_ = solvers::kConjugateGradientWorkVectors;
  solvers::IdentityPreconditioner identity_;
  std::vector<double> x_, uniform_, z_;
};

}  // namespace ryushi
