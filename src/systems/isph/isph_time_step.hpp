#pragma once
// Time step of an ISPH run for the next step: no sound speed bounds it, only
//   CFL:      cfl * d / max(|v|max, sqrt(2 g H))   (the reference speed bounds the first steps)
//   viscous:  0.125 h^2 / nu
// The CFL bound keeps every particle's move per step below cfl * d, which the neighbour list's
// skin relies on (IsphParameters::search_radius).
#include <algorithm>
#include <cmath>

#include "ecs/system.hpp"
#include "systems/fluid/for_each_fluid.hpp"
#include "systems/isph/isph_parameters.hpp"

namespace ryushi {

template <int D>
class IsphTimeStep final : public System<D> {
 public:
  explicit IsphTimeStep(const IsphParameters<D>& p) : p_(p) {}
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
    double dt = p_.cfl * p_.spacing / std::max(vmax, p_.reference_speed);
    if (p_.nu > 0) dt = std::min(dt, 0.125 * p_.kernel.h() * p_.kernel.h() / p_.nu);
    return dt;
  }

 private:
  IsphParameters<D> p_;
};

}  // namespace ryushi
