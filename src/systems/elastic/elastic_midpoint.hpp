#pragma once
// The elastic solid's time integration, in the two stages of the fluid's midpoint step: velocity
// Verlet, which is symplectic (an undamped elastic body keeps its energy; the midpoint rule's
// amplification |1 + i w dt - (w dt)^2/2| > 1 makes every undamped oscillation grow, measured: an
// oscillating plate without artificial viscosity blew up within 0.15 s):
//   after the first stage's forces a^n:    v^{n+1/2} = v^n + dt/2 a^n,  x^{n+1} = x^n + dt v^{n+1/2}
//   after the second stage's a^{n+1}:      v^{n+1}   = v^{n+1/2} + dt/2 a^{n+1} + dt f
// The second stage therefore sees the solid at t^{n+1} where the fluid is at t^{n+1/2}. The
// fluid's push f (force / mass, fluid_on_solid.hpp) enters once, from the second stage, times dt:
// exactly the impulse the midpoint fluid takes from the same pairs (dt times its second-stage
// force), so the momentum they exchange balances to round-off (with f in both kicks it missed by
// 2e-4 of the total in a water-on-block impact).
// Clamped particles keep their place and zero velocity. The step ends with the displacement from
// the rest position (output). The stress follows from the positions (total_lagrangian_elastic.hpp).
#include "ecs/system.hpp"
#include "systems/elastic/elastic_parameters.hpp"
#include "systems/fluid/for_each_fluid.hpp"
#include "systems/neighbour/domain.hpp"

namespace ryushi {

template <int D>
class ElasticPredictor final : public System<D> {
 public:
  std::string name() const override { return "elastic_kick_drift"; }
  Access access() const override {
    return Access{}
        .read(components::acceleration, components::kind, components::clamped, resources::dt,
              domain_resource<D>)
        .write(components::position, components::velocity);
  }
  void run(SystemContext<D>& ctx) override {
    const double dt = ctx.read(resources::dt);
    const auto& domain = ctx.read(domain_resource<D>);
    auto a = ctx.read(components::acceleration);
    auto clamped = ctx.read(components::clamped);
    auto x = ctx.write(components::position);
    auto v = ctx.write(components::velocity);
    for_each_of_kind(ctx.read(components::kind), kElastic, [&](std::size_t i) {
      if (clamped[i]) return;
      v[i] += 0.5 * dt * a[i];
      x[i] += dt * v[i];
      if (domain.any_periodic()) domain.wrap(x[i]);
    });
  }
};

template <int D>
class ElasticCorrector final : public System<D> {
 public:
  explicit ElasticCorrector(bool fluid) : fluid_(fluid) {}
  std::string name() const override { return "elastic_kick"; }
  Access access() const override {
    Access a;
    a.read(components::acceleration, components::kind, components::clamped, components::rest_position,
           resources::dt, domain_resource<D>)
        .write(components::velocity, components::displacement, components::position);
    if (fluid_) a.read(components::fluid_force);
    return a;
  }
  void run(SystemContext<D>& ctx) override {
    const double dt = ctx.read(resources::dt);
    const auto& domain = ctx.read(domain_resource<D>);
    auto a = ctx.read(components::acceleration);
    auto clamped = ctx.read(components::clamped);
    auto rest = ctx.read(components::rest_position);
    auto x = ctx.write(components::position);
    auto v = ctx.write(components::velocity);
    auto u = ctx.write(components::displacement);
    std::span<const Vec<D>> f;
    if (fluid_) f = ctx.read(components::fluid_force);
    for_each_of_kind(ctx.read(components::kind), kElastic, [&](std::size_t i) {
      if (!clamped[i]) v[i] += 0.5 * dt * a[i] + (f.empty() ? Vec<D>::Zero() : Vec<D>(dt * f[i]));
      u[i] = domain.displacement(x[i], rest[i]);
    });
  }

 private:
  bool fluid_;
};

}  // namespace ryushi
