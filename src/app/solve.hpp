#pragma once
// `ryushi solve A.mtx --rhs b.txt --coords x.txt ...`: solves an exported system and prints one
// line `setup_s=.. solve_s=.. iters=.. relres=..` (and the multigrid's levels), so other solvers
// and other multigrid settings can be compared on the very same matrix. Exit 0 converged, 2 bad
// input, 3 not converged (the reason goes to stderr).
#include <cstddef>
#include <string>

namespace ryushi {

struct SolveCommandOptions {
  std::string matrix, rhs, coords;
  std::string krylov = "cg";              // cg | bicgstab
  std::string preconditioner = "multigrid";  // none | jacobi | multigrid
  std::string cycle = "sw";               // v | w | sw
  std::string precision = "mixed";        // double | mixed
  double tolerance = 1e-8;
  int max_iterations = 10000;
  double bucket_width = 0;  // 0: the longest coupling |x_i - x_j| over the matrix entries
  // The multigrid's smoothing and bottom, as the scene's [solver] keys set them.
  int pre_smoothing = 1, post_smoothing = 1, bottom_smoothing = 2;
  std::size_t bottom_size = 64;
  double jacobi_weight = 0;  // 0: the scenes' default for the Krylov method (1 with cg, 2/3 with bicgstab)
  int threads = 0;           // 0: all cores
  // Unknowns per particle (MPH-I's velocity: the dimension): --coords then holds one line per
  // block of rows, and the multigrid sums each component over a bucket on its own.
  int block_size = 1;
  bool bound_jacobi_weight = false;  // each level's weight at most 4 / (3 max eig(D^-1 A))
};

int solve_command(const SolveCommandOptions& options);

}  // namespace ryushi
