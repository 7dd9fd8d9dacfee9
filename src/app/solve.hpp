#pragma once
// `ryushi solve A.mtx --rhs b.txt --coords x.txt ...`: solves an exported system and prints one
// line `setup_s=.. solve_s=.. iters=.. relres=..`, so other solvers can be compared on the very
// same matrix. Exit 0 converged, 2 bad input, 3 not converged (the reason goes to stderr).
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
};

int solve_command(const SolveCommandOptions& options);

}  // namespace ryushi
