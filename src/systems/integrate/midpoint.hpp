#pragma once
// Two-stage predictor-corrector (seed 002 eqs. 29-31) for position, velocity and density of
// fluid particles:
//   phi^{n+1/2} = phi^n + dt/2 F(phi^n)        (MidpointPredictor, keeps phi^n)
//   phi^{n+1}   = phi^n + dt   F(phi^{n+1/2})  (MidpointCorrector)
#include "ecs/io.hpp"
#include "systems/loops/for_each_particle.hpp"
#include "systems/neighbour/domain.hpp"

namespace ryushi {

template <int D>
class MidpointPredictor final : public System<D> {
 public:
  std::string name() const override { return "integrate_predictor"; }
  static constexpr auto io =
      Io{reads(components::acceleration, components::density_rate, components::kind, resources::dt),
         writes(components::position, components::velocity, components::density, components::position_start,
                components::velocity_start, components::density_start)};
  Access access() const override { return io.access(); }
  void run(SystemContext<D>& ctx) override {
    auto [a, drho, kind, dt, x, v, rho, x0, v0, rho0] = io.fetch(ctx);
    const double half = 0.5 * dt;
    for_each_of_kind(kind, kFluid, [&](std::size_t i) {
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
  static constexpr auto io = Io{
      reads(components::acceleration, components::density_rate, components::kind, components::position_start,
            components::velocity_start, components::density_start, resources::dt, domain_resource<D>),
      writes(components::position, components::velocity, components::density)};
  Access access() const override { return io.access(); }
  void run(SystemContext<D>& ctx) override {
    auto [a, drho, kind, x0, v0, rho0, dt, domain, x, v, rho] = io.fetch(ctx);
    const bool periodic = domain.any_periodic();
    for_each_of_kind(kind, kFluid, [&](std::size_t i) {
      x[i] = x0[i] + dt * v[i];  // v is v^{n+1/2} here
      v[i] = v0[i] + dt * a[i];
      rho[i] = rho0[i] + dt * drho[i];
      if (periodic) domain.wrap(x[i]);
    });
  }
};

}  // namespace ryushi
