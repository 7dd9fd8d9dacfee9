#pragma once
// Time step of the projection methods (MPS, ISPH) for the next step: no sound speed bounds it,
// only
//   CFL:      cfl * d / max(|v|max, u_ref)   (u_ref = sqrt(2 g H), the speed a collapsing column
//                                             of height H reaches: it bounds dt while the fluid is
//                                             still at rest; MPS)
//   or, with a body acceleration a and no u_ref (ISPH), the step whose predicted motion
//   dt (|v|max + a dt) is cfl * d: the particles' actual speed, plus what gravity adds within the
//   step (a fluid at rest then takes sqrt(cfl d / a), the time to fall cfl d from rest)
//   viscous:  the method's explicit-viscosity bound (MPS 0.2 l0^2 / nu, ISPH 0.125 h^2 / nu)
// The CFL bound keeps every particle's move per step below cfl * d, which the neighbour lists'
// skins rely on (MpsParameters / IsphParameters::search_radius).
#include <algorithm>
#include <cmath>

#include "ecs/io.hpp"
#include "systems/loops/for_each_particle.hpp"

namespace ryushi {

template <int D>
class VelocityTimeStep final : public System<D> {
 public:
  // viscous_limit in seconds; 0 when the fluid is inviscid.
  // wave_limit: a further bound in seconds (ISPH's particle-scale surface wave); 0 for none.
  VelocityTimeStep(double cfl, double spacing, double reference_speed, double viscous_limit,
                   double body_acceleration = 0, double wave_limit = 0)
      : cfl_(cfl),
        spacing_(spacing),
        reference_speed_(reference_speed),
        viscous_limit_(viscous_limit),
        body_acceleration_(body_acceleration),
        wave_limit_(wave_limit) {}
  std::string name() const override { return "time_step_control"; }
  static constexpr auto io = Io{reads(components::velocity, components::kind), writes(resources::dt)};
  Access access() const override { return io.access(); }
  void run(SystemContext<D>& ctx) override {
    auto [v, kind, dt] = io.fetch(ctx);
    dt = limit(max_fluid_speed<D>(kind, v));
  }
  double limit(double vmax) const {
    const double reach = cfl_ * spacing_;
    // The positive root of a dt^2 + vmax dt = reach, written without cancellation.
    double dt = body_acceleration_ > 0
                    ? 2 * reach / (vmax + std::sqrt(vmax * vmax + 4 * body_acceleration_ * reach))
                    : reach / std::max(vmax, reference_speed_);
    if (viscous_limit_ > 0) dt = std::min(dt, viscous_limit_);
    if (wave_limit_ > 0) dt = std::min(dt, wave_limit_);
    return dt;
  }

 private:
  double cfl_, spacing_, reference_speed_, viscous_limit_, body_acceleration_, wave_limit_;
};

}  // namespace ryushi
