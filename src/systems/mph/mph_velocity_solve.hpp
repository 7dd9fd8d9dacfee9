#pragma once
// Solves MPH-I's velocity equation (mph_velocity_system.hpp) and moves the particles:
//   mph_preconditioner  the bucket multigrid for block rows (MPH-I paper section 3: each velocity
//                       component summed over a bucket, eqs. 5-6, prolongation the transpose,
//                       Jacobi smoothing), the inverse diagonal, or none, per [solver]
//   mph_velocity_solve  CG from the last velocities; writes u^{k+1} and the pressure
//                       psi_i = lambda_i D_i(u^{k+1}) + kappa max(n_i - n0, 0) (eq. 2, the
//                       implicit part of the elastic pressure in lambda_i) of every particle
//                       (the virial of the pair forces read 2-3% below the weight of the
//                       liquid above in a column at rest, psi within 1%: docs/mph.md)
//   mph_move            x^{k+1} = x^k + dt u^{k+1} (symplectic Euler)
// A solve that does not converge stops the step with the solver's reason.
#include <cstdio>
#include <memory>
#include <stdexcept>

#include "ecs/io.hpp"
#include "solvers/bucket_multigrid.hpp"
#include "solvers/linear_solver.hpp"
#include "systems/mph/mph_velocity_system.hpp"
#include "systems/pressure/preconditioner_setup.hpp"
#include "systems/pressure/pressure_system.hpp"

namespace ryushi {

inline constexpr Resource<PressurePreconditioner> mph_preconditioner_resource{"mph_preconditioner"};

template <int D>
class MphPreconditionerSetup final : public System<D> {
 public:
  explicit MphPreconditionerSetup(const SolverSpec& s) : spec_(s) {}
  std::string name() const override { return "mph_" + spec_.preconditioner + "_setup"; }
  static constexpr auto io = Io{reads(mph_system_resource), writes(mph_preconditioner_resource)};
  Access access() const override { return io.access(); }
  void initialise(World<D>&, Resources& res) override { res.ensure(mph_preconditioner_resource); }
  void run(SystemContext<D>& ctx) override {
    auto [sys, out] = io.fetch(ctx);
    // The bulk term makes the rows far from diagonally dominant (max eig(D^-1 A) above 5 in the
    // resting column): each level's Jacobi weight is bounded by its own spectrum.
    build_preconditioner(spec_, sys.A, sys.coordinates, D, sys.bucket_width, out, D, true);
  }

 private:
  SolverSpec spec_;
};

template <int D>
class MphVelocitySolve final : public System<D> {
 public:
  explicit MphVelocitySolve(const SolverSpec& s) : solver_(solvers::make_linear_solver(s, true)) {}
  std::string name() const override { return "mph_velocity_solve"; }
  static constexpr auto io =
      Io{reads(mph_system_resource, mph_preconditioner_resource, mph_terms_resource<D>),
         writes(components::velocity, components::pressure, solve_statistics_resource)};
  Access access() const override { return io.access(); }
  void initialise(World<D>&, Resources& res) override { res.ensure(solve_statistics_resource); }
  void run(SystemContext<D>& ctx) override {
    auto [sys, pre, terms, v, p, stats] = io.fetch(ctx);
    const std::size_t rows = sys.A.rows;
    u_.resize(rows);
    for (std::size_t r = 0; r < sys.particle_of_block.size(); ++r)
      for (int a = 0; a < D; ++a) u_[r * D + a] = v[sys.particle_of_block[r]][a];
    solvers::SolveStatus status;
    status.converged = true;
    status.relative_residual = 0;
    if (rows > 0) {
      const solvers::Preconditioner* M = pre.M ? pre.M.get() : &identity_;
      status = solver_->solve(sys.A, sys.b, u_, *M);
      stats.krylov = solver_->name();
      if (!status.converged) {
        char m[256];
        std::snprintf(
            m, sizeof m,
            "mph_velocity_solve: %s on %zu unknowns stopped after %d iterations at relative residual "
            "%.3e: %s",
            stats.krylov.c_str(), rows, status.iterations, status.relative_residual, status.reason.c_str());
        throw std::runtime_error(m);
      }
    }
    for (std::size_t r = 0; r < sys.particle_of_block.size(); ++r)
      for (int a = 0; a < D; ++a) v[sys.particle_of_block[r]][a] = u_[r * D + a];
    // The pressure of eq. 2 with the new velocities, walls included.
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, p.size(), 1024), [&](auto range) {
      for (std::size_t i = range.begin(); i != range.end(); ++i) {
        double rate = 0;
        for (auto q = terms.pair_offsets[i]; q != terms.pair_offsets[i + 1]; ++q)
          rate += terms.pair_rate[q].dot(v[terms.pair_index[q]] - v[i]);
        p[i] = terms.bulk_coefficient[i] * rate + terms.elastic_pressure[i];
      }
    });
    record_solve(stats, status, rows, sys.A.nonzeros(),
                 sys.A.bytes() + (sys.b.size() + sys.coordinates.size()) * sizeof(double), pre.bytes,
                 std::size_t(solver_->work_vectors() + 1) * rows * sizeof(double));
  }

 private:
  std::unique_ptr<solvers::LinearSolver> solver_;
  solvers::IdentityPreconditioner identity_;
  std::vector<double> u_;
};

template <int D>
class MphMove final : public System<D> {
 public:
  std::string name() const override { return "mph_move"; }
  static constexpr auto io =
      Io{reads(components::velocity, components::kind, resources::dt, domain_resource<D>),
         writes(components::position)};
  Access access() const override { return io.access(); }
  void run(SystemContext<D>& ctx) override {
    auto [v, kind, dt, domain, x] = io.fetch(ctx);
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, x.size(), 4096), [&](auto range) {
      for (std::size_t i = range.begin(); i != range.end(); ++i)
        if (kind[i] == kFluid) {
          x[i] += dt * v[i];
          domain.wrap(x[i]);
        }
    });
  }
};

}  // namespace ryushi
