#pragma once
// The fluid's push on the elastic solid: the reaction to the pair forces the fluid particles felt
// from the solid's particles in wcsph_pair_forces.hpp (there an elastic particle is a moving wall
// particle with Adami's fluid-side pressure and ghost velocity), so that momentum is exchanged
// pair by pair: for an elastic particle j and each fluid neighbour i,
//   F_ij = -m_i m_j [(p_i + p_j)/(rho_i rho_j) + Pi_ij] grad_i W_ij
//          + m_i m_j 2 mu_i / (rho_i rho_j) (r^2 F_ij / (r^2 + 0.01 h^2)) (v_i - v~_j)   (no-slip viscosity)
// is the force on i, and j receives -sum_i F_ij, divided here by its solid mass rho0_s d^D.
#include <cmath>

#include "ecs/io.hpp"
#include "systems/elastic/elastic_parameters.hpp"
#include "systems/fluid/wcsph_parameters.hpp"
#include "systems/loops/for_each_particle.hpp"
#include "systems/neighbour/neighbour_list.hpp"

namespace ryushi {

template <int D>
class FluidOnSolid final : public System<D> {
 public:
  FluidOnSolid(const WcsphParameters<D>& fluid, double volume) : p_(fluid), volume_(volume) {}
  std::string name() const override { return "fluid_on_solid"; }
  // The viscous force on the solid is the no-slip wall's only (slip walls feel none).
  bool viscous() const { return p_.viscous() && p_.wall_no_slip; }
  auto io() const {
    return Io{reads(components::position, components::velocity, components::density, components::pressure,
                    components::mass, components::kind, components::solid_rest_density, neighbours_resource),
              writes(components::fluid_force),
              optional(viscous(), reads(components::viscosity, components::wall_velocity))};
  }
  Access access() const override { return io().access(); }
  void run(SystemContext<D>& ctx) override {
    auto [x, v, rho, p, m, kind, rho0, nl, out, mu, ghost] = io().fetch(ctx);
    const bool viscous = this->viscous();
    const double support2 = p_.kernel.support() * p_.kernel.support(),
                 eta2 = 0.01 * p_.kernel.h() * p_.kernel.h();
    for_each_of_kind(kind, kElastic, [&](std::size_t j) {
      Vec<D> force = Vec<D>::Zero();  // on the fluid, from j
      for (auto i : nl.of(j)) {
        if (kind[i] != kFluid) continue;
        const Vec<D> xij = p_.domain.displacement(x[i], x[j]);
        const double r2 = xij.squaredNorm();
        if (r2 >= support2) continue;
        const double F = p_.kernel.grad_factor(std::sqrt(r2));
        const double inv_rho_ij = 1.0 / (rho[i] * rho[j]), inv_r2_eta2 = 1.0 / (r2 + eta2);
        const double approach =  // read by the Riemann dissipation only
            p_.riemann ? WcsphParameters<D>::riemann_approach(v[i] - v[j], xij, std::sqrt(r2)) : 0.0;
        const double coeff = p_.pair_pressure_coefficient(p[i], p[j], rho[i], rho[j], inv_rho_ij,
                                                          (v[i] - v[j]).dot(xij), inv_r2_eta2, approach);
        force -= m[i] * m[j] * coeff * F * xij;
        if (viscous)
          force += (m[i] * m[j] * 2.0 * mu[i] * inv_rho_ij * r2 * F * inv_r2_eta2) * (v[i] - ghost[j]);
      }
      out[j] = -force / (rho0[j] * volume_);
    });
  }

 private:
  WcsphParameters<D> p_;
  double volume_;
};

}  // namespace ryushi
