#pragma once
// The temperature's part of the two-stage midpoint integrator (integrate/midpoint.hpp), its own
// systems so that a scene without heat does not carry the columns:
//   T^{n+1/2} = T^n + dt/2 dT/dt(n)        (TemperaturePredictor, keeps T^n)
//   T^{n+1}   = T^n + dt   dT/dt(n+1/2)    (TemperatureCorrector)
// Fluid particles only: walls keep the temperature the scene gave them.
#include "ecs/system.hpp"
#include "systems/fluid/for_each_fluid.hpp"
#include "systems/heat/heat_parameters.hpp"

namespace ryushi {

template <int D>
class TemperaturePredictor final : public System<D> {
 public:
  std::string name() const override { return "temperature_predictor"; }
  Access access() const override {
    return Access{}
        .read(components::temperature_rate, components::kind, resources::dt)
        .write(components::temperature, components::temperature_start);
  }
  void run(SystemContext<D>& ctx) override {
    const double half = 0.5 * ctx.read(resources::dt);
    auto rate = ctx.read(components::temperature_rate);
    auto T = ctx.write(components::temperature);
    auto T0 = ctx.write(components::temperature_start);
    for_each_of_kind(ctx.read(components::kind), kFluid, [&](std::size_t i) {
      T0[i] = T[i];
      T[i] += half * rate[i];
    });
  }
};

template <int D>
class TemperatureCorrector final : public System<D> {
 public:
  std::string name() const override { return "temperature_corrector"; }
  Access access() const override {
    return Access{}
        .read(components::temperature_rate, components::temperature_start, components::kind, resources::dt)
        .write(components::temperature);
  }
  void run(SystemContext<D>& ctx) override {
    const double dt = ctx.read(resources::dt);
    auto rate = ctx.read(components::temperature_rate);
    auto T0 = ctx.read(components::temperature_start);
    auto T = ctx.write(components::temperature);
    for_each_of_kind(ctx.read(components::kind), kFluid, [&](std::size_t i) { T[i] = T0[i] + dt * rate[i]; });
  }
};

}  // namespace ryushi
