#pragma once
// Heat conduction (seed 001 eqs. 2 and 32-34): the columns a scene that models temperature adds,
// the wall conditions and the constants of the conduction systems. A scene without heat never
// creates these columns.
#include <cstdint>

#include "ecs/component.hpp"
#include "kernels/kernel.hpp"
#include "systems/neighbour/domain.hpp"

namespace ryushi {

namespace components {
inline constexpr Component<Scalar> temperature{"temperature"};  // K
inline constexpr Component<Scalar> temperature_rate{"temperature_rate"};
inline constexpr Component<Scalar> temperature_start{"temperature_start"};  // the midpoint's T^n
// A wall particle's thermal condition (ThermalWall); only in scenes with walls and heat.
inline constexpr Component<Flags> thermal_wall{"thermal_wall"};
// A heat-flux wall particle's flux into the fluid, W/m^2; only in scenes with a flux wall.
inline constexpr Component<Scalar> wall_heat_flux{"wall_heat_flux"};
// How deep a wall particle lies behind the wall's surface, (layer - 1/2) d; with fixed-temperature
// or flux walls (which also take wall_normal).
inline constexpr Component<Scalar> wall_depth{"wall_depth"};
}  // namespace components

// How a wall takes part in conduction (heat_conduction.hpp): adiabatic walls are left out of the
// sum (no flux through them: the SPH sum sees no neighbour there, a zero normal gradient);
// fixed-temperature walls (Dirichlet) and flux walls (Neumann) stand, pair by pair, for the
// temperature that continues the fluid's profile through the wall's surface.
enum ThermalWall : std::int32_t { kAdiabaticWall = 0, kFixedTemperatureWall = 1, kHeatFluxWall = 2 };

template <int D>
struct HeatParameters {
  Kernel<D> kernel{KernelType::WendlandC2, 1.0};
  Domain<D> domain;
  double conductivity = 0;   // k, W/(m K)
  double heat_capacity = 1;  // c, J/(kg K)
  double spacing = 1;        // d: the nearest a fluid particle is taken to be to a wall's surface is d/2
  bool walls = false;        // the scene has wall particles (thermal_wall column)
  bool flux_walls = false;   // some wall has a heat flux (wall_heat_flux column)
  bool fixed_walls = false;  // some wall has a fixed temperature
  // wall_normal and wall_depth columns: the geometry a fixed or flux wall's pair term needs
  bool wall_geometry() const { return flux_walls || fixed_walls; }

  // Explicit diffusion's step limit with the reference density rho0: 0.125 h^2 / alpha, alpha =
  // k / (rho0 c), the same factor as the viscous limit (the Laplacians have the same form).
  double step_limit(double rho0) const {
    const double h = kernel.h();
    return conductivity > 0 ? 0.125 * h * h * rho0 * heat_capacity / conductivity : 0.0;
  }
};

}  // namespace ryushi
