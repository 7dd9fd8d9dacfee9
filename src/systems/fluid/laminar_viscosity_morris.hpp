#pragma once
// Laminar viscosity, Morris et al. (1997) form of the viscous term of seed 002 eq. 4:
//   dv_i/dt += sum_j m_j (mu_i + mu_j) / (rho_i rho_j) * x_ij . grad_i W_ij / (r^2 + 0.01 h^2) * v_ij
// Per-particle dynamic viscosity lives in the `viscosity` column, which exists only when the
// scene has a viscous material. Walls use the Adami ghost velocity (no-slip) or are skipped
// (free-slip) and take the fluid particle's viscosity.
#include "ecs/io.hpp"
#include "systems/fluid/for_each_fluid.hpp"
#include "systems/fluid/wcsph_parameters.hpp"
#include "systems/neighbour/neighbour_list.hpp"

namespace ryushi {

template <int D>
class LaminarViscosityMorris final : public System<D> {
 public:
  explicit LaminarViscosityMorris(const WcsphParameters<D>& p) : p_(p) {}
  std::string name() const override { return "laminar_viscosity_morris"; }
  static constexpr auto io =
      Io{reads(components::position, components::velocity, components::wall_velocity, components::density,
               components::mass, components::viscosity, components::kind, neighbours_resource),
         writes(components::acceleration)};
  Access access() const override { return io.access(); }
  void initialise(World<D>& world, Resources&) override {
    auto& mu = world.ensure(components::viscosity);
    std::fill(mu.begin(), mu.end(), p_.mu);
  }
  void run(SystemContext<D>& ctx) override {
    auto [x, v, vw, rho, m, mu, kind, nl, a] = io.fetch(ctx);
    const bool periodic = p_.domain.any_periodic();
    const double eta2 = 0.01 * p_.kernel.h() * p_.kernel.h();
    for_each_of_kind(kind, kFluid, [&](std::size_t i) {
      Vec<D> acc = Vec<D>::Zero();
      for (auto j : nl.of(i)) {
        bool wall = kind[j] == kWall;
        if (wall && !p_.wall_no_slip) continue;
        Vec<D> xij = periodic ? p_.domain.displacement(x[i], x[j]) : Vec<D>(x[i] - x[j]);
        double r2 = xij.squaredNorm();
        double F = p_.kernel.grad_factor(std::sqrt(r2));  // x_ij . grad W = r2 * F
        double muj = wall ? mu[i] : mu[j];
        Vec<D> vj = wall ? vw[j] : v[j];
        acc += m[j] * (mu[i] + muj) / (rho[i] * rho[j]) * (r2 * F) / (r2 + eta2) * (v[i] - vj);
      }
      a[i] += acc;
    });
  }

 private:
  WcsphParameters<D> p_;
};

}  // namespace ryushi
