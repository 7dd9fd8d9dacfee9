#pragma once
// A running sum of outer products a b^T, held in plain scalars. Eigen's `M += a * b.transpose()`
// on a fixed-size 3 x 3 matrix builds the product on the stack with 8- and 16-byte stores and
// reads it back with 16-byte loads that span two stores; such a load cannot take its data from
// the store buffer and waits until both stores have retired. perf put 80% of the 3D corrected
// gradient's time on two such loads. Here every entry is the same product added in the same
// order, so the sums are bit-identical to Eigen's either way.
#include <Eigen/Core>

namespace ryushi {

template <int R, int C = R>
struct OuterSum {
  // Odd row counts (3 x 3 in 3D, the K = 3 moments in 2D) in scalars; even ones keep Eigen's
  // matrix, whose columns are whole 16-byte packets that forward (scalars there measured a few
  // percent slower on the 2D density gradient).
  static constexpr bool kScalars = R % 2 == 1;
  double m[kScalars ? R : 1][kScalars ? C : 1] = {};
  using Packed = Eigen::Matrix<double, (kScalars ? 1 : R), (kScalars ? 1 : C)>;
  Packed packed = Packed::Zero();

  // m += a b^T
  template <class A, class B>
  void add(const A& a, const B& b) {
    if constexpr (kScalars) {
      for (int r = 0; r < R; ++r)
        for (int c = 0; c < C; ++c) m[r][c] += a[r] * b[c];
    } else {
      packed += a * b.transpose();
    }
  }
  // m -= a b^T
  template <class A, class B>
  void subtract(const A& a, const B& b) {
    if constexpr (kScalars) {
      for (int r = 0; r < R; ++r)
        for (int c = 0; c < C; ++c) m[r][c] -= a[r] * b[c];
    } else {
      packed -= a * b.transpose();
    }
  }
  Eigen::Matrix<double, R, C> matrix() const {
    if constexpr (!kScalars) {
      return packed;
    } else {
      Eigen::Matrix<double, R, C> out;
      for (int r = 0; r < R; ++r)
        for (int c = 0; c < C; ++c) out(r, c) = m[r][c];
      return out;
    }
  }
};

}  // namespace ryushi
