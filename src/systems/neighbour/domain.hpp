#pragma once
// The simulation box: bounds, periodic axes and the minimum-image displacement.
#include <array>
#include <cmath>

#include "ecs/math.hpp"
#include "ecs/resources.hpp"

namespace ryushi {

template <int D>
struct Domain {
  Vec<D> min = Vec<D>::Zero();
  Vec<D> max = Vec<D>::Ones();
  std::array<bool, D> periodic{};

  bool any_periodic() const {
    for (bool p : periodic)
      if (p) return true;
    return false;
  }
  // x_i - x_j, wrapped to the nearest image on periodic axes.
  Vec<D> displacement(const Vec<D>& xi, const Vec<D>& xj) const {
    Vec<D> d = xi - xj;
    for (int a = 0; a < D; ++a) {
      if (!periodic[a]) continue;
      double L = max[a] - min[a];
      d[a] -= L * std::round(d[a] / L);
    }
    return d;
  }
  // x_to - x_from: the minimum image on periodic axes, the plain difference otherwise (r_ij =
  // x_j - x_i in the operators' convention is offset(x[i], x[j])).
  Vec<D> offset(const Vec<D>& from, const Vec<D>& to) const {
    return any_periodic() ? displacement(to, from) : Vec<D>(to - from);
  }
  // Brings a position back into the box on periodic axes.
  void wrap(Vec<D>& x) const {
    for (int a = 0; a < D; ++a) {
      if (!periodic[a]) continue;
      double L = max[a] - min[a];
      x[a] -= L * std::floor((x[a] - min[a]) / L);
    }
  }
  bool contains(const Vec<D>& x) const {
    for (int a = 0; a < D; ++a)
      if (!periodic[a] && (x[a] < min[a] || x[a] > max[a])) return false;
    return true;
  }
};

template <int D>
inline constexpr Resource<Domain<D>> domain_resource{"domain"};

}  // namespace ryushi
