#pragma once
// The options of the pressure equation's linear solve ([solver] in a scene; docs/scenes.md),
// owned by the solver layer: the scene fills them, the systems hand them here, and the solver a
// scene asks for is built once from them (solvers/linear_solver.hpp).
#include <string>

#include "solvers/bucket_multigrid.hpp"

namespace ryushi {

struct SolverSpec {
  std::string krylov = "cg", preconditioner = "multigrid", cycle = "sw", precision = "mixed";
  std::string initial_guess = "previous";
  double tolerance = 1e-8;
  int max_iterations = 1000;
  int pre_smoothing = 1, post_smoothing = 1, bottom_smoothing = 2;
  long long bottom_size = 64;
  double jacobi_weight = 1.0;  // the method's default: 1 for mps, 2/3 for isph (its spec's hook)
};

// The bucket multigrid's options from the spec's cycle, precision and smoothing.
inline solvers::MultigridOptions multigrid_options(const SolverSpec& s) {
  solvers::MultigridOptions o;
  o.cycle = s.cycle == "v" ? solvers::MultigridOptions::Cycle::V : solvers::MultigridOptions::Cycle::W;
  o.scale_correction = s.cycle == "sw";
  o.single_precision = s.precision == "mixed";
  o.pre_smoothing = s.pre_smoothing;
  o.post_smoothing = s.post_smoothing;
  o.bottom_smoothing = s.bottom_smoothing;
  o.bottom_size = static_cast<std::size_t>(s.bottom_size);
  o.jacobi_weight = s.jacobi_weight;
  return o;
}

}  // namespace ryushi
