#pragma once
// Walks a D-dimensional integer lattice, axis 0 fastest: the one loop behind particle blocks,
// walls, patch tests and benchmark problems (the order matters wherever a random generator is
// drawn per point, so it is fixed here).
#include <array>

#include "ecs/math.hpp"

namespace ryushi {

// f(k) for every index k with lo[a] <= k[a] < hi[a]; nothing if the box is empty.
template <int D, class F>
void for_each_lattice_index(const std::array<long, D>& lo, const std::array<long, D>& hi, F&& f) {
  for (int a = 0; a < D; ++a)
    if (lo[a] >= hi[a]) return;
  std::array<long, D> k = lo;
  while (true) {
    f(k);
    int a = 0;
    while (a < D && ++k[a] == hi[a]) {
      k[a] = lo[a];
      ++a;
    }
    if (a == D) return;
  }
}

// f(x) for every lattice point x = origin + (k + 1/2) d, k in [lo, hi).
template <int D, class F>
void for_each_lattice_point(const Vec<D>& origin, double d, const std::array<long, D>& lo,
                            const std::array<long, D>& hi, F&& f) {
  for_each_lattice_index<D>(lo, hi, [&](const std::array<long, D>& k) {
    Vec<D> x;
    for (int a = 0; a < D; ++a) x[a] = origin[a] + (k[a] + 0.5) * d;
    f(x);
  });
}

}  // namespace ryushi
