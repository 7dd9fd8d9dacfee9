#pragma once
// Continuity equation with delta-SPH density diffusion (seed 002 eqs. 17-19), a pair term
// (systems/loops/pair_loop.hpp):
//   drho_i/dt = rho_i sum_j V_j (v_i - v_j) . grad_i W_ij + delta h c0 sum_j V_j psi_ij . grad_i W_ij
//   psi_ij = 2 (rho_j - rho_i) (x_j - x_i) / |x_ij|^2 - (<grad rho>_i + <grad rho>_j)
// The gradient pair enters as a sum: that subtracts the linear part of rho_j - rho_i (so a
// hydrostatic density field does not diffuse) and keeps the term antisymmetric, hence mass-
// conserving. (The seed prints a difference; with x_ij = x_i - x_j the sum is what follows
// from Marrone et al. 2011.) Diffusion acts between fluid particles only; walls enter the
// divergence term with their own (prescribed) velocity.
// With the Riemann dissipation (wcsph_parameters.hpp) the diffusion is that of the same pair's
// Riemann problem: its interface velocity U* = (U_L + U_R)/2 + (p_i - p_j) / (2 rho0 c0) in
// drho_i/dt = 2 rho_i sum_j V_j (v_i - v*) . grad_i W_ij adds rho_i/(rho0 c0) sum_j V_j (p_i - p_j)
// r F ~ c0 sum_j V_j (rho_i - rho_j) r F (Zhang, Hu & Adams 2017): delta-SPH's pair with delta h
// replaced by r/2. It is taken with delta-SPH's linear part removed (their form diffuses a
// resting column's density at its free surface, where ryushi has no density summation).
#include <cstdint>
#include <span>

#include "ecs/component.hpp"
#include "systems/loops/pair_loop.hpp"

namespace ryushi {

template <int D, bool Diffusion>
struct ContinuityDeltaSph {
  struct Sum {
    double divergence = 0, diffusive = 0;
    Sum& operator+=(const Sum& o) {
      divergence += o.divergence;
      diffusive += o.diffusive;
      return *this;
    }
  };
  std::span<const double> V, rho;  // volumes m/rho, densities
  std::span<const Vec<D>> grad;    // the renormalised density gradient (Diffusion only)
  std::span<const std::int32_t> kind;
  std::span<double> density_rate;
  double diffusion;     // delta h c0, or c0 with riemann_weight
  bool riemann_weight;  // each pair's psi weighted by r/2 (the Riemann problem's diffusion)

  struct Row {  // row i's values, read once per row
    double V, rho;
    Vec<D> grad;
    bool fluid;
  };
  Row row(std::size_t i) const {
    Row r{V[i], rho[i], Vec<D>::Zero(), kind[i] == kFluid};
    if constexpr (Diffusion) r.grad = grad[i];
    return r;
  }

  Sum zero() const { return {}; }
  void operator()(const PairGeometry<D>& g, PairSides s, const Row& ri, Sum& to_i, Sum& to_j) const {
    // v_ij . grad_i W_ij is the same seen from j (both factors change sign).
    const double t = g.vij.dot(g.gradW);
    if (s.i) to_i.divergence += V[g.j] * t;
    if (s.j) to_j.divergence += ri.V * t;
    if constexpr (Diffusion) {
      if (ri.fluid && kind[g.j] == kFluid) {
        // (x_j - x_i) . grad_i W_ij / r^2 = -F exactly, so no division per pair; antisymmetric:
        // what i gains, j loses (weighted by V).
        double psi = -2.0 * (rho[g.j] - ri.rho) * g.F - (ri.grad + grad[g.j]).dot(g.gradW);
        if (riemann_weight) psi *= 0.5 * g.r;
        if (s.i) to_i.diffusive += V[g.j] * psi;
        if (s.j) to_j.diffusive -= ri.V * psi;
      }
    }
  }
  void store(std::size_t i, const Sum& sum) const {
    density_rate[i] = rho[i] * sum.divergence + diffusion * sum.diffusive;
  }
};

}  // namespace ryushi
