#pragma once
// The particles a scene describes, before any method gives them mass or pressure: fluid blocks
// on the lattice (with their depth below the block's top, for hydrostatic starts, cut around
// solid bodies and clipped to a mesh), imported fluid, wall containers and solid bodies (with
// each wall particle's layer, 1 = touching the fluid, its normal and its body). Every method
// fills its world from this one description.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <span>
#include <utility>
#include <vector>

#include "ecs/math.hpp"
#include "ecs/world.hpp"
#include "scene/scene.hpp"
#include "methods/method_context.hpp"
#include "systems/neighbour/domain.hpp"

namespace ryushi {

template <int D>
struct SceneParticles {
  std::vector<Vec<D>> fluid;
  std::vector<double> depth;
  std::vector<Vec<D>> fluid_velocity;  // the block's initial velocity and rotation
  std::vector<double> pressure;        // the block's initial pressure; NaN: the method's own start
  std::vector<double> fluid_temperature;  // the block's (or [material]) temperature; NaN: no heat
  std::vector<Vec<D>> wall;
  std::vector<int> wall_layer;
  // Unit normal out of the fluid into the wall: along the axes on which the particle lies
  // outside the box, weighted by how far, so a layer-1 corner particle gets the bisector.
  std::vector<Vec<D>> wall_normal;
  std::vector<Vec<D>> wall_velocity;  // a [[solid]]'s prescribed velocity; zero for containers
  std::vector<int> wall_body;         // the [[solid]]'s index; -1 for containers
  std::vector<int> wall_box;          // the [[wall]]'s index; -1 for solids
  std::vector<double> wall_area;      // a body's first layer: the surface each stands for (else 0)
};

// ring_containers: ISPH's one wall layer with normals, a ring outside a round container
// (scene_particles.cpp says why); otherwise a container's walls are the lattice outside it.
template <int D>
SceneParticles<D> scene_particles(const Scene& scene, bool ring_containers = false);

// Appends the scene's particles to the world: fluid with the blocks' initial velocities,
// (density, pressure) = fluid_state(depth, pressure) (pressure: the block's given initial
// pressure, NaN where none) and mass = density * d^D (each lattice cell holds its fluid), then
// the wall particles with kind = wall_kind(layer), density rho0, mass rho0 d^D and their body's
// velocity; a method that keeps only some layers drops the others with keep_layer (and, with
// one layer, may ask for ring_containers).
// Returns the particles as appended (the kept wall layers, in order), for what a method adds.
template <int D, class FluidState, class WallKind, class KeepLayer = bool (*)(int)>
SceneParticles<D> append_scene_particles(
    const Scene& s, double rho0, World<D>& world, FluidState&& fluid_state, WallKind&& wall_kind,
    KeepLayer&& keep_layer = [](int) { return true; }, bool ring_containers = false) {
  const double volume = std::pow(s.spacing, D);
  auto particles = scene_particles<D>(s, ring_containers);
  {  // only the kept wall layers
    SceneParticles<D> kept = particles;
    kept.wall.clear(), kept.wall_layer.clear(), kept.wall_normal.clear();
    kept.wall_velocity.clear(), kept.wall_body.clear(), kept.wall_box.clear(), kept.wall_area.clear();
    for (std::size_t k = 0; k < particles.wall.size(); ++k)
      if (keep_layer(particles.wall_layer[k])) {
        kept.wall.push_back(particles.wall[k]);
        kept.wall_layer.push_back(particles.wall_layer[k]);
        kept.wall_normal.push_back(particles.wall_normal[k]);
        kept.wall_velocity.push_back(particles.wall_velocity[k]);
        kept.wall_body.push_back(particles.wall_body[k]);
        kept.wall_box.push_back(particles.wall_box[k]);
        kept.wall_area.push_back(particles.wall_area[k]);
      }
    particles = std::move(kept);
  }
  std::size_t first = world.append(particles.fluid.size(), kFluid);
  auto& x = world.ensure(components::position);
  auto& m = world.ensure(components::mass);
  auto& rho = world.ensure(components::density);
  auto& pr = world.ensure(components::pressure);
  auto& v = world.ensure(components::velocity);
  for (std::size_t k = 0; k < particles.fluid.size(); ++k) {
    std::size_t i = first + k;
    x[i] = particles.fluid[k];
    v[i] = particles.fluid_velocity[k];
    auto [density, pressure] = fluid_state(particles.depth[k], particles.pressure[k]);
    rho[i] = density;
    pr[i] = pressure;
    m[i] = density * volume;
  }
  std::size_t wfirst = world.append(particles.wall.size(), kWall);
  auto& kind = world.column(components::kind);
  // Only a scene with [[solid]] bodies pays for the column that tells them apart (force probes).
  std::span<std::int32_t> body;
  if (!s.solids.empty()) {
    auto& column = world.ensure(components::body);
    std::fill(column.begin(), column.end(), -1);
    body = column;
  }
  std::span<Vec<D>> origin;
  if (std::any_of(s.solids.begin(), s.solids.end(),
                  [](const SolidSpec& b) { return b.moves(); })) {
    origin = world.ensure(components::body_origin);
    world.ensure(components::body_acceleration);  // zero until the motion sets it
  }
  for (std::size_t k = 0; k < particles.wall.size(); ++k) {
    std::size_t i = wfirst + k;
    if (!origin.empty()) origin[i] = particles.wall[k];
    kind[i] = wall_kind(particles.wall_layer[k]);
    x[i] = particles.wall[k];
    v[i] = particles.wall_velocity[k];  // a moving body's particles stay put; walls use v as the surface's
    m[i] = rho0 * volume;
    rho[i] = rho0;
    if (!body.empty()) body[i] = particles.wall_body[k];
  }
  return particles;
}

// Each wall particle's unit normal out of the fluid (wall_normal), for the systems that read a
// wall's orientation (ISPH's wall rows, WCSPH's Riemann wall state). `appended`: what
// append_scene_particles returned, its walls the world's last particles.
template <int D>
void add_wall_normals(const SceneParticles<D>& appended, World<D>& world) {
  auto& normal = world.ensure(components::wall_normal);
  const std::size_t first = world.size() - appended.wall.size();
  for (std::size_t k = 0; k < appended.wall.size(); ++k) normal[first + k] = appended.wall_normal[k];
}

// For a scene with a `force` probe: each body particle's surface element, area times the unit normal into the
// body (zero elsewhere), for the pressure integral of solid_surface_force.hpp. `appended`: what
// append_scene_particles returned, its walls the world's last particles.
template <int D>
void add_surface_elements(const Scene& s, const SceneParticles<D>& appended, World<D>& world) {
  if (std::none_of(s.probes.begin(), s.probes.end(), [](const ProbeSpec& q) { return q.type == "force"; })) return;
  auto& element = world.ensure(components::surface_element);
  const std::size_t first = world.size() - appended.wall.size();
  for (std::size_t k = 0; k < appended.wall.size(); ++k)
    if (appended.wall_body[k] >= 0) element[first + k] = appended.wall_area[k] * appended.wall_normal[k];
}

}  // namespace ryushi
