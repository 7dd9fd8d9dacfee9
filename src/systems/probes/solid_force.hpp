#pragma once
// The force of the fluid on a [[solid]] body (probe type `force`): the reaction to the pair
// forces its wall particles exert on the fluid, with WCSPH's pair terms (wcsph_pair_forces.hpp):
//   F = sum_{w in body} sum_{f fluid} m_f m_w [ (p_f + p_w) / (rho_f rho_w) grad_f W_fw
//         - (mu_f + mu_f) / (rho_f rho_w) (r^2 F_fw / (r^2 + 0.01 h^2)) (v_f - v~_w) ],
// the viscous part only where the pipeline keeps per-particle viscosity and wall ghost velocities
// (WCSPH with viscosity: no-slip walls). In 2D it is a force per unit depth (N/m).
#include <algorithm>
#include <array>
#include <cmath>
#include <span>
#include <unordered_map>
#include <vector>

#include "ecs/lattice.hpp"
#include "ecs/world.hpp"
#include "systems/kernels/kernel.hpp"
#include "systems/neighbour/domain.hpp"

namespace ryushi {

template <int D>
Vec<D> solid_force(int body, const World<D>& world, const Kernel<D>& kernel, const Domain<D>& domain) {
  auto& x = world.column(components::position);
  auto& kind = world.column(components::kind);
  auto& owner = world.column(components::body);
  auto& m = world.column(components::mass);
  auto& rho = world.column(components::density);
  auto& p = world.column(components::pressure);
  auto& v = world.column(components::velocity);
  const bool viscous = world.has(components::viscosity.name) && world.has(components::wall_velocity.name);
  std::span<const double> mu;
  std::span<const Vec<D>> ghost;
  if (viscous) mu = world.column(components::viscosity), ghost = world.column(components::wall_velocity);
  const double support = kernel.support(), eta2 = 0.01 * kernel.h() * kernel.h();
  // The fluid binned in cells at least a support wide, one pass; on a periodic axis the cells
  // divide the period evenly, so that a step of one cell from the last lands in the first.
  Vec<D> cell = Vec<D>::Constant(support);
  for (int a = 0; a < D; ++a)
    if (domain.periodic[a]) {
      const double length = domain.max[a] - domain.min[a];
      cell[a] = length / std::max(1.0, std::floor(length / support));
    }
  auto cell_of = [&](const Vec<D>& at) {
    long long key = 0;
    for (int a = 0; a < D; ++a)
      key = key * 1000003 + static_cast<long long>(std::floor((at[a] - domain.min[a]) / cell[a]));
    return key;
  };
  std::unordered_map<long long, std::vector<std::size_t>> cells;
  for (std::size_t i = 0; i < world.size(); ++i)
    if (kind[i] == kFluid) cells[cell_of(x[i])].push_back(i);
  const bool periodic = domain.any_periodic();
  Vec<D> force = Vec<D>::Zero();
  for (std::size_t w = 0; w < world.size(); ++w) {
    if (owner[w] != body) continue;
    // The 3^D cells around it (on a periodic axis only a few cells long, some are one cell).
    std::vector<long long> around;
    std::array<long, D> lo{}, hi{};
    for (int a = 0; a < D; ++a) lo[a] = -1, hi[a] = 2;
    for_each_lattice_index<D>(lo, hi, [&](const std::array<long, D>& offset) {
      Vec<D> at = x[w];
      for (int a = 0; a < D; ++a) at[a] += offset[a] * cell[a];
      if (periodic) domain.wrap(at);
      around.push_back(cell_of(at));
    });
    std::sort(around.begin(), around.end());
    around.erase(std::unique(around.begin(), around.end()), around.end());
    for (long long key : around) {
      auto found = cells.find(key);
      if (found == cells.end()) continue;
      for (auto f : found->second) {
        const Vec<D> r = periodic ? domain.displacement(x[f], x[w]) : Vec<D>(x[f] - x[w]);
        const double r2 = r.squaredNorm();
        if (r2 >= support * support || r2 == 0) continue;
        const double F = kernel.grad_factor(std::sqrt(r2)), inv_rho = 1.0 / (rho[f] * rho[w]);
        force += m[f] * m[w] * (p[f] + p[w]) * inv_rho * F * r;
        if (viscous) force -= m[f] * m[w] * 2 * mu[f] * inv_rho * (r2 * F / (r2 + eta2)) * (v[f] - ghost[w]);
      }
    }
  }
  return force;
}

}  // namespace ryushi
