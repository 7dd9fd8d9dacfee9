#pragma once
// Laminar viscosity, Morris et al. (1997) form of the viscous term of seed 002 eq. 4, a pair term
// (systems/loops/pair_loop.hpp):
//   dv_i/dt += sum_j m_j (mu_i + mu_j) / (rho_i rho_j) * x_ij . grad_i W_ij / (r^2 + 0.01 h^2) * v_ij
// Per-particle dynamic viscosity lives in the `viscosity` column, which exists only when the
// scene has a viscous material. Walls use the Adami ghost velocity (no-slip) or are skipped
// (free-slip) and take the fluid particle's viscosity. Stored after the pressure term: it adds.
#include <cstdint>
#include <span>

#include "ecs/component.hpp"
#include "systems/loops/pair_loop.hpp"

namespace ryushi {

template <int D>
struct LaminarViscosityMorris {
  using Sum = Vec<D>;
  std::span<const Vec<D>> v, wall_velocity;
  std::span<const double> mu, inv_rho, m;
  std::span<const std::int32_t> kind;
  std::span<Vec<D>> acceleration;
  double eta2;  // 0.01 h^2
  bool no_slip;

  Sum zero() const { return Sum::Zero(); }
  void operator()(const PairGeometry<D>& g, PairSides s, Sum& to_i, Sum& to_j) const {
    const std::uint32_t i = g.i, j = g.j;
    const bool fluid_i = kind[i] == kFluid, fluid_j = kind[j] == kFluid;
    const double k = inv_rho[i] * inv_rho[j] * (g.r2 * g.F) * (1.0 / (g.r2 + eta2));
    if (fluid_i && fluid_j) {  // symmetric factor, v_ij changes sign
      const double kk = (mu[i] + mu[j]) * k;
      if (s.i) to_i += (m[j] * kk) * g.vij;
      if (s.j) to_j -= (m[i] * kk) * g.vij;
    } else if (no_slip) {  // the fluid side sees the wall's ghost velocity and its own mu
      if (fluid_i) {
        if (s.i) to_i += (m[j] * 2.0 * mu[i] * k) * (v[i] - wall_velocity[j]);
      } else if (s.j) {
        to_j += (m[i] * 2.0 * mu[j] * k) * (v[j] - wall_velocity[i]);
      }
    }
  }
  void store(std::size_t i, const Sum& sum) const { acceleration[i] += sum; }
};

}  // namespace ryushi
