#pragma once
// The fluid particles binned in cells at least a support wide, for probes that visit the fluid
// around a few points (a body's particles) once per sample, without the step's neighbour list.
// On a periodic axis the cells divide the period evenly, so that a step of one cell from the
// last lands in the first.
#include <algorithm>
#include <array>
#include <cmath>
#include <unordered_map>
#include <vector>

#include "ecs/lattice.hpp"
#include "ecs/world.hpp"
#include "systems/neighbour/domain.hpp"

namespace ryushi {

template <int D>
class FluidCells {
 public:
  FluidCells(const World<D>& world, const Domain<D>& domain, double support)
      : domain_(domain), cell_(Vec<D>::Constant(support)) {
    for (int a = 0; a < D; ++a)
      if (domain.periodic[a]) {
        const double length = domain.max[a] - domain.min[a];
        cell_[a] = length / std::max(1.0, std::floor(length / support));
      }
    auto& x = world.column(components::position);
    auto& kind = world.column(components::kind);
    for (std::size_t i = 0; i < world.size(); ++i)
      if (kind[i] == kFluid) cells_[key(x[i])].push_back(i);
  }
  // Calls visit(f) for every fluid particle in the 3^D cells around `at` (each once), a superset
  // of those within a support of it.
  template <class Visit>
  void around(const Vec<D>& at, Visit&& visit) const {
    std::vector<long long> keys;
    std::array<long, D> lo{}, hi{};
    for (int a = 0; a < D; ++a) lo[a] = -1, hi[a] = 2;
    for_each_lattice_index<D>(lo, hi, [&](const std::array<long, D>& offset) {
      Vec<D> q = at;
      for (int a = 0; a < D; ++a) q[a] += offset[a] * cell_[a];
      if (domain_.any_periodic()) domain_.wrap(q);
      keys.push_back(key(q));
    });
    // On a periodic axis only a few cells long, some of the 3^D are one cell.
    std::sort(keys.begin(), keys.end());
    keys.erase(std::unique(keys.begin(), keys.end()), keys.end());
    for (long long k : keys)
      if (auto found = cells_.find(k); found != cells_.end())
        for (auto f : found->second) visit(f);
  }

 private:
  long long key(const Vec<D>& at) const {
    long long k = 0;
    for (int a = 0; a < D; ++a)
      k = k * 1000003 + static_cast<long long>(std::floor((at[a] - domain_.min[a]) / cell_[a]));
    return k;
  }
  Domain<D> domain_;
  Vec<D> cell_;
  std::unordered_map<long long, std::vector<std::size_t>> cells_;
};

}  // namespace ryushi
