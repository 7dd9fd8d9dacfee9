#pragma once
// The particles of a scene's [[elastic]] bodies (systems/elastic/elastic_parameters.hpp), appended
// after the fluid and walls: on each body's lattice min + (k + 1/2) d, at rest density and zero
// stress, with their initial velocity; to the fluid they are walls (fluid mass rho0_f d^D, fluid
// density), their own state in the solid columns.
#include <array>
#include <cmath>

#include "ecs/lattice.hpp"
#include "ecs/world.hpp"
#include "methods/method_context.hpp"
#include "scene/block_fields.hpp"
#include "scene/scene.hpp"
#include "systems/elastic/elastic_parameters.hpp"

namespace ryushi {

template <int D>
void add_elastic_bodies(const Scene& s, double fluid_rho0, World<D>& world) {
  const double d = s.spacing, volume = std::pow(d, D);
  for (std::size_t b = 0; b < s.elastic.size(); ++b) {
    const ElasticSpec& e = s.elastic[b];
    const BlockFields fields(e.initial, b, "[[elastic]] #" + std::to_string(b));
    std::vector<Vec<D>> points;
    std::array<long, D> from{}, to{};
    for (int a = 0; a < D; ++a) to[a] = std::lround((e.max[a] - e.min[a]) / d);
    for_each_lattice_point<D>(scene_vector<D>(e.min), d, from, to,
                              [&](const Vec<D>& q) { points.push_back(q); });
    const std::size_t first = world.append(points.size(), kElastic);
    auto& x = world.ensure(components::position);
    auto& v = world.ensure(components::velocity);
    auto& m = world.ensure(components::mass);
    auto& rho = world.ensure(components::density);
    auto& rho_s = world.ensure(components::solid_density);
    auto& rest_rho = world.ensure(components::solid_rest_density);
    auto& K = world.ensure(components::bulk_modulus);
    auto& G = world.ensure(components::shear_modulus);
    auto& rest = world.ensure(components::rest_position);
    auto& clamped = world.ensure(components::clamped);
    auto& body = world.ensure(components::elastic_body);
    for (std::size_t k = 0; k < points.size(); ++k) {
      const std::size_t i = first + k;
      x[i] = rest[i] = points[k];
      for (int a = 0; a < D; ++a) v[i][a] = fields.velocity(a, points[k].data(), D);
      m[i] = fluid_rho0 * volume;
      rho[i] = fluid_rho0;
      rho_s[i] = rest_rho[i] = e.density;
      K[i] = e.bulk_modulus, G[i] = e.shear_modulus;
      bool held = !e.clamp_min.empty();
      for (int a = 0; a < D && held; ++a)
        held = points[k][a] >= e.clamp_min[a] && points[k][a] <= e.clamp_max[a];
      clamped[i] = held ? 1 : 0;
      body[i] = static_cast<std::int32_t>(b);
    }
  }
  auto& kind = world.column(components::kind);
  auto& body = world.ensure(components::elastic_body);
  for (std::size_t i = 0; i < world.size(); ++i)
    if (kind[i] != kElastic) body[i] = -1;
}

// step_fraction: the step rule's fraction of h / c (the CFL number, or seed 001's 0.1).
template <int D>
ElasticParameters<D> elastic_parameters(const Scene& s, const Kernel<D>& kernel, const Domain<D>& domain,
                                        double step_fraction) {
  ElasticParameters<D> p;
  p.kernel = kernel;
  p.domain = domain;
  p.gravity = scene_vector<D>(s.gravity);
  p.spacing = s.spacing;
  p.alpha = s.method_params.number("solid_artificial_viscosity");
  p.beta = s.method_params.number("solid_artificial_viscosity_quadratic");
  p.artificial_stress = s.method_params.number("solid_artificial_stress");
  p.seed_walls = s.method_params.text("solid_walls") == "seed";
  for (auto& e : s.elastic) p.max_sound_speed = std::max(p.max_sound_speed, e.sound_speed());
  p.fluid = !s.fluid.empty() || !s.imports.empty();
  p.max_substeps = static_cast<int>(s.method_params.integer("solid_substeps"));
  if (p.max_sound_speed > 0) p.substep_limit = step_fraction * kernel.h() / p.max_sound_speed;
  return p;
}

}  // namespace ryushi
