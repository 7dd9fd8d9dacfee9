#pragma once
// Time step of an MPS run for the next step: the smallest of
//   Courant:  cfl * l0 / max(|u|max, sqrt(2 g H))   (BMG paper: Courant number <= 0.2)
//   viscous:  0.2 * l0^2 / nu                       (explicit viscosity)
// sqrt(2 g H) is the speed a collapsing column of height H reaches (1 m/s without gravity); it
// bounds dt while the fluid is still at rest, and it keeps each particle's predictor displacement below cfl *
// l0, which the neighbour list's skin relies on (MpsParameters::search_radius).
#include <algorithm>
#include <cmath>

#include "ecs/system.hpp"
#include "systems/fluid/for_each_fluid.hpp"
#include "systems/mps/mps_parameters.hpp"

namespace ryushi {

template <int D>
class MpsTimeStep final : public System<D> {
 public:
  explicit MpsTimeStep(const MpsParameters<D>& p) : p_(p) {}
  std::string name() const override { return "time_step_control"; }
  Access access() const override {
    return Access{}.read(components::velocity, components::kind).write(resources::dt);
  }
  void run(SystemContext<D>& ctx) override {
    auto v = ctx.read(components::velocity);
    auto kind = ctx.read(components::kind);
    ctx.write(resources::dt) = limit(max_fluid_speed<D>(kind, v));
  }
  double limit(double vmax) const {
    // One step's gravity increment g dt = u_ref * cfl l0 / (2H) is a small fraction of u_ref, so
    // |u*| dt stays below 1.25 cfl l0 and two particles close in by less than the 2.5 cfl l0 skin.
    double dt = p_.cfl * p_.spacing / std::max(vmax, p_.reference_speed);
    if (p_.nu > 0) dt = std::min(dt, 0.2 * p_.spacing * p_.spacing / p_.nu);
    return dt;
  }

 private:
  MpsParameters<D> p_;
};

}  // namespace ryushi
