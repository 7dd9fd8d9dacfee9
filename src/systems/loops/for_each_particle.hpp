#pragma once
// Parallel loop over the fluid particles: each particle gathers over its own neighbours and
// writes only itself, so no atomics are needed.
#include <tbb/parallel_for.h>
#include <tbb/parallel_reduce.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <span>
#include <vector>

#include "ecs/component.hpp"
#include "ecs/math.hpp"

namespace ryushi {

template <class Body>
void for_each_of_kind(std::span<const std::int32_t> kind, std::int32_t wanted, Body&& body) {
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, kind.size(), 1024), [&](auto r) {
    for (std::size_t i = r.begin(); i != r.end(); ++i)
      if (kind[i] == wanted) body(i);
  });
}

// The largest speed of a fluid particle (time-step controls).
template <int D>
double max_fluid_speed(std::span<const std::int32_t> kind, std::span<const Vec<D>> v) {
  double v2 = tbb::parallel_reduce(
      tbb::blocked_range<std::size_t>(0, v.size(), 4096), 0.0,
      [&](auto r, double m) {
        for (std::size_t i = r.begin(); i != r.end(); ++i)
          if (kind[i] == kFluid) m = std::max(m, v[i].squaredNorm());
        return m;
      },
      [](double a, double b) { return std::max(a, b); });
  return std::sqrt(v2);
}

// Particle volumes V_i = m_i / rho_i, the weights of the SPH sums (operators' ParticleView).
inline void particle_volumes(std::span<const double> m, std::span<const double> rho,
                             std::vector<double>& out) {
  out.resize(m.size());
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, m.size(), 4096), [&](auto r) {
    for (std::size_t i = r.begin(); i != r.end(); ++i) out[i] = m[i] / rho[i];
  });
}

// 1/rho_i per particle: a pair loop multiplies instead of dividing.
inline void inverse_densities(std::span<const double> rho, std::vector<double>& out) {
  out.resize(rho.size());
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, rho.size(), 4096), [&](auto r) {
    for (std::size_t i = r.begin(); i != r.end(); ++i) out[i] = 1.0 / rho[i];
  });
}

}  // namespace ryushi
