#pragma once
// Parallel kernels for the Krylov methods: SpMV, dot, axpy. Reductions are deterministic for
// every thread count: the vector is cut into fixed chunks (independent of the number of
// threads), each chunk is summed serially, and the chunk sums are added in order.
#include <tbb/parallel_for.h>

#include <span>
#include <type_traits>
#include <vector>

#include "solvers/csr_matrix.hpp"

namespace ryushi::solvers {

inline constexpr std::size_t kReductionChunk = 4096;

// y = A x (x may be of another precision). A row sums in double unless matrix and vector are
// both float: the float multigrid hierarchy then runs at float speed (8 bytes per nonzero read
// instead of 12, no conversions), and a preconditioner needs no more than float accuracy.
template <class T, class X, class Y>
void spmv(const CsrView<T>& A, std::span<const X> x, std::span<Y> y) {
  using Sum = std::conditional_t<std::is_same_v<T, float> && std::is_same_v<X, float>, float, double>;
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, A.rows, 1024), [&](auto r) {
    for (std::size_t i = r.begin(); i != r.end(); ++i) {
      Sum s = 0;
      for (auto k = A.row_ptr[i]; k < A.row_ptr[i + 1]; ++k) s += Sum(A.val[k]) * Sum(x[A.col[k]]);
      y[i] = static_cast<Y>(s);
    }
  });
}
template <class T, class X, class Y>
void spmv(const CsrMatrix<T>& A, std::span<const X> x, std::span<Y> y) {
  spmv<T, X, Y>(A.view(), x, y);
}

// f(i) for i in [0, n) in parallel, in blocks (one call per block, not per element).
template <class F>
void parallel_indices(std::size_t n, F&& f, std::size_t grain = 4096) {
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n, grain), [&](auto r) {
    for (std::size_t i = r.begin(); i != r.end(); ++i) f(i);
  });
}

template <class T>
double dot(std::span<const T> a, std::span<const T> b) {
  const std::size_t n = a.size(), chunks = (n + kReductionChunk - 1) / kReductionChunk;
  std::vector<double> partial(chunks, 0.0);
  tbb::parallel_for(std::size_t(0), chunks, [&](std::size_t c) {
    double s = 0;
    for (std::size_t i = c * kReductionChunk, e = std::min(n, i + kReductionChunk); i < e; ++i) s += double(a[i]) * double(b[i]);
    partial[c] = s;
  });
  double total = 0;
  for (double p : partial) total += p;
  return total;
}

// y = y + alpha x
template <class T>
void axpy(double alpha, std::span<const T> x, std::span<T> y) {
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, x.size(), 8192), [&](auto r) {
    for (std::size_t i = r.begin(); i != r.end(); ++i) y[i] += static_cast<T>(alpha * x[i]);
  });
}

// y = x + beta y
template <class T>
void xpby(std::span<const T> x, double beta, std::span<T> y) {
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, x.size(), 8192), [&](auto r) {
    for (std::size_t i = r.begin(); i != r.end(); ++i) y[i] = x[i] + static_cast<T>(beta * y[i]);
  });
}

}  // namespace ryushi::solvers
