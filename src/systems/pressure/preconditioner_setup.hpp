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

// The spec's preconditioner for A into `out` (none: null), the last hierarchy rebuilt in its own
// storage (BucketMultigrid::rebuild). coordinates: one line of `dimension` values per block of
// block_size rows; bound_weight: MultigridOptions::bound_jacobi_weight.
inline void build_preconditioner(const SolverSpec& spec, const solvers::CsrMatrix<double>& A,
                                 std::span<const double> coordinates, int dimension, double bucket_width,
                                 PressurePreconditioner& out, int block_size = 1, bool bound_weight = false) {
  out.bytes = 0;
  out.levels = 0;
  if (A.rows == 0 || spec.preconditioner == "none") {
    out.M.reset();
    return;
  }
  if (spec.preconditioner == "jacobi") {
    out.M = std::make_unique<solvers::JacobiPreconditioner>(A);
    out.bytes = A.rows * sizeof(double);
    out.levels = 1;
    return;
  }
  auto* mg = dynamic_cast<solvers::BucketMultigrid*>(out.M.get());
  if (mg) {
    mg->rebuild(A, coordinates, dimension, bucket_width, block_size);
  } else {
    auto options = multigrid_options(spec);
    options.bound_jacobi_weight = bound_weight;
    auto fresh = std::make_unique<solvers::BucketMultigrid>(A, coordinates, dimension, bucket_width, options,
                                                            block_size);
    mg = fresh.get();
    out.M = std::move(fresh);
  }
  out.bytes = mg->bytes();
  out.levels = static_cast<int>(mg->levels().size());
}

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
    build_preconditioner(spec_, sys.A, sys.coordinates, sys.dimension, sys.bucket_width, out);
  }

 private:
  SolverSpec spec_;
};

}  // namespace ryushi
