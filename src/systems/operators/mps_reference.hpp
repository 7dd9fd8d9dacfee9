#pragma once
// MPS reference values from the initial lattice (MPS paper eqs. 6 and 8): the particle number
// density n0 = sum_{j != i} w(|r_ij|) and lambda0 = sum_{j != i} |r_ij|^2 w / n0, summed over a
// perfect square (cubic) lattice of spacing d around one particle.
#include <cmath>

#include "kernels/kernel.hpp"

namespace ryushi {

struct MpsReference {
  double n0, lambda0;
};

template <int D>
MpsReference mps_reference(const Kernel<D>& kernel, double d) {
  const long reach = static_cast<long>(std::ceil(kernel.support() / d)) + 1;
  double n0 = 0, second = 0;
  for (long a = -reach; a <= reach; ++a)
    for (long b = -reach; b <= reach; ++b)
      for (long c = (D == 3 ? -reach : 0); c <= (D == 3 ? reach : 0); ++c) {
        if (a == 0 && b == 0 && c == 0) continue;
        double r = d * std::sqrt(double(a * a + b * b + c * c));
        double w = kernel.w(r);
        n0 += w;
        second += r * r * w;
      }
  return {n0, second / n0};
}

}  // namespace ryushi
