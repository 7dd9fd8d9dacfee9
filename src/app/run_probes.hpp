#pragma once
// The scene's [[probe]] entries as the probes sample them, once the particles exist: a
// wall_pressure sensor off any wall or facing into it is bad input (exit 2), named at its key.
#include <cmath>
#include <vector>

#include "scene/scene.hpp"
#include "systems/probes/probes.hpp"

namespace ryushi {

template <int D>
std::vector<Probe> probes_of(const Scene& scene, const World<D>& world, const MethodContext<D>& context) {
  std::vector<Probe> probes;
  for (const auto& q : scene.probes) {
    // A force coefficient: F over the dynamic pressure of the reference speed on the reference
    // length (2D, per unit depth) or its square (3D).
    const double dynamic = 0.5 * context.rho0 * q.reference_speed * q.reference_speed *
                           std::pow(q.reference_length, context.dimension - 1);
    probes.push_back(
        Probe{q.type, q.position, q.solid, q.axis, q.normal, q.diameter, dynamic > 0 ? 1.0 / dynamic : 1.0});
  }
  const auto problems = wall_sensor_problems(probes, world, context);
  for (std::size_t k = 0; k < problems.size(); ++k)
    if (!problems[k].text.empty())
      throw SceneError(
          (problems[k].about_position ? scene.probes[k].position_where : scene.probes[k].normal_where) +
          ": [[probe]] '" + scene.probes[k].name + "': " + problems[k].text);
  return probes;
}

}  // namespace ryushi
