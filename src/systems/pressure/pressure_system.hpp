#pragma once
// The assembled pressure equation A p = b of an implicit method, as a resource shared by the
// assembly, the preconditioner setup, the linear solve and the matrix dump. Rows are the
// particles whose pressure is unknown, in particle order; `coordinates` (rows x dimension,
// row-major) lets the bucket multigrid build its hierarchy from where the particles are.
#include <algorithm>
#include <cstdint>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "ecs/resources.hpp"
#include "solvers/csr_matrix.hpp"
#include "solvers/krylov.hpp"

namespace ryushi {

struct PressureSystem {
  solvers::CsrMatrix<double> A;
  std::vector<double> b;
  std::vector<std::uint32_t> particle_of_row;
  std::vector<double> coordinates;
  int dimension = 2;
  double bucket_width = 0;  // the influence radius: no coupling is longer
  bool symmetric = true;    // cg applies; otherwise bicgstab
  // Particles without a row whose Dirichlet value is not 0 (ISPH's [[fixed_pressure]]), with it.
  std::vector<std::pair<std::uint32_t, double>> fixed_values;
  // No Dirichlet value: p up to a constant, one row pinned (pressure_gauge.hpp). Unless b was
  // made consistent exactly, the pinned row's own equation fixes a uniform source.
  bool gauge_free = false, gauge_exact = true;
  std::size_t pinned_row = 0;
  std::vector<std::pair<std::uint32_t, double>> pinned_equation;  // A's row before pinning
  double pinned_rhs = 0;
};

// Built by the preconditioner setup system; null means no preconditioner.
struct PressurePreconditioner {
  std::unique_ptr<solvers::Preconditioner> M;
  std::size_t bytes = 0;
  int levels = 0;
};

// What the linear solves of a run did, for summary.json.
struct LinearSolveStatistics {
  long long solves = 0, iterations = 0;
  int max_iterations = 0;
  double max_relative_residual = 0;
  std::size_t max_rows = 0, max_nonzeros = 0;
  // The largest memory of one step's solve, in bytes: the assembled system (CSR matrix, right-hand
  // side, coordinates, row map), the preconditioner (multigrid hierarchy or inverse diagonal) and
  // the Krylov method's vectors with the solution.
  std::size_t max_matrix_bytes = 0, max_preconditioner_bytes = 0, max_krylov_bytes = 0;
  std::string krylov;  // the method the solves used (a non-symmetric system takes BiCGSTAB)
  long long preconditioner_fallbacks = 0;  // solves that failed with the preconditioner, redone with Jacobi
};

// One solve's figures into the run's statistics (the largest of each over the run).
inline void record_solve(LinearSolveStatistics& stats, const solvers::SolveStatus& status, std::size_t rows,
                         std::size_t nonzeros, std::size_t matrix_bytes, std::size_t preconditioner_bytes,
                         std::size_t krylov_bytes) {
  ++stats.solves;
  stats.iterations += status.iterations;
  stats.max_iterations = std::max(stats.max_iterations, status.iterations);
  stats.max_relative_residual = std::max(stats.max_relative_residual, status.relative_residual);
  stats.max_rows = std::max(stats.max_rows, rows);
  stats.max_nonzeros = std::max(stats.max_nonzeros, nonzeros);
  stats.max_matrix_bytes = std::max(stats.max_matrix_bytes, matrix_bytes);
  stats.max_preconditioner_bytes = std::max(stats.max_preconditioner_bytes, preconditioner_bytes);
  stats.max_krylov_bytes = std::max(stats.max_krylov_bytes, krylov_bytes);
}

inline constexpr Resource<PressureSystem> pressure_system_resource{"pressure_system"};
inline constexpr Resource<PressurePreconditioner> preconditioner_resource{"preconditioner"};
inline constexpr Resource<LinearSolveStatistics> solve_statistics_resource{"solve_statistics"};

}  // namespace ryushi
