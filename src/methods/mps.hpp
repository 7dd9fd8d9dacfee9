#pragma once
// The MPS method (moving particle semi-implicit; BMG paper section 2) as a recipe. One step:
//   neighbour_search         pairs within r_e + skin at x^k (reused at x*)
//   mps_explicit_forces      u* = u + dt (nu lap u + g), x* = x + dt u*
//   mps_number_density       n* at x*; surface where n* < beta n0 (p = 0)
//   ppe_assembly             -lap p = gamma rho0/dt^2 (n* - n0)/n0 over unknown particles
//   multigrid_setup          (or jacobi_setup) the preconditioner from the current positions
//   linear_solve             Krylov solve into the pressure column
//   mps_pressure_correction  u, x corrected by -dt/rho0 grad p
//   mps_collision            approaching pairs closer than 0.5 l0 collide inelastically
//   time_step_control        dt for the next step
// Fluid particles move; wall particles (the innermost wall_pressure_layers) carry pressure;
// the outer wall layers are dummies that only complete the number density.
#include <vector>

#include "ecs/system.hpp"
#include "scene/scene.hpp"
#include "systems/mps/mps_parameters.hpp"

namespace ryushi {

template <int D>
MpsParameters<D> mps_parameters(const Scene& scene);

// Fluid (mass rho0 l0^D, hydrostatic pressure as the first solve's guess), wall and dummy
// particles.
template <int D>
void populate_mps_world(const Scene& scene, const MpsParameters<D>& p, World<D>& world);

template <int D>
std::vector<SystemPtr<D>> mps_pipeline(const Scene& scene, const MpsParameters<D>& p);

}  // namespace ryushi
