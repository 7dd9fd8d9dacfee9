#pragma once
// WCSPH pair forces: one pair loop (systems/loops/pair_loop.hpp) over each fluid particle's
// neighbours that evaluates every pair term of the stage on the same pair geometry:
//   continuity + delta-SPH diffusion   (continuity_delta_sph.hpp, seed 002 eqs. 17-19)
//   pressure + artificial viscosity    (momentum.hpp, seed 002 eqs. 22-24)
//   laminar viscosity, Morris 1997     (laminar_viscosity_morris.hpp, viscous scenes only)
// The loop visits each pair once when the particle order allows it (1.5x faster measured),
// else gathers. The density gradient stays a separate pass because the diffusion term needs
// its neighbours' values.
#include <algorithm>
#include <vector>

#include "ecs/io.hpp"
#include "systems/fluid/continuity_delta_sph.hpp"
#include "systems/fluid/laminar_viscosity_morris.hpp"
#include "systems/fluid/momentum.hpp"
#include "systems/fluid/wcsph_parameters.hpp"
#include "systems/loops/for_each_particle.hpp"
#include "systems/loops/pair_loop.hpp"
#include "systems/neighbour/neighbour_list.hpp"

namespace ryushi {

template <int D>
class WcsphPairForces final : public System<D> {
 public:
  explicit WcsphPairForces(const WcsphParameters<D>& p) : p_(p), loop_(p.kernel, p.domain) {}
  std::string name() const override { return "wcsph_pair_forces"; }
  auto io() const {
    return Io{reads(components::position, components::velocity, components::density, components::pressure,
                    components::mass, components::kind, neighbours_resource),
              writes(components::density_rate, components::acceleration),
              optional(p_.density_diffusion(), reads(components::density_gradient)),
              optional(p_.riemann, reads(components::wall_normal)),
              optional(p_.viscous(), reads(components::viscosity, components::wall_velocity))};
  }
  Access access() const override { return io().access(); }
  void initialise(World<D>& world, Resources&) override {
    if (!p_.viscous() || p_.variable_viscosity) return;  // a rheology model writes it each stage
    auto& mu = world.ensure(components::viscosity);
    std::fill(mu.begin(), mu.end(), p_.mu);
  }
  void run(SystemContext<D>& ctx) override {
    auto [x, v, rho, p, m, kind, nl, drho, a, grad, normal, mu, vw] = io().fetch(ctx);
    particle_volumes(m, rho, volume_);
    inverse_densities(rho, inv_rho_);
    const typename PairLoop<D>::Inputs in{x, v, kind, kFluid, x.size()};
    const double h = p_.kernel.h();
    const PressureArtificialViscosity<D> pressure{p_, p, rho, inv_rho_, m, kind, normal, a};
    with_flag(p_.density_diffusion(), [&](auto Diffusion) {
      const ContinuityDeltaSph<D, Diffusion.value> continuity{
          volume_, rho, grad, kind, drho, p_.riemann ? p_.c0 : p_.delta * h * p_.c0, p_.riemann};
      if (p_.viscous())
        loop_.run(in, nl, continuity, pressure,
                  LaminarViscosityMorris<D>{v, vw, mu, inv_rho_, m, kind, a, 0.01 * h * h, p_.wall_no_slip});
      else
        loop_.run(in, nl, continuity, pressure);
    });
  }

  // Test hook: both strategies of the loop are checked.
  void set_pairs_once(PairsOnce mode) { loop_.set_strategy(mode); }

 private:
  WcsphParameters<D> p_;
  PairLoop<D> loop_;
  std::vector<double> volume_, inv_rho_;
};

}  // namespace ryushi
