#pragma once
// Momentum equation for weakly compressible SPH (seed 002 eq. 22 with sigma = -p I), a pair term
// (systems/loops/pair_loop.hpp):
//   dv_i/dt = g - sum_j m_j [ (p_i + p_j)/(rho_i rho_j) + Pi_ij ] grad_i W_ij
// with Monaghan's artificial viscosity Pi_ij (seed 002 eqs. 23-24) or Zhang, Hu & Adams's Riemann
// dissipation (WcsphParameters::pair_pressure_coefficient). Walls contribute their Adami pressure and their
// own velocity. The coefficient is symmetric in (i, j) and the kernel gradient changes sign, so j gets the
// opposite push weighted by m_i.
#include <cstdint>
#include <span>

#include "ecs/component.hpp"
#include "systems/fluid/wcsph_parameters.hpp"
#include "systems/loops/pair_loop.hpp"

namespace ryushi {

template <int D>
struct PressureArtificialViscosity {
  using Sum = Vec<D>;
  WcsphParameters<D> p;  // a copy: the pair loop keeps its terms where row sums cannot alias them
  std::span<const double> pressure, rho, inv_rho, m;
  std::span<const std::int32_t> kind;   // riemann: a wall pair's right state is the fluid's mirror
  std::span<const Vec<D>> wall_normal;  // riemann only: out of the fluid
  std::span<Vec<D>> acceleration;

  struct Row {  // row i's values, read once per row
    double pressure, rho, inv_rho, m;
    bool wall;  // a pairs-once visit may come from a wall row
  };
  Row row(std::size_t i) const { return {pressure[i], rho[i], inv_rho[i], m[i], kind[i] == kWall}; }

  double approach(const PairGeometry<D>& g, const Row& ri) const {
    if (!p.riemann) return 0;
    if (ri.wall) return WcsphParameters<D>::riemann_wall_approach(-g.vij, -g.xij, g.r, wall_normal[g.i]);
    if (kind[g.j] == kWall)
      return WcsphParameters<D>::riemann_wall_approach(g.vij, g.xij, g.r, wall_normal[g.j]);
    return WcsphParameters<D>::riemann_approach(g.vij, g.xij, g.r);
  }

  Sum zero() const { return Sum::Zero(); }
  void operator()(const PairGeometry<D>& g, PairSides s, const Row& ri, Sum& to_i, Sum& to_j) const {
    // Divisions are the costly part of a pair: 1/rho comes per particle, 1/(r^2 + eta^2) is
    // shared with the laminar term (the compiler keeps one).
    const double h = p.kernel.h();
    const double inv_rho_ij = ri.inv_rho * inv_rho[g.j];
    const double inv_r2_eta2 = 1.0 / (g.r2 + 0.01 * h * h);
    const double coeff = p.pair_pressure_coefficient(ri.pressure, pressure[g.j], ri.rho, rho[g.j], inv_rho_ij,
                                                     g.vij.dot(g.xij), inv_r2_eta2, approach(g, ri));
    if (s.i) to_i -= m[g.j] * coeff * g.gradW;
    if (s.j) to_j += ri.m * coeff * g.gradW;
  }
  void store(std::size_t i, const Sum& sum) const { acceleration[i] = sum + p.gravity; }
};

}  // namespace ryushi
