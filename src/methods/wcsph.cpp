// The weakly compressible SPH method as a recipe: which systems, in which order, with which
// options from the scene, registered as "wcsph". One step: neighbour search, then two stages of
// [wall BC, density gradient, pair forces (continuity, momentum, viscosity in one pass)] around
// the predictor and corrector, the equation of state after each, and the time-step control.
#include <algorithm>
#include <cmath>
#include <cstdio>

#include "methods/elastic_bodies.hpp"
#include "methods/isph2_surface_detection.hpp"
#include "methods/method.hpp"
#include "methods/scene_particles.hpp"
#include "methods/thermal_state.hpp"
#include "methods/wcsph_spec.hpp"
#include "systems/boundary/adami_wall.hpp"
#include "systems/elastic/elastic_midpoint.hpp"
#include "systems/elastic/fluid_on_solid.hpp"
#include "systems/elastic/total_lagrangian_elastic.hpp"
#include "systems/elastic/updated_lagrangian_elastic.hpp"
#include "systems/fluid/renormalised_density_gradient.hpp"
#include "systems/fluid/tait_equation_of_state.hpp"
#include "systems/fluid/wcsph_pair_forces.hpp"
#include "systems/fluid/wcsph_parameters.hpp"
#include "systems/fluid/xsph_velocity_smoothing.hpp"
#include "systems/heat/heat_conduction.hpp"
#include "systems/heat/temperature_midpoint.hpp"
#include "systems/integrate/leapfrog.hpp"
#include "systems/integrate/midpoint.hpp"
#include "systems/integrate/time_step.hpp"
#include "systems/neighbour/neighbour_search.hpp"
#include "systems/rheology/apparent_viscosity.hpp"
#include "systems/shifting/fickian_shifting.hpp"
#include "systems/shifting/xsph_shifting.hpp"

namespace ryushi {

namespace {

template <int D>
WcsphParameters<D> wcsph_parameters(const Scene& s) {
  WcsphParameters<D> p;
  p.kernel = Kernel<D>(kernel_from_name(s.kernel), s.smoothing_length());
  p.domain = scene_domain<D>(s);
  p.gravity = scene_vector<D>(s.gravity);
  p.spacing = s.spacing;
  p.rho0 = s.density;
  p.c0 = s.resolved_sound_speed();
  p.gamma = s.gamma;
  p.delta = s.method_params.number("delta");
  p.alpha = s.method_params.number("artificial_viscosity");
  p.beta = s.method_params.number("artificial_viscosity_quadratic");
  p.riemann = s.method_params.text("dissipation") == "riemann";
  p.riemann_limiter = s.method_params.number("riemann_limiter");
  p.mu = s.viscosity;
  p.wall_no_slip = !s.method_params.flag("wall_slip");
  p.wall_acceleration =
      std::any_of(s.solids.begin(), s.solids.end(), [](const SolidSpec& b) { return b.moves(); });
  p.variable_viscosity = s.rheology.shear_dependent() || s.rheology.temperature_dependent();
  p.elastic_bodies = !s.elastic.empty();
  // With solid substeps the step keeps N times the solid's limit: its sound speed over N.
  for (auto& e : s.elastic)
    p.solid_sound_speed =
        std::max(p.solid_sound_speed, e.sound_speed() / s.method_params.integer("solid_substeps"));
  return p;
}

// Heat conduction's fixed step limit (0: the scene conducts no heat).
template <int D>
double thermal_step_limit(const Scene& s, const WcsphParameters<D>& p) {
  return s.conductivity > 0 ? heat_parameters<D>(s, p.kernel, p.domain).step_limit(p.rho0) : 0.0;
}

// The step control of the scene's rule and integrator (the leapfrog's diffusion limits are half
// the midpoint's: time_step.hpp).
template <int D>
TimeStepControl<D> step_control(const Scene& s, const WcsphParameters<D>& p) {
  return TimeStepControl<D>(p, s.cfl, thermal_step_limit<D>(s, p), s.step_rule == "seed001",
                            s.method_params.text("integrator") == "leapfrog" ? 0.5 : 1.0);
}

// A rheology model's first step: the largest viscosity at rest over the starting temperatures
// (later steps take the largest of the column).
template <int D>
double viscosity_at_rest(const Scene& s, const World<D>& world) {
  if (!s.rheology.temperature_dependent()) return s.rheology.apparent(0.0, 0.0);
  const auto& T = world.column(components::temperature);
  const auto& kind = world.column(components::kind);
  double mu = 0;
  for (std::size_t i = 0; i < T.size(); ++i)
    if (kind[i] == kFluid) mu = std::max(mu, s.rheology.apparent(0.0, T[i]));
  return mu;
}

// Fluid blocks at rest (hydrostatic density and pressure) and Adami wall containers.
template <int D>
void populate_world(const Scene& s, const WcsphParameters<D>& p, World<D>& world) {
  const double g_up = -p.gravity[D - 1];  // gravity along the vertical (last) axis
  // Hydrostatic start: the density that the equation of state maps to rho0 g depth, so the
  // column starts in equilibrium (mass = that compressed density times d^D).
  auto appended = append_scene_particles<D>(
      s, p.rho0, world,
      [&](double depth, double given) {
        double rho = p.density(!std::isnan(given)                         ? given
                               : s.method_params.flag("hydrostatic_init") ? p.rho0 * g_up * depth
                                                                          : 0.0);
        return std::pair{rho, p.pressure(rho)};
      },
      [](int) { return kWall; });
  add_surface_elements(s, appended, world);          // the force probe's pressure integral
  if (p.riemann) add_wall_normals(appended, world);  // the wall's Riemann state (momentum.hpp)
  if (s.models_heat()) add_thermal_state<D>(s, appended, world);
  if (!s.elastic.empty()) add_elastic_bodies<D>(s, p.rho0, world);
}

template <int D>
std::vector<SystemPtr<D>> wcsph_pipeline(const Scene& s, const WcsphParameters<D>& p, const World<D>& world) {
  // A scene of elastic bodies alone pays for no fluid system, and a lone body without walls for
  // no contact loop.
  const auto& kinds = world.column(components::kind);
  const bool has_fluid = std::find(kinds.begin(), kinds.end(), kFluid) != kinds.end();
  const bool has_walls = std::find(kinds.begin(), kinds.end(), kWall) != kinds.end();
  auto neighbours =
      std::make_shared<NeighbourSearch<D>>(p.kernel.support(), kWall, s.neighbour_skin * s.spacing);
  auto wall = std::make_shared<AdamiWall<D>>(p);
  auto gradient = std::make_shared<RenormalisedDensityGradient<D>>(p);
  auto forces = std::make_shared<WcsphPairForces<D>>(p);
  auto eos = std::make_shared<TaitEquationOfState<D>>(p);
  const bool walls = !s.walls.empty() || !s.solids.empty() || !s.elastic.empty();
  // Multiphysics (docs/multiphysics.md): only a scene that models them pays for these systems.
  SystemPtr<D> rheology, conduction;
  if (p.variable_viscosity)
    rheology = std::make_shared<ApparentViscosity<D>>(
        ApparentViscosityParameters<D>{p.kernel, p.domain, s.rheology, p.wall_no_slip, walls});
  const bool heat = s.conductivity > 0;
  if (heat) conduction = std::make_shared<HeatConduction<D>>(heat_parameters<D>(s, p.kernel, p.domain));

  // The solid's force model keeps the bodies' rest neighbours; its substeps (first stage) and
  // its forces at the end of the step (second stage) share it.
  auto elastic_p = elastic_parameters<D>(s, p.kernel, p.domain, s.step_rule == "seed001" ? 0.1 : s.cfl);
  elastic_p.contacts = has_walls || s.elastic.size() > 1;
  std::shared_ptr<ElasticModel<D>> elastic;
  SystemPtr<D> fluid_push;  // the fluid's force on the solid (second stage: the final kick's)
  if (!s.elastic.empty()) {
    if (s.method_params.text("solid_formulation") == "updated")
      elastic = std::make_shared<UpdatedLagrangianElasticity<D>>(elastic_p);
    else
      elastic = std::make_shared<TotalLagrangianElasticity<D>>(elastic_p);
    if (elastic_p.fluid) fluid_push = std::make_shared<FluidOnSolid<D>>(p, elastic_p.volume());
  }

  std::vector<SystemPtr<D>> list{neighbours};
  auto stage = [&] {
    if (!has_fluid) return;
    if (walls) list.push_back(wall);
    if (p.density_diffusion()) list.push_back(gradient);
    if (rheology) list.push_back(rheology);
    list.push_back(forces);
    if (conduction) list.push_back(conduction);
  };
  const bool leapfrog = s.method_params.text("integrator") == "leapfrog";
  if (leapfrog) {  // one force evaluation per step (seed 001 eqs. 15-17)
    stage();
    list.push_back(std::make_shared<LeapfrogIntegrator<D>>(heat));
    list.push_back(eos);
  } else {
    stage();
    list.push_back(std::make_shared<MidpointPredictor<D>>());
    if (heat) list.push_back(std::make_shared<TemperaturePredictor<D>>());
    if (elastic) list.push_back(std::make_shared<ElasticSubsteps<D>>(elastic, elastic_p));
    list.push_back(eos);
    stage();
    if (fluid_push) list.push_back(fluid_push);
    if (elastic) list.push_back(std::make_shared<ElasticForces<D>>(elastic));
    list.push_back(std::make_shared<MidpointCorrector<D>>());
    if (heat) list.push_back(std::make_shared<TemperatureCorrector<D>>());
    if (elastic) list.push_back(std::make_shared<ElasticCorrector<D>>(elastic_p.fluid));
    list.push_back(eos);
  }
  if (const double eps = s.method_params.number("velocity_smoothing"); eps > 0)
    list.push_back(std::make_shared<XsphVelocitySmoothing<D>>(p.kernel, p.domain, eps, leapfrog));
  if (s.shifting_model == "xsph") {
    list.push_back(std::make_shared<XsphShifting<D>>(
        XsphShiftingParameters<D>{p.kernel, p.domain, p.spacing, s.xsph_epsilon, s.max_shift}));
  } else if (s.shifting_model == "fickian" || s.shifting_model == "optimised") {
    // Particle shifting after the step (issue 8: WCSPH may use ISPH's system): the free-surface
    // rule of I-SPH(2) marks where only the tangential part of the shift is kept. The velocity is
    // carried to the shifted place (Taylor); the density is not (delta-SPH's diffusion smooths
    // it; a correction is not measured yet).
    list.push_back(isph2_surface_detection<D>(method_context<D>(s, p.kernel)));
    list.push_back(std::make_shared<FickianShifting<D>>(
        FickianShiftingParameters<D>{p.kernel, p.domain, p.spacing, s.fickian_coefficient, s.anti_clumping,
                                     s.max_shift, false, s.shifting_model == "optimised"}));
  }
  if (s.fixed_dt <= 0) list.push_back(std::make_shared<TimeStepControl<D>>(step_control<D>(s, p)));
  return list;
}

template <int D>
MethodSetup<D> build_wcsph(const Scene& s, World<D>& world, const PipelineOptions& options) {
  refuse_matrix_dump(s, options);
  auto p = wcsph_parameters<D>(s);
  populate_world<D>(s, p, world);
  if (p.variable_viscosity) p.mu = viscosity_at_rest<D>(s, world);
  MethodSetup<D> m;
  m.context = method_context<D>(s, p.kernel);
  m.context.solid_force = SolidForceReading::PairReaction;  // the reaction to wcsph_pair_forces
  m.pipeline = wcsph_pipeline<D>(s, p, world);
  m.first_dt = step_control<D>(s, p).limit(0.0, p.gravity.norm());
  if (s.models_heat()) m.frame_fields.push_back("temperature");
  if (p.variable_viscosity) m.frame_fields.insert(m.frame_fields.end(), {"viscosity", "shear_rate"});
  if (!s.elastic.empty())
    m.frame_fields.insert(m.frame_fields.end(), {"stress", "displacement", "solid_pressure", "elastic_body"});
  char b[96];
  std::snprintf(b, sizeof b, "h = %.4g m, c0 = %.4g m/s", p.kernel.h(), p.c0);
  m.summary = b;
  m.parameters = {{"smoothing_length", p.kernel.h()}, {"sound_speed", p.c0}};
  return m;
}

}  // namespace

RYUSHI_REGISTER_METHOD("wcsph", wcsph_spec(), build_wcsph);

}  // namespace ryushi
