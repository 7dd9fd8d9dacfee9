#pragma once
// The spectrum bound behind the bucket multigrid's bounded Jacobi weight
// (MultigridOptions::bound_jacobi_weight): a weighted Jacobi sweep z += w D^-1 (r - A z) damps every
// error mode of a symmetric positive definite A while w < 2 / rho, rho the largest eigenvalue of
// D^-1 A, and smooths best near w = 4 / (3 rho).
#include <cmath>
#include <span>
#include <vector>

#include "solvers/csr_matrix.hpp"
#include "solvers/vector_ops.hpp"

namespace ryushi::solvers {

// The largest eigenvalue of D^-1 A (similar to the symmetric D^-1/2 A D^-1/2) by power
// iteration from a fixed start, 5% over its estimate (power iteration approaches it from below).
template <class T>
double largest_jacobi_eigenvalue(const CsrView<T>& A, const std::vector<T>& inverse_diagonal) {
  const std::size_t n = A.rows;
  std::vector<T> x(n), y(n);
  for (std::size_t i = 0; i < n; ++i) x[i] = T(1) + T(0.5) * T(std::sin(double(i) * 12.9898));
  double estimate = 0;
  for (int iteration = 0; iteration < 15; ++iteration) {
    spmv<T, T, T>(A, std::span<const T>(x), std::span<T>(y));
    double norm = 0, dot = 0, xx = 0;
    for (std::size_t i = 0; i < n; ++i) {
      y[i] *= inverse_diagonal[i];
      norm += double(y[i]) * double(y[i]);
      dot += double(y[i]) * double(x[i]);
      xx += double(x[i]) * double(x[i]);
    }
    if (!(norm > 0)) break;
    estimate = dot / xx;
    const double scale = 1.0 / std::sqrt(norm);
    for (std::size_t i = 0; i < n; ++i) x[i] = static_cast<T>(y[i] * scale);
  }
  return 1.05 * estimate;
}

}  // namespace ryushi::solvers
