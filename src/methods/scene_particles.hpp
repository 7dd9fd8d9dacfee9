#pragma once
// The particles a scene describes, before any method gives them mass or pressure: fluid blocks
// on the lattice (with their depth below the block's top, for hydrostatic starts) and wall
// containers (with each wall particle's layer, 1 = touching the fluid). Every method fills its
// world from this one description (and takes the domain and vectors from the scene here).
#include <vector>

#include "ecs/math.hpp"
#include "scene/scene.hpp"
#include "systems/neighbour/domain.hpp"

namespace ryushi {

template <int D>
struct SceneParticles {
  std::vector<Vec<D>> fluid;
  std::vector<double> depth;
  std::vector<Vec<D>> wall;
  std::vector<int> wall_layer;
};

template <int D>
SceneParticles<D> scene_particles(const Scene& scene);

template <int D>
Vec<D> scene_vector(const std::vector<double>& v) {
  Vec<D> x;
  for (int a = 0; a < D; ++a) x[a] = v[a];
  return x;
}

template <int D>
Domain<D> scene_domain(const Scene& s) {
  Domain<D> d;
  d.min = scene_vector<D>(s.domain_min);
  d.max = scene_vector<D>(s.domain_max);
  for (int a = 0; a < D; ++a) d.periodic[a] = s.periodic[a];
  return d;
}

}  // namespace ryushi
