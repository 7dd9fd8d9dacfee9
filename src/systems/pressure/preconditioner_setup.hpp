#pragma once
// Builds the preconditioner of the pressure equation every step, as a system of its own so the
// profile shows setup and solve apart: "multigrid_setup" (the bucket multigrid hierarchy from the
// current particle positions, BMG paper sections 3-4) or "jacobi_setup" (the inverse diagonal).
// With preconditioner = none the pipeline has no setup system at all.
#include "ecs/io.hpp"
#include "solvers/bucket_multigrid.hpp"
#include "solvers/solver_options.hpp"
#include "systems/pressure/pressure_system.hpp"

namespace ryushi {

template <int D>
class PreconditionerSetup final : public System<D> {
 public:
  explicit PreconditionerSetup(const SolverSpec& s) : spec_(s) {}
  std::string name() const override { return spec_.preconditioner + "_setup"; }
  static constexpr auto io = Io{reads(pressure_system_resource), writes(preconditioner_resource)};
  Access access() const override { return io.access(); }
  void initialise(World<D>&, Resources& res) override { res.ensure(preconditioner_resource); }
  void run(SystemContext<D>& ctx) override {
    auto [sys, out] = io.fetch(ctx);
    out.bytes = 0;
    out.levels = 0;
    if (sys.A.rows == 0) {
      out.M.reset();
      return;
    }
    if (spec_.preconditioner == "jacobi") {
      out.M = std::make_unique<solvers::JacobiPreconditioner>(sys.A);
      out.bytes = sys.A.rows * sizeof(double);
      out.levels = 1;
      return;
    }
    // The last step's hierarchy is rebuilt in its own storage (BucketMultigrid::rebuild).
    auto* mg = dynamic_cast<solvers::BucketMultigrid*>(out.M.get());
    if (mg) {
      mg->rebuild(sys.A, sys.coordinates, sys.dimension, sys.bucket_width);
    } else {
      auto fresh = std::make_unique<solvers::BucketMultigrid>(sys.A, sys.coordinates, sys.dimension,
                                                              sys.bucket_width, multigrid_options(spec_));
      mg = fresh.get();
      out.M = std::move(fresh);
    }
    out.bytes = mg->bytes();
    out.levels = static_cast<int>(mg->levels().size());
  }

 private:
  SolverSpec spec_;
};

}  // namespace ryushi
