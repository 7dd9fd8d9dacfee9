#include "app/solve.hpp"

#include <tbb/global_control.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <memory>
#include <optional>

#include "app/exit_codes.hpp"
#include "solvers/bucket_multigrid.hpp"
#include "solvers/matrix_market.hpp"

namespace ryushi {

int solve_command(const SolveCommandOptions& o) {
  using namespace solvers;
  using Clock = std::chrono::steady_clock;
  try {
    auto A = read_matrix_market(o.matrix);
    auto b = read_values(o.rhs);
    if (A.rows != A.cols) throw std::invalid_argument(o.matrix + ": matrix is not square");
    if (b.size() != A.rows)
      throw std::invalid_argument(o.rhs + ": " + std::to_string(b.size()) + " values for a matrix of " + std::to_string(A.rows) + " rows");
    std::optional<tbb::global_control> limit;
    if (o.threads > 0) limit.emplace(tbb::global_control::max_allowed_parallelism, o.threads);
    auto t0 = Clock::now();
    std::unique_ptr<Preconditioner> M;
    std::string levels;  // the multigrid's rows x nonzeros per row, finest first
    if (o.preconditioner == "none") {
      M = std::make_unique<IdentityPreconditioner>();
    } else if (o.preconditioner == "jacobi") {
      M = std::make_unique<JacobiPreconditioner>(A);
    } else {
      if (o.coords.empty()) throw std::invalid_argument("--preconditioner multigrid needs --coords");
      auto raw = read_values(o.coords, 0);
      const std::size_t blocks = A.rows / std::size_t(o.block_size);
      if (A.rows % std::size_t(o.block_size) != 0)
        throw std::invalid_argument(o.matrix + ": " + std::to_string(A.rows) + " rows are not blocks of " +
                                    std::to_string(o.block_size));
      if (blocks == 0 || raw.size() % blocks != 0 || (raw.size() / blocks != 2 && raw.size() / blocks != 3))
        throw std::invalid_argument(o.coords + ": expected 2 or 3 coordinates per block of " +
                                    std::to_string(o.block_size) + " rows of the matrix");
      const int D = static_cast<int>(raw.size() / blocks);
      const std::size_t block = std::size_t(o.block_size);
      double width = o.bucket_width;
      if (width <= 0) {  // the longest coupling: buckets at least this wide keep A_c to 3^D per row
        for (std::size_t r = 0; r < A.rows; ++r)
          for (auto k = A.row_ptr[r]; k < A.row_ptr[r + 1]; ++k) {
            double d2 = 0;
            for (int a = 0; a < D; ++a)
              d2 += std::pow(raw[r / block * D + a] - raw[A.col[k] / block * D + a], 2);
            width = std::max(width, std::sqrt(d2));
          }
        width *= 1 + 1e-9;
      }
      MultigridOptions mo;
      mo.cycle = o.cycle == "v" ? MultigridOptions::Cycle::V : MultigridOptions::Cycle::W;
      mo.scale_correction = o.cycle == "sw";
      mo.single_precision = o.precision == "mixed";
      mo.pre_smoothing = o.pre_smoothing;
      mo.post_smoothing = o.post_smoothing;
      mo.bottom_smoothing = o.bottom_smoothing;
      mo.bottom_size = o.bottom_size;
      mo.jacobi_weight = o.jacobi_weight > 0 ? o.jacobi_weight : o.krylov == "bicgstab" ? 2.0 / 3.0 : 1.0;
      mo.bound_jacobi_weight = o.bound_jacobi_weight;
      auto mg = std::make_unique<BucketMultigrid>(A, raw, D, width, mo, o.block_size);
      for (auto& l : mg->levels()) {
        char b[64];
        std::snprintf(b, sizeof b, "%s%zux%.1f", levels.empty() ? "" : ",", l.rows,
                      double(l.nonzeros) / double(std::max<std::size_t>(l.rows, 1)));
        levels += b;
      }
      M = std::move(mg);
    }
    double setup = std::chrono::duration<double>(Clock::now() - t0).count();
    std::vector<double> x(A.rows, 0.0);
    auto t1 = Clock::now();
    SolveOptions so{o.tolerance, o.max_iterations};
    auto s = o.krylov == "bicgstab" ? bicgstab(A, b, x, *M, so) : conjugate_gradient(A, b, x, *M, so);
    double solve = std::chrono::duration<double>(Clock::now() - t1).count();
    std::printf("setup_s=%.6f solve_s=%.6f iters=%d relres=%.3e%s%s\n", setup, solve, s.iterations,
                s.relative_residual, levels.empty() ? "" : " levels=", levels.c_str());
    if (!s.converged) {
      std::fprintf(stderr, "ryushi: solve did not converge: %s\n", s.reason.c_str());
      return kExitNumericalFailure;
    }
    return kExitDone;
  } catch (const std::invalid_argument& e) {
    std::fprintf(stderr, "ryushi: solve: %s\n", e.what());
    return kExitBadInput;
  }
}

}  // namespace ryushi
