#pragma once
// The weakly compressible SPH method as a recipe: which systems, in which order, with which
// options from the scene. Also fills the world with the scene's fluid blocks and walls.
#include <vector>

#include "ecs/system.hpp"
#include "scene/scene.hpp"
#include "systems/fluid/wcsph_parameters.hpp"

namespace ryushi {

template <int D>
WcsphParameters<D> wcsph_parameters(const Scene& scene);

// Appends fluid blocks and wall containers to the world (positions, kind, mass, density,
// pressure; velocity zero).
template <int D>
void populate_world(const Scene& scene, const WcsphParameters<D>& p, World<D>& world);

// neighbour search, then two stages of [wall BC, density gradient, continuity, momentum,
// viscosity] around the predictor and corrector, the equation of state after each, and the
// time-step control. (build_method appends the scene's [[systems]].)
template <int D>
std::vector<SystemPtr<D>> wcsph_pipeline(const Scene& scene, const WcsphParameters<D>& p);

}  // namespace ryushi
