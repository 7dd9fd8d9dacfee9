#pragma once
// The fluid particles (or, with solid = true, the wall and body particles) binned in cells at
// least a support wide, for probes that visit them around a few points (a body's particles) once
// per sample, without the step's neighbour list.
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
  FluidCells(const World<D>& world, const Domain<D>& domain, double support, bool solid = false)
      : domain_(domain), cell_(Vec<D>::Constant(support)) {
    for (int a = 0; a < D; ++a)
      if (domain.periodic[a]) {
        const double length = domain.max[a] - domain.min[a];
        count_[a] = static_cast<long long>(std::max(1.0, std::floor(length / support)));
        cell_[a] = length / static_cast<double>(count_[a]);
      }
    auto& x = world.column(components::position);
    auto& kind = world.column(components::kind);
    for (std::size_t i = 0; i < world.size(); ++i)
      if ((kind[i] == kFluid) != solid) cells_[key(x[i])].push_back(i);
  }
  // Calls visit(f) for every fluid particle in the 3^D cells around `at` (each once), a superset
  // of those within a support of it. The neighbouring cells are counted from `at`'s own cell in
  // whole indices: stepping `at` by a cell width and flooring again skipped a cell when `at` lay
  // on a cell boundary (a force probe's surface point 0.5 m from the domain's edge with 0.06 m
  // cells read 9.99.. and 8.99.., missing the fluid in cell 9).
  template <class Visit>
  void around(const Vec<D>& at, Visit&& visit) const {
    Vec<D> q = at;
    if (domain_.any_periodic()) domain_.wrap(q);
    const auto base = index(q);
    std::vector<long long> keys;
    std::array<long, D> lo{}, hi{};
    for (int a = 0; a < D; ++a) lo[a] = -1, hi[a] = 2;
    for_each_lattice_index<D>(lo, hi, [&](const std::array<long, D>& offset) {
      std::array<long long, D> cell{};
      for (int a = 0; a < D; ++a) {
        cell[a] = base[a] + offset[a];
        if (domain_.periodic[a]) cell[a] = ((cell[a] % count_[a]) + count_[a]) % count_[a];
      }
      keys.push_back(key_of(cell));
    });
    // On a periodic axis only a few cells long, some of the 3^D are one cell.
    std::sort(keys.begin(), keys.end());
    keys.erase(std::unique(keys.begin(), keys.end()), keys.end());
    for (long long k : keys)
      if (auto found = cells_.find(k); found != cells_.end())
        for (auto f : found->second) visit(f);
  }

 private:
  std::array<long long, D> index(const Vec<D>& at) const {
    std::array<long long, D> cell{};
    for (int a = 0; a < D; ++a) {
      cell[a] = static_cast<long long>(std::floor((at[a] - domain_.min[a]) / cell_[a]));
      if (domain_.periodic[a])
        cell[a] = std::clamp<long long>(cell[a], 0, count_[a] - 1);  // at the period's end
    }
    return cell;
  }
  static long long key_of(const std::array<long long, D>& cell) {
    long long k = 0;
    for (int a = 0; a < D; ++a) k = k * 1000003 + cell[a];
    return k;
  }
  long long key(const Vec<D>& at) const { return key_of(index(at)); }
  Domain<D> domain_;
  Vec<D> cell_;
  std::array<long long, D> count_{};  // cells along each periodic axis (the period over cell_)
  std::unordered_map<long long, std::vector<std::size_t>> cells_;
};

}  // namespace ryushi
