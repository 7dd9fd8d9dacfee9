#pragma once
// Probes sampled between steps into probes.csv:
//   pressure      Shepard-normalised kernel interpolation of fluid pressure at a point:
//                 p(x) = sum_j p_j V_j W(x - x_j) / sum_j V_j W(x - x_j)
//   velocity      component `axis` of the fluid velocity at a point, interpolated the same way
//   surge_front   the leading edge of the water body: max of x (first axis) + d/2, the outer
//                 edge, over the fluid particles that have another fluid particle within 2 d,
//                 so that it equals the block width at t = 0. A droplet thrown ahead of the
//                 surge is not the front (MPS at a/l0 = 40 throws one 3-4 d ahead of the tongue,
//                 and whether it does changes with round-off: the a/l0 = 20 and 40 fronts were
//                 3.8-4.3% apart over T <= 2.5 in ten runs that differed only in the solver's
//                 round-off, and 5.8% in the one with a droplet). A tongue one particle thick
//                 stays the front: its tip particles are 1.5-2 d apart in the coarse I-SPH(2)
//                 collapse, where a reach of 1.5 d made the front step back. With every particle
//                 isolated, the largest x
//   water_height  elevation of the surface of the water column standing on the probe's base
//                 point: going up the vertical line from the base, the first height where the
//                 fluid fill fraction f(z) falls below 1/2 (linear between samples d/4 apart).
//                 f = sum_fluid V_j W / (1 - sum_wall V_j W), V_j = m_j/rho0: the share of the
//                 kernel support not taken by walls that holds fluid (1 inside water, also next
//                 to a wall; 1/2 at the surface, which on a lattice is the top row's edge, +d/2).
//                 Drops and particles clinging to a wall above a gap are not the column and do
//                 not count; an isolated particle reaches f ~ 0.2. The base itself when no water
//                 stands there; points inside walls (wall share > 0.9) are skipped.
//   particle_count    the number of fluid particles (it grows with particle splitting)
//   front_depth       swe: the depth of the foremost fluid particle (largest x)
//   kinetic_energy    sum over fluid particles of m |v|^2 / 2 (J; J/m in 2D, per unit depth)
//   potential_energy  sum over fluid particles of -m g . x (J; zero at the origin): with the
//                     kinetic energy, the mechanical energy a sloshing tank may only lose
//   wall_pressure     a pressure sensor on a wall: the fluid's surface pressure averaged over
//                     the sensor's face (wall_sensor.hpp)
//   force             a component of the fluid's force on a [[solid]]: WCSPH's pair-force
//                     reaction (solid_force.hpp), else the surface pressure and wall shear
//                     on the body's first layer (solid_surface_force.hpp)
#include <string>
#include <vector>

#include "ecs/world.hpp"
#include "systems/method_context.hpp"
#include "systems/probes/wall_sensor.hpp"  // SensorProblem

namespace ryushi {

// One probe as the scene's [[probe]] gives it (the types above).
struct Probe {
  std::string type;
  std::vector<double> position;
  int solid = -1, axis = 0;    // force: the [[solid]]'s index and the component (also velocity)
  std::vector<double> normal;  // wall_pressure: out of the wall, into the fluid (unit)
  double diameter = 0;         // wall_pressure: the sensor face's
  double scale = 1;            // force: what the reading is multiplied by (1 / (rho0 U^2 L^(D-1) / 2))
};

// Why each wall_pressure probe cannot read a wall, by the probe's index (empty where it can).
template <int D>
std::vector<SensorProblem> wall_sensor_problems(const std::vector<Probe>& probes, const World<D>& world,
                                                const MethodContext<D>& context);

template <int D>
std::vector<double> sample_probes(const std::vector<Probe>& probes, const World<D>& world,
                                  const MethodContext<D>& context);

}  // namespace ryushi
