#pragma once
// WCSPH's pair forces between the fluid and a [[solid]] body's particles, the reaction to what they
// exert on the fluid (wcsph_pair_forces.hpp):
//   F = sum_{w in body} sum_{f fluid} m_f m_w [ (p_f + p_w) / (rho_f rho_w) grad_f W_fw
//         - (mu_f + mu_f) / (rho_f rho_w) (r^2 F_fw / (r^2 + 0.01 h^2)) (v_f - v~_w) ],
// the viscous part only where the pipeline keeps per-particle viscosity and wall ghost velocities
// (WCSPH with viscosity: no-slip walls). In 2D it is a force per unit depth (N/m). The `force`
// probe takes the viscous part only (with_pressure = false), its pressure part being the surface
// pressure's that every method shares (solid_surface_force.hpp): the pair reaction read a resting
// tank's thrust on a plate 2.5% low (H/d = 20), the Adami wall's pressure being the fluid's
// carried to a particle d/2 behind the surface with the kernel's lattice error.
#include <cmath>
#include <span>

#include "ecs/world.hpp"
#include "kernels/kernel.hpp"
#include "systems/neighbour/domain.hpp"
#include "systems/probes/fluid_cells.hpp"

namespace ryushi {

template <int D>
Vec<D> solid_force(int body, const World<D>& world, const Kernel<D>& kernel, const Domain<D>& domain,
                   const FluidCells<D>& cells, bool with_pressure = true) {
  auto& x = world.column(components::position);
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
  // cells: the fluid binned at least a support wide (the force probe shares the sensors').
  const bool periodic = domain.any_periodic();
  Vec<D> force = Vec<D>::Zero();
  for (std::size_t w = 0; w < world.size(); ++w) {
    if (owner[w] != body) continue;
    cells.around(x[w], [&](std::size_t f) {
      const Vec<D> r = periodic ? domain.displacement(x[f], x[w]) : Vec<D>(x[f] - x[w]);
      const double r2 = r.squaredNorm();
      if (r2 >= support * support || r2 == 0) return;
      const double F = kernel.grad_factor(std::sqrt(r2)), inv_rho = 1.0 / (rho[f] * rho[w]);
      if (with_pressure) force += m[f] * m[w] * (p[f] + p[w]) * inv_rho * F * r;
      if (viscous) force -= m[f] * m[w] * 2 * mu[f] * inv_rho * (r2 * F / (r2 + eta2)) * (v[f] - ghost[w]);
    });
  }
  return force;
}

}  // namespace ryushi
