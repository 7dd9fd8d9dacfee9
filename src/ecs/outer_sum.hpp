#pragma once
// A running sum of outer products a b^T, held in plain scalars. Eigen's `M += a * b.transpose()`
// on a fixed-size 3 x 3 matrix builds the product on the stack with 8- and 16-byte stores and
// reads it back with 16-byte loads that span two stores; such a load cannot take its data from
// the store buffer and waits until both stores have retired. perf put 80% of the 3D corrected
// gradient's time on two such loads. Here every entry is the same product added in the same
// order, so the sums are bit-identical to Eigen's.
#include <Eigen/Core>

namespace ryushi {

template <int R, int C = R>
struct OuterSum {
  double m[R][C] = {};

  // m += a b^T
  template <class A, class B>
  void add(const A& a, const B& b) {
    for (int r = 0; r < R; ++r)
      for (int c = 0; c < C; ++c) m[r][c] += a[r] * b[c];
  }
  // m -= a b^T
  template <class A, class B>
  void subtract(const A& a, const B& b) {
    for (int r = 0; r < R; ++r)
      for (int c = 0; c < C; ++c) m[r][c] -= a[r] * b[c];
  }
  Eigen::Matrix<double, R, C> matrix() const {
    Eigen::Matrix<double, R, C> out;
    for (int r = 0; r < R; ++r)
      for (int c = 0; c < C; ++c) out(r, c) = m[r][c];
    return out;
  }
};

}  // namespace ryushi
