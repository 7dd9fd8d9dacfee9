#include "methods/mps.hpp"

#include <cmath>

#include "methods/scene_particles.hpp"
#include "systems/mps/mps_collision.hpp"
#include "systems/mps/mps_explicit_forces.hpp"
#include "systems/mps/mps_number_density.hpp"
#include "systems/mps/mps_pressure_correction.hpp"
#include "systems/mps/mps_pressure_equation.hpp"
#include "systems/mps/mps_time_step.hpp"
#include "systems/neighbour/neighbour_search.hpp"
#include "systems/pressure/linear_solve.hpp"
#include "systems/pressure/preconditioner_setup.hpp"

namespace ryushi {

template <int D>
MpsParameters<D> mps_parameters(const Scene& s) {
  MpsParameters<D> p;
  p.domain = scene_domain<D>(s);
  p.gravity = scene_vector<D>(s.gravity);
  p.spacing = s.spacing;
  p.set_weight(s.smoothing_length());
  p.rho0 = s.density;
  p.nu = s.viscosity / s.density;
  p.surface_threshold = s.surface_threshold;
  p.relaxation = s.source_relaxation;
  p.clamp_negative_pressure = s.clamp_negative_pressure;
  p.cfl = s.cfl;
  double u = std::sqrt(2.0 * s.gravity_magnitude() * s.fluid_height());
  p.reference_speed = u > 0 ? u : 1.0;
  return p;
}

template <int D>
void populate_mps_world(const Scene& s, const MpsParameters<D>& p, World<D>& world) {
  const double g_up = -p.gravity[D - 1];
  // Incompressible: density rho0 everywhere; the hydrostatic pressure is the first solve's guess.
  append_scene_particles<D>(
      s, p.rho0, world,
      [&](double depth) {
        return std::pair{p.rho0, s.hydrostatic_init ? p.rho0 * g_up * depth : 0.0};
      },
      [&](int layer) { return layer <= s.wall_pressure_layers ? kWall : kDummy; });
}

template <int D>
std::vector<SystemPtr<D>> mps_pipeline(const Scene& s, const MpsParameters<D>& p) {
  // Dummy-dummy pairs are never used; wall-wall and wall-dummy pairs are (wall number density,
  // wall rows of the pressure equation).
  std::vector<SystemPtr<D>> list{
      std::make_shared<NeighbourSearch<D>>(p.search_radius(), kDummy),
      std::make_shared<MpsExplicitForces<D>>(p),
      std::make_shared<MpsNumberDensity<D>>(p),
      std::make_shared<MpsPressureEquation<D>>(p),
  };
  if (s.solver.preconditioner != "none") list.push_back(std::make_shared<PreconditionerSetup<D>>(s.solver));
  list.push_back(std::make_shared<LinearSolve<D>>(s.solver));
  list.push_back(std::make_shared<MpsPressureCorrection<D>>(p));
  if (s.collision_distance > 0)
    list.push_back(std::make_shared<MpsCollision<D>>(p, s.collision_distance, s.wall_collision_distance,
                                                     s.collision_restitution));
  if (s.fixed_dt <= 0) list.push_back(std::make_shared<MpsTimeStep<D>>(p));
  return list;
}

template MpsParameters<2> mps_parameters<2>(const Scene&);
template MpsParameters<3> mps_parameters<3>(const Scene&);
template void populate_mps_world<2>(const Scene&, const MpsParameters<2>&, World<2>&);
template void populate_mps_world<3>(const Scene&, const MpsParameters<3>&, World<3>&);
template std::vector<SystemPtr<2>> mps_pipeline<2>(const Scene&, const MpsParameters<2>&);
template std::vector<SystemPtr<3>> mps_pipeline<3>(const Scene&, const MpsParameters<3>&);

}  // namespace ryushi
