// The MPS method (moving particle semi-implicit; BMG paper section 2) as a recipe, registered
// as "mps". One step:
//   neighbour_search         pairs within r_e + 2.5 cfl l0 at x^k (from a Verlet list with a skin)
//   mps_explicit_forces      u* = u + dt (nu lap u + g), x* = x + dt u*
//   mps_number_density       the list narrowed to r_e at x*, n* there; surface where n* < beta n0
//                            (p = 0)
//   ppe_assembly             -lap p = gamma rho0/dt^2 (n* - n0)/n0 over unknown particles
//   multigrid_setup          (or jacobi_setup) the preconditioner from the current positions
//   linear_solve             Krylov solve into the pressure column
//   mps_pressure_correction  u, x corrected by -dt/rho0 grad p
//   mps_collision            approaching pairs closer than 0.5 l0 collide inelastically
//   time_step_control        dt for the next step
// Fluid particles move; wall particles (the innermost wall_pressure_layers) carry pressure;
// the outer wall layers are dummies that only complete the number density.
#include <algorithm>
#include <cmath>
#include <cstdio>

#include "methods/method.hpp"
#include "methods/mps_spec.hpp"
#include "methods/scene_particles.hpp"
#include "systems/integrate/velocity_time_step.hpp"
#include "systems/fluid/pair_collision.hpp"
#include "systems/mps/mps_explicit_forces.hpp"
#include "systems/mps/mps_number_density.hpp"
#include "systems/mps/mps_pressure_correction.hpp"
#include "systems/mps/mps_pressure_equation.hpp"
#include "systems/neighbour/neighbour_search.hpp"
#include "systems/operators/mps_reference.hpp"
#include "systems/pressure/linear_solve.hpp"
#include "systems/pressure/preconditioner_setup.hpp"
#include "systems/pressure/pressure_system_dump.hpp"

namespace ryushi {

namespace {

template <int D>
MpsParameters<D> mps_parameters(const Scene& s) {
  MpsParameters<D> p;
  p.domain = scene_domain<D>(s);
  p.gravity = scene_vector<D>(s.gravity);
  p.spacing = s.spacing;
  p.set_weight(s.smoothing_length());
  p.rho0 = s.density;
  p.nu = s.viscosity / s.density;
  p.surface_threshold = s.method_params.number("surface_threshold");
  p.relaxation = s.method_params.number("source_relaxation");
  if (s.method_params.text("source_density") == "smooth")
    p.set_source_kernel(s.method_params.number("source_support"));
  p.clamp_negative_pressure = s.method_params.flag("clamp_negative_pressure");
  p.cfl = s.cfl;
  double u = std::sqrt(2.0 * s.gravity_magnitude() * s.fluid_height());
  p.reference_speed = u > 0 ? u : 1.0;
  return p;
}

// Courant number <= 0.2 on the velocity (BMG paper) and the explicit viscosity's 0.2 l0^2 / nu.
// One step's gravity increment g dt = u_ref * cfl l0 / (2H) is a small fraction of u_ref, so
// |u*| dt stays below 1.25 cfl l0 and two particles close in by less than the 2.5 cfl l0 skin.
template <int D>
VelocityTimeStep<D> mps_time_step(const MpsParameters<D>& p) {
  return VelocityTimeStep<D>(p.cfl, p.spacing, p.reference_speed,
                             p.nu > 0 ? 0.2 * p.spacing * p.spacing / p.nu : 0.0);
}

template <int D>
void populate_mps_world(const Scene& s, const MpsParameters<D>& p, World<D>& world) {
  const double g_up = -p.gravity[D - 1];
  // Incompressible: density rho0 everywhere; the hydrostatic pressure is the first solve's guess.
  const auto appended = append_scene_particles<D>(
      s, p.rho0, world,
      [&](double depth, double given) {
        return std::pair{p.rho0, !std::isnan(given)                         ? given
                                 : s.method_params.flag("hydrostatic_init") ? p.rho0 * g_up * depth
                                                                            : 0.0};
      },
      [&](int layer) { return layer <= s.method_params.integer("wall_pressure_layers") ? kWall : kDummy; });
  add_surface_elements(s, appended, world);
}

template <int D>
std::vector<SystemPtr<D>> mps_pipeline(const Scene& s, const MpsParameters<D>& p) {
  // Dummy-dummy pairs are never used; wall-wall and wall-dummy pairs are (wall number density,
  // wall rows of the pressure equation).
  std::vector<SystemPtr<D>> list{
      std::make_shared<NeighbourSearch<D>>(p.search_radius(), kDummy, s.neighbour_skin * s.spacing, false),
      std::make_shared<MpsExplicitForces<D>>(p),
      std::make_shared<MpsNumberDensity<D>>(p),  // narrows the list to r_e at x* as it goes
      std::make_shared<MpsPressureEquation<D>>(p),
  };
  if (s.solver.preconditioner != "none") list.push_back(std::make_shared<PreconditionerSetup<D>>(s.solver));
  list.push_back(std::make_shared<LinearSolve<D>>(s.solver));
  list.push_back(std::make_shared<MpsPressureCorrection<D>>(p));
  const auto& mp = s.method_params;
  if (mp.number("collision_distance") > 0)
    list.push_back(std::make_shared<PairCollision<D>>(PairCollisionParameters{
        "mps_collision", mp.number("collision_distance") * p.spacing,
        mp.number("wall_collision_distance") * p.spacing, mp.number("collision_restitution")}));
  if (s.fixed_dt <= 0) list.push_back(std::make_shared<VelocityTimeStep<D>>(mps_time_step<D>(p)));
  return list;
}

template <int D>
MethodSetup<D> build_mps(const Scene& s, World<D>& world, const PipelineOptions& options) {
  auto p = mps_parameters<D>(s);
  populate_mps_world<D>(s, p, world);
  MethodSetup<D> m;
  m.context = method_context<D>(s, p.weight);
  {  // the force probe's wall shear as MPS's Laplacian writes the viscous term
    const auto ref = mps_reference(m.context.kernel, m.context.spacing);
    m.context.wall_layer_viscous = m.context.viscosity / m.context.rho0 * 2.0 * D / (ref.lambda0 * ref.n0);
  }
  m.pipeline = mps_pipeline<D>(s, p);
  m.first_dt = mps_time_step<D>(p).limit(0.0);
  m.density_may_vanish = true;
  char b[64];
  std::snprintf(b, sizeof b, "r_e = %.4g m, ", p.weight.support());
  m.summary = b + s.solver.krylov + " + " + s.solver.preconditioner;
  m.parameters = {{"smoothing_length", p.weight.h()}, {"influence_radius", p.weight.support()}};
  if (!options.dump_matrix_dir.empty())
    m.pipeline.push_back(std::make_shared<PressureSystemDump<D>>(options.dump_matrix_dir, options.dump_step));
  // Mass is a constant column (exact by construction); what incompressibility keeps is the
  // source's density of the particles below the surface: its mean over them against rho0 (the
  // smooth kernel's, or n*/n0 with the number-density source), and n*/n0 beside it.
  const double n0 = p.n0, rho0 = p.rho0;
  m.diagnostics = [n0, rho0](const World<D>& w,
                             const Resources&) -> std::vector<std::pair<std::string, double>> {
    if (!w.has(components::number_density.name) || !w.has(components::pressure_role.name)) return {};
    auto& n = w.column(components::number_density);
    auto& rho = w.column(components::density);
    auto& role = w.column(components::pressure_role);
    auto& kind = w.column(components::kind);
    double sum = 0, density_sum = 0;
    std::size_t count = 0;
    for (std::size_t i = 0; i < w.size(); ++i)
      if (kind[i] == kFluid && role[i] == kPressureUnknown)
        sum += n[i] / n0, density_sum += rho[i] / rho0, ++count;
    return {{"interior_number_density_ratio", count ? sum / count : 1.0},
            {"interior_density_ratio", count ? density_sum / count : 1.0},
            {"interior_particles", static_cast<double>(count)}};
  };
  return m;
}

}  // namespace

RYUSHI_REGISTER_METHOD("mps", mps_spec(), build_mps);

}  // namespace ryushi
