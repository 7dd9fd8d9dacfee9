#pragma once
// Heat conduction by the Cleary-Monaghan SPH Laplacian (seed 001 eq. 34, Cleary & Monaghan 1999):
//   c dT_i/dt = sum_j 4 m_j k_i k_j / (rho_i rho_j (k_i + k_j)) (T_i - T_j) x_ij . grad_i W_ij / (r^2 +
//   eta^2)
// with eta^2 = 0.01 h^2; one material here, so 4 k_i k_j / (k_i + k_j) = 2 k. Seed 001 writes the
// density weight as 4 rho_i / (rho_i + rho_j) m / rho_j, equal to this at equal densities; this
// form is symmetric in (i, j), so m_i c dT_i/dt + m_j c dT_j/dt = 0 pair by pair and the heat of
// fluid between adiabatic walls is conserved to round-off at any densities.
// Walls (heat_parameters.hpp): adiabatic walls are left out. A fixed-temperature or flux wall
// particle j at depth delta_j behind the wall's surface (normal n_j, out of the fluid) stands,
// for the pair (i, j), for the fluid's profile continued linearly through the surface, with i at
// distance delta_i = -x_ij . n_j - delta_j in front of it (at least d/2, the lattice's distance):
//   fixed T_w:  T_j = T_w + (T_w - T_i) delta_j / delta_i   (Morris, Fox & Zhu 1997's no-slip
//               velocity, applied to temperature)
//   flux q:     T_j = T_i + (q / k)(delta_i + delta_j)       (normal gradient -q/k: heat q, W/m^2,
//               entering the fluid)
// Holding the wall particles at T_w instead puts the effective wall 0.6 d behind the surface
// (measured: the steady slope between two plates 40 d apart 3% low).
#include <algorithm>
#include <cmath>

#include "ecs/io.hpp"
#include "systems/heat/heat_parameters.hpp"
#include "systems/loops/for_each_particle.hpp"
#include "systems/neighbour/neighbour_list.hpp"

namespace ryushi {

template <int D>
class HeatConduction final : public System<D> {
 public:
  explicit HeatConduction(const HeatParameters<D>& p) : p_(p) {}
  std::string name() const override { return "heat_conduction_cleary_monaghan"; }
  auto io() const {
    return Io{reads(components::position, components::density, components::mass, components::kind,
                    components::temperature, neighbours_resource),
              writes(components::temperature_rate), optional(p_.walls, reads(components::thermal_wall)),
              optional(p_.flux_walls, reads(components::wall_heat_flux)),
              optional(p_.wall_geometry(), reads(components::wall_normal, components::wall_depth))};
  }
  Access access() const override { return io().access(); }
  void run(SystemContext<D>& ctx) override {
    // Empty spans for the wall columns the scene has not got.
    auto [x, rho, m, kind, T, nl, rate, thermal, flux, normal, depth] = io().fetch(ctx);
    const double nearest = 0.5 * p_.spacing;
    const double support2 = p_.kernel.support() * p_.kernel.support();
    const double eta2 = 0.01 * p_.kernel.h() * p_.kernel.h();
    const double k = p_.conductivity, two_k_over_c = 2.0 * k / p_.heat_capacity;
    for_each_of_kind(kind, kFluid, [&](std::size_t i) {
      const Vec<D> xi = x[i];
      const double Ti = T[i];
      double sum = 0;
      for (auto j : nl.of(i)) {
        const Vec<D> xij = p_.domain.displacement(xi, x[j]);
        const double r2 = xij.squaredNorm();
        if (r2 >= support2) continue;
        double Tj = T[j];
        if (kind[j] != kFluid) {
          const std::int32_t condition = thermal.empty() ? kAdiabaticWall : thermal[j];
          if (condition == kAdiabaticWall) continue;
          const double dj = depth[j], di = std::max(nearest, -xij.dot(normal[j]) - dj);
          Tj = condition == kHeatFluxWall ? Ti + flux[j] / k * (di + dj) : T[j] + (T[j] - Ti) * dj / di;
        }
        // x_ij . grad_i W = r^2 grad_factor(r)
        sum += m[j] / rho[j] * (Ti - Tj) * r2 * p_.kernel.grad_factor(std::sqrt(r2)) / (r2 + eta2);
      }
      rate[i] = two_k_over_c / rho[i] * sum;
    });
  }

 private:
  HeatParameters<D> p_;
};

}  // namespace ryushi
