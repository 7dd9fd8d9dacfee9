#pragma once
// The kernel summed over a square (cubic) lattice: the reference a density estimate of a
// particle arrangement is measured against.
#include <array>
#include <cmath>

#include "ecs/lattice.hpp"
#include "kernels/kernel.hpp"

namespace ryushi {

// f(k, r2) for each offset k of a square (cubic) lattice of spacing d within `radius` of a lattice
// point (the point itself included, k = 0), r2 = |k d|^2.
template <int D, class F>
void for_each_lattice_offset(double d, double radius, F&& f) {
  const long reach = static_cast<long>(std::ceil(radius / d));
  std::array<long, D> lo, hi;
  lo.fill(-reach);
  hi.fill(reach + 1);
  for_each_lattice_index<D>(lo, hi, [&](const std::array<long, D>& k) {
    double r2 = 0;
    for (int a = 0; a < D; ++a) r2 += double(k[a] * k[a]) * d * d;
    if (r2 <= radius * radius) f(k, r2);
  });
}

// Sum of W over the lattice points of spacing d within `radius` of a lattice point (itself
// included): eq. 19's reference (radius = the first shell) and the full support's.
template <int D>
double lattice_kernel_sum(const Kernel<D>& kernel, double d, double radius) {
  double sum = 0;
  for_each_lattice_offset<D>(d, radius,
                             [&](const std::array<long, D>&, double r2) { sum += kernel.w(std::sqrt(r2)); });
  return sum;
}

// sum_j V (x_j - x_i)_0 (grad_i W_ij)_0 over the lattice (V = d^D): 1 for a gradient that is exact
// for a linear field, 0 when no neighbour lies inside the support.
template <int D>
double lattice_gradient_moment(const Kernel<D>& kernel, double d) {
  double moment = 0;
  for_each_lattice_offset<D>(d, kernel.support(), [&](const std::array<long, D>& k, double r2) {
    if (r2 > 0) moment -= std::pow(d, D) * double(k[0] * k[0]) * d * d * kernel.grad_factor(std::sqrt(r2));
  });
  return moment;
}

}  // namespace ryushi
