#pragma once
// Probes sampled between steps into probes.csv:
//   pressure      Shepard-normalised kernel interpolation of fluid pressure at a point:
//                 p(x) = sum_j p_j V_j W(x - x_j) / sum_j V_j W(x - x_j)
//   surge_front   max over fluid particles of x (first axis) + d/2, the particle's outer edge,
//                 so that it equals the block width at t = 0
//   water_height  max over fluid particles within d of the probe horizontally of the vertical
//                 coordinate, + d/2
#include <vector>

#include "ecs/world.hpp"
#include "scene/scene.hpp"
#include "systems/kernels/kernel.hpp"

namespace ryushi {

template <int D>
std::vector<double> sample_probes(const std::vector<ProbeSpec>& probes, const World<D>& world,
                                  const Kernel<D>& kernel, double spacing);

}  // namespace ryushi
