#pragma once
// Two-stage predictor-corrector (seed 002 eqs. 29-31) for position, velocity and density of
// fluid particles:
//   phi^{n+1/2} = phi^n + dt/2 F(phi^n)        (MidpointPredictor, keeps phi^n)
//   phi^{n+1}   = phi^n + dt   F(phi^{n+1/2})  (MidpointCorrector)
#include "ecs/system.hpp"
#include "systems/fluid/for_each_fluid.hpp"
#include "systems/neighbour/domain.hpp"

namespace ryushi {

template <int D>
class MidpointPredictor final : public System<D> {
 public:
  std::string name() const override { return "integrate_predictor"; }
  Access access() const override {
    return Access{}
        .read(components::acceleration, components::density_rate, components::kind, resources::dt)
        .write(components::position, components::velocity, components::density,
               components::position_start, components::velocity_start, components::density_start);
  }
  void run(SystemContext<D>& ctx) override {
    const double half = 0.5 * ctx.read(resources::dt);
    auto a = ctx.read(components::acceleration);
    auto drho = ctx.read(components::density_rate);
    auto x = ctx.write(components::position);
    auto v = ctx.write(components::velocity);
    auto rho = ctx.write(components::density);
    auto x0 = ctx.write(components::position_start);
    auto v0 = ctx.write(components::velocity_start);
    auto rho0 = ctx.write(components::density_start);
    for_each_of_kind(ctx.read(components::kind), kFluid, [&](std::size_t i) {
      x0[i] = x[i];
      v0[i] = v[i];
      rho0[i] = rho[i];
      x[i] += half * v[i];
      v[i] += half * a[i];
      rho[i] += half * drho[i];
    });
  }
};

template <int D>
class MidpointCorrector final : public System<D> {
 public:
  std::string name() const override { return "integrate_corrector"; }
  Access access() const override {
    return Access{}
        .read(components::acceleration, components::density_rate, components::kind,
              components::position_start, components::velocity_start, components::density_start,
              resources::dt, domain_resource<D>)
        .write(components::position, components::velocity, components::density);
  }
  void run(SystemContext<D>& ctx) override {
    const double dt = ctx.read(resources::dt);
    const auto& domain = ctx.read(domain_resource<D>);
    const bool periodic = domain.any_periodic();
    auto a = ctx.read(components::acceleration);
    auto drho = ctx.read(components::density_rate);
    auto x0 = ctx.read(components::position_start);
    auto v0 = ctx.read(components::velocity_start);
    auto rho0 = ctx.read(components::density_start);
    auto x = ctx.write(components::position);
    auto v = ctx.write(components::velocity);
    auto rho = ctx.write(components::density);
    for_each_of_kind(ctx.read(components::kind), kFluid, [&](std::size_t i) {
      x[i] = x0[i] + dt * v[i];  // v is v^{n+1/2} here
      v[i] = v0[i] + dt * a[i];
      rho[i] = rho0[i] + dt * drho[i];
      if (periodic) domain.wrap(x[i]);
    });
  }
};

}  // namespace ryushi
