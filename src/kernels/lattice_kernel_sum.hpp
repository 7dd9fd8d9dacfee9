#pragma once
// The kernel summed over a square (cubic) lattice: the reference a density estimate of a
// particle arrangement is measured against.
#include <array>
#include <cmath>

#include "ecs/lattice.hpp"
#include "kernels/kernel.hpp"

namespace ryushi {

// Sum of W over the lattice points of spacing d within `radius` of a lattice point (itself
// included): eq. 19's reference (radius = the first shell) and the full support's.
template <int D>
double lattice_kernel_sum(const Kernel<D>& kernel, double d, double radius) {
  const long reach = static_cast<long>(std::ceil(radius / d));
  std::array<long, D> lo, hi;
  lo.fill(-reach);
  hi.fill(reach + 1);
  double sum = 0;
  for_each_lattice_index<D>(lo, hi, [&](const std::array<long, D>& k) {
    double r2 = 0;
    for (int a = 0; a < D; ++a) r2 += double(k[a] * k[a]) * d * d;
    if (r2 <= radius * radius) sum += kernel.w(std::sqrt(r2));
  });
  return sum;
}

}  // namespace ryushi
