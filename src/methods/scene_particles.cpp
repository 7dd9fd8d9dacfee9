#include "methods/scene_particles.hpp"

#include <algorithm>
#include <cmath>

#include "ecs/lattice.hpp"

namespace ryushi {

template <int D>
SceneParticles<D> scene_particles(const Scene& s) {
  const double d = s.spacing;
  SceneParticles<D> out;
  for (auto& b : s.fluid) {
    Vec<D> lo = scene_vector<D>(b.min);
    std::array<long, D> from{}, to{};
    for (int a = 0; a < D; ++a) to[a] = std::lround((b.max[a] - b.min[a]) / d);
    double top = b.min[D - 1] + to[D - 1] * d;
    for_each_lattice_point<D>(lo, d, from, to, [&](const Vec<D>& x) {
      out.fluid.push_back(x);
      out.depth.push_back(top - x[D - 1]);
    });
  }
  for (auto& w : s.walls) {
    Vec<D> lo = scene_vector<D>(w.min), hi = scene_vector<D>(w.max);
    std::array<long, D> from{}, to{};
    for (int a = 0; a < D; ++a) {
      from[a] = -w.layers;
      to[a] = std::lround((w.max[a] - w.min[a]) / d) + ((a == D - 1 && w.open_top) ? 0 : w.layers);
    }
    for_each_lattice_point<D>(lo, d, from, to, [&](const Vec<D>& q) {
      double outside = 0;  // how far the point lies outside the box, (layer - 1/2) d
      for (int a = 0; a < D; ++a) outside = std::max({outside, lo[a] - q[a], q[a] - hi[a]});
      if (outside <= 0) return;
      out.wall.push_back(q);
      out.wall_layer.push_back(static_cast<int>(std::lround(outside / d + 0.5)));
    });
  }
  return out;
}

template SceneParticles<2> scene_particles<2>(const Scene&);
template SceneParticles<3> scene_particles<3>(const Scene&);

}  // namespace ryushi
