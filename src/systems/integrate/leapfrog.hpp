#pragma once
// Leapfrog integration (seed 001 eqs. 15-17): one force evaluation per step, where the midpoint
// integrator (midpoint.hpp) takes two. Velocity and density live on the half steps
// (velocity_start, density_start hold v^{n-1/2}, rho^{n-1/2}); the forces at t^n are evaluated
// with the full-step values predicted from them (eq. 16), and after the forces
//   v^{n+1/2} = v^{n-1/2} + (dt_{n-1} + dt_n)/2 a^n       (eq. 17; the first step: v^0 + dt/2 a^0, eq. 15)
//   x^{n+1}   = x^n + dt_n v^{n+1/2}
//   v^{n+1}   = v^{n+1/2} + dt_n/2 a^n                    (eq. 16: predicted for the next forces and output)
// and the same for density (and temperature, when the scene has heat). With a constant step the
// kick is the textbook dt a^n; with a varying one it is the average of the two half steps around
// t^n, which keeps the scheme second order. Position and velocity of wall particles are the
// walls' own (not integrated).
#include "ecs/io.hpp"
#include "systems/heat/heat_parameters.hpp"
#include "systems/loops/for_each_particle.hpp"
#include "systems/neighbour/domain.hpp"

namespace ryushi {

template <int D>
class LeapfrogIntegrator final : public System<D> {
 public:
  explicit LeapfrogIntegrator(bool heat) : heat_(heat) {}
  std::string name() const override { return "integrate_leapfrog"; }
  auto io() const {
    return Io{reads(components::acceleration, components::density_rate, components::kind, resources::dt,
                    domain_resource<D>),
              writes(components::position, components::velocity, components::density,
                     components::velocity_start, components::density_start),
              optional(heat_, reads(components::temperature_rate),
                       writes(components::temperature, components::temperature_start))};
  }
  Access access() const override { return io().access(); }
  void run(SystemContext<D>& ctx) override {
    // Without heat the temperature spans are empty.
    auto [a, drho, kind, dt, domain, x, v, rho, v_half, rho_half, dT, T, T_half] = io().fetch(ctx);
    const double kick = 0.5 * ((started_ ? previous_dt_ : 0.0) + dt);
    const bool periodic = domain.any_periodic(), first = !started_;
    for_each_of_kind(kind, kFluid, [&](std::size_t i) {
      // The previous half step's values; at the first step the initial ones (eq. 15).
      Vec<D> vh = (first ? v[i] : v_half[i]) + kick * a[i];
      const double rh = (first ? rho[i] : rho_half[i]) + kick * drho[i];
      x[i] += dt * vh;
      if (periodic) domain.wrap(x[i]);
      v_half[i] = vh;
      rho_half[i] = rh;
      v[i] = vh + 0.5 * dt * a[i];
      rho[i] = rh + 0.5 * dt * drho[i];
      if (!T.empty()) {
        const double th = (first ? T[i] : T_half[i]) + kick * dT[i];
        T_half[i] = th;
        T[i] = th + 0.5 * dt * dT[i];
      }
    });
    started_ = true;
    previous_dt_ = dt;
  }
  // The half-step values are columns; what else a resumed run needs is whether the first
  // step is behind it and that step's length.
  std::vector<double> checkpoint_state(const World<D>&, const Resources&) const override {
    return {started_ ? 1.0 : 0.0, previous_dt_};
  }
  void restore_state(const World<D>&, Resources&, std::span<const double> state) override {
    if (state.size() != 2) return;
    started_ = state[0] == 1.0;
    previous_dt_ = state[1];
  }

 private:
  bool heat_;
  bool started_ = false;
  double previous_dt_ = 0;
};

}  // namespace ryushi
