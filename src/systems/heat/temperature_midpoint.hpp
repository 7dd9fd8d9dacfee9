#pragma once
// The temperature's part of the two-stage midpoint integrator (integrate/midpoint.hpp), its own
// systems so that a scene without heat does not carry the columns:
//   T^{n+1/2} = T^n + dt/2 dT/dt(n)        (TemperaturePredictor, keeps T^n)
//   T^{n+1}   = T^n + dt   dT/dt(n+1/2)    (TemperatureCorrector)
// Fluid particles only: walls keep the temperature the scene gave them.
#include "ecs/io.hpp"
#include "systems/heat/heat_parameters.hpp"
#include "systems/loops/for_each_particle.hpp"

namespace ryushi {

template <int D>
class TemperaturePredictor final : public System<D> {
 public:
  std::string name() const override { return "temperature_predictor"; }
  static constexpr auto io = Io{reads(components::temperature_rate, components::kind, resources::dt),
                                writes(components::temperature, components::temperature_start)};
  Access access() const override { return io.access(); }
  void run(SystemContext<D>& ctx) override {
    auto [rate, kind, dt, T, T0] = io.fetch(ctx);
    const double half = 0.5 * dt;
    for_each_of_kind(kind, kFluid, [&](std::size_t i) {
      T0[i] = T[i];
      T[i] += half * rate[i];
    });
  }
};

template <int D>
class TemperatureCorrector final : public System<D> {
 public:
  std::string name() const override { return "temperature_corrector"; }
  static constexpr auto io =
      Io{reads(components::temperature_rate, components::temperature_start, components::kind, resources::dt),
         writes(components::temperature)};
  Access access() const override { return io.access(); }
  void run(SystemContext<D>& ctx) override {
    auto [rate, T0, kind, dt, T] = io.fetch(ctx);
    for_each_of_kind(kind, kFluid, [&](std::size_t i) { T[i] = T0[i] + dt * rate[i]; });
  }
};

}  // namespace ryushi
