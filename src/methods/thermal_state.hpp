#pragma once
// A scene with heat (Scene::models_heat): the particles' starting temperatures and the walls'
// thermal conditions (systems/heat/heat_parameters.hpp), after append_scene_particles put the
// fluid first and the walls last. Fluid takes its block's temperature; fixed-temperature walls
// hold theirs (the wall's, from which the conduction extrapolates); adiabatic and flux walls
// carry the mean fluid temperature, for pictures only. A wall particle's depth behind the
// surface is (layer - 1/2) d: the lattice layers of [[wall]] boxes and [[solid]] shells.
#include <cmath>

#include "methods/scene_particles.hpp"
#include "systems/heat/heat_parameters.hpp"

namespace ryushi {

template <int D>
void add_thermal_state(const Scene& s, const SceneParticles<D>& appended, World<D>& world) {
  auto& T = world.ensure(components::temperature);
  const std::size_t nf = appended.fluid.size(), nw = appended.wall.size();
  const std::size_t first_wall = world.size() - nw, first_fluid = first_wall - nf;
  double mean = 0;
  for (std::size_t k = 0; k < nf; ++k) mean += (T[first_fluid + k] = appended.fluid_temperature[k]);
  mean = nf > 0 ? mean / static_cast<double>(nf) : 0.0;
  if (nw == 0) return;
  auto condition = [&](std::size_t k) -> const ThermalCondition& {
    return appended.wall_body[k] >= 0 ? s.solids[appended.wall_body[k]].thermal
                                      : s.walls[appended.wall_box[k]].thermal;
  };
  bool flux = false, geometry = false;
  for (std::size_t k = 0; k < nw; ++k) {
    flux = flux || condition(k).flux();
    geometry = geometry || condition(k).flux() || condition(k).fixed();
  }
  auto& kind = world.ensure(components::thermal_wall);
  std::span<double> q, depth;
  std::span<Vec<D>> normal;
  if (flux) q = world.ensure(components::wall_heat_flux);
  if (geometry) {
    normal = world.ensure(components::wall_normal);
    depth = world.ensure(components::wall_depth);
  }
  for (std::size_t k = 0; k < nw; ++k) {
    const std::size_t i = first_wall + k;
    const ThermalCondition& c = condition(k);
    kind[i] = c.fixed() ? kFixedTemperatureWall : c.flux() ? kHeatFluxWall : kAdiabaticWall;
    T[i] = c.fixed() ? c.temperature : mean;
    if (flux) q[i] = c.flux() ? c.heat_flux : 0.0;
    if (geometry) {
      normal[i] = appended.wall_normal[k];
      depth[i] = (appended.wall_layer[k] - 0.5) * s.spacing;
    }
  }
}

template <int D>
HeatParameters<D> heat_parameters(const Scene& s, const Kernel<D>& kernel, const Domain<D>& domain) {
  HeatParameters<D> p;
  p.kernel = kernel;
  p.domain = domain;
  p.conductivity = s.conductivity;
  p.heat_capacity = s.heat_capacity;
  p.spacing = s.spacing;
  p.walls = !s.walls.empty() || !s.solids.empty();
  for (auto& w : s.walls)
    p.flux_walls = p.flux_walls || w.thermal.flux(), p.fixed_walls = p.fixed_walls || w.thermal.fixed();
  for (auto& b : s.solids)
    p.flux_walls = p.flux_walls || b.thermal.flux(), p.fixed_walls = p.fixed_walls || b.thermal.fixed();
  return p;
}

}  // namespace ryushi
