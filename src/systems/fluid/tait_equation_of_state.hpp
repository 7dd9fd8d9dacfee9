#pragma once
// Tait equation of state p = B((rho/rho0)^gamma - 1) for fluid particles (seed 002 eq. 3).
#include "ecs/io.hpp"
#include "systems/fluid/wcsph_parameters.hpp"
#include "systems/loops/for_each_particle.hpp"

namespace ryushi {

template <int D>
class TaitEquationOfState final : public System<D> {
 public:
  explicit TaitEquationOfState(const WcsphParameters<D>& p) : p_(p) {}
  std::string name() const override { return "equation_of_state"; }
  static constexpr auto io = Io{reads(components::density, components::kind), writes(components::pressure)};
  Access access() const override { return io.access(); }
  void run(SystemContext<D>& ctx) override {
    auto [rho, kind, p] = io.fetch(ctx);
    for_each_of_kind(kind, kFluid, [&](std::size_t i) { p[i] = p_.pressure(rho[i]); });
  }

 private:
  WcsphParameters<D> p_;
};

}  // namespace ryushi
