// Poisson benchmark of the multigrid paper at several sizes: setup time, solve time, iterations
// and bytes per unknown for DCG and MGCG with V, W and S-W cycles, double and mixed precision.
// Usage: ryushi_bench_solvers [THREADS] [--quick]. docs/solvers.md holds the table.
#include <tbb/global_control.h>

#include <chrono>
#include <cstdio>
#include <cstring>
#include <string>

#include "solvers/bucket_multigrid.hpp"
#include "verification/poisson_benchmark.hpp"

using namespace ryushi;
using namespace ryushi::solvers;
using Clock = std::chrono::steady_clock;

static double seconds_since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

int main(int argc, char** argv) {
  int threads = argc > 1 ? std::stoi(argv[1]) : 2;
  bool quick = argc > 2 && std::strcmp(argv[2], "--quick") == 0;
  tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads);
  struct Case {
    int dim, n;
  };
  std::vector<Case> cases = quick ? std::vector<Case>{{2, 256}, {3, 32}}
                                  : std::vector<Case>{{2, 256}, {2, 512}, {2, 1024}, {3, 64}, {3, 128}};
  std::printf("| case | unknowns | nnz/row | solver | setup_s | solve_s | iters | relres | bytes/unknown |\n");
  std::printf("|---|---|---|---|---|---|---|---|---|\n");
  for (auto c : cases) {
    auto t0 = Clock::now();
    auto P = mps_poisson_problem(c.dim, c.n);
    double assemble = seconds_since(t0);
    const double n = double(P.b.size());
    std::fprintf(stderr, "%dD n=%d: %zu unknowns assembled in %.2f s\n", c.dim, c.n, P.b.size(), assemble);
    const double matrix_bytes = double(P.A.bytes()) / n;
    auto run = [&](const std::string& label, auto make) {
      auto s0 = Clock::now();
      auto M = make();
      double setup = seconds_since(s0);
      std::vector<double> x(P.b.size(), 0.0);
      auto s1 = Clock::now();
      auto st = conjugate_gradient(P.A, P.b, x, *M, {1e-8, 20000});
      double solve = seconds_since(s1);
      double extra = 0;
      if (auto* mg = dynamic_cast<BucketMultigrid*>(M.get())) extra = double(mg->bytes()) / n;
      // Matrix + CG's 4 vectors + x, b (+ hierarchy).
      double bytes = matrix_bytes + 6 * sizeof(double) + extra;
      std::printf("| %dD %d^%d | %zu | %.1f | %s | %.3f | %.3f | %d%s | %.1e | %.0f |\n", c.dim, c.n, c.dim, P.b.size(),
                  double(P.A.nonzeros()) / n, label.c_str(), setup, solve, st.iterations, st.converged ? "" : " (not converged)",
                  st.relative_residual, bytes);
      std::fflush(stdout);
    };
    run("DCG", [&] { return std::make_unique<JacobiPreconditioner>(P.A); });
    for (auto [name, cycle, scale] : {std::tuple{"V", MultigridOptions::Cycle::V, false},
                                      std::tuple{"W", MultigridOptions::Cycle::W, false},
                                      std::tuple{"S-W", MultigridOptions::Cycle::W, true}})
      for (bool single : {false, true}) {
        MultigridOptions o;
        o.cycle = cycle;
        o.scale_correction = scale;
        o.single_precision = single;
        run(std::string("MGCG ") + name + (single ? " mixed" : " double"),
            [&] { return std::make_unique<BucketMultigrid>(P.A, P.coordinates, c.dim, P.influence_radius, o); });
      }
  }
  return 0;
}
