// MPH-I (moving particle hydrodynamics for incompressible flow: Kondo's physically consistent
// particle method with the pressure substituted into an implicit velocity equation; seed paper
// "MPH-I法を高速化するマルチグリッド前処理ソルバー", eqs. 1-4) as a recipe, registered as "mph".
// One step:
//   neighbour_search      pairs within max(h_v, 2 h_p) at x^k (a Verlet list with a skin)
//   mph_number_density    n, the rate coefficients, the elastic pressure, the bulk coefficient
//   mph_assembly          the velocity equation, D unknowns per fluid particle
//   mph_*_setup           the block bucket multigrid (or Jacobi), per [solver]
//   mph_velocity_solve    CG; u^{k+1} and the pressure of eq. 2
//   mph_move              x^{k+1} = x^k + dt u^{k+1}
//   time_step_control     dt for the next step: the convective CFL only (the viscous, bulk and
//                         elastic terms are implicit)
// Walls are frozen particles of the same material (every layer within h_v of the fluid): they
// enter the number density, the rates and the shear pairs with their surface velocity, which
// makes the wall no-slip. docs/mph.md states these choices and what they were measured against.
#include <algorithm>
#include <cmath>
#include <cstdio>

#include "methods/method.hpp"
#include "methods/scene_particles.hpp"
#include "scene/validator.hpp"
#include "systems/integrate/velocity_time_step.hpp"
#include "systems/mph/mph_number_density.hpp"
#include "systems/mph/mph_system_dump.hpp"
#include "systems/mph/mph_velocity_solve.hpp"
#include "systems/mph/mph_velocity_system.hpp"
#include "systems/neighbour/neighbour_search.hpp"

namespace ryushi {

namespace {

using namespace keyspec;

std::vector<KeySpec> mph_keys() {
  using K = KeyType;
  return {
      positive(
          "bulk_modulus", "Pa", "",
          "mph: kappa of eq. 2, the elastic pressure kappa (n - n0) of a compressed particle (n the number "
          "density, whose change is the volume strain). The MPH-I paper's dam break: 1e6 Pa. The relative "
          "compression at a depth H is about rho0 g H / kappa.",
          true),
      {"bulk_viscosity", K::Float, "Pa s", "",
       "mph: lambda of eq. 2, the viscous pressure -lambda div u. The MPH-I paper's dam break: 1e4 Pa s. It "
       "also brakes particle rows sliding past each other (their number density changes as they pass): a "
       "channel flow's error was 3.4-4.8% at 1e4 Pa s, 0.9-1.5% at 100 or less (docs/mph.md).",
       true, 0.0},
      ranged(
          {"pressure_radius", K::Float, "spacing", "1.75",
           "mph: h_p, the radius of the number density, its rate and the pressure force (the paper's 1.75)."},
          1.2, 4.0),
      ranged(
          {"viscous_radius", K::Float, "spacing", "3.5",
           "mph: h_v, the radius of the shear viscosity (the paper's 3.5); the [particles] smoothing_ratio "
           "follows it, so [[wall]] boxes hold ceil(h_v / spacing) layers by default."},
          1.2, 6.0),
      {"implicit_compression", K::Bool, "", "true",
       "mph: a compressed particle's elastic pressure at the end of the step, kappa (n + dt dn/dt - n0), is "
       "taken implicitly through its rate (kappa dt joins lambda there); false: explicit, stable only while "
       "kappa dt < 2 lambda."},
  };
}

// The fastest sliding surface ([[solid]] velocity): without gravity, what sets the first steps.
double surface_speed(const Scene& s) {
  double fastest = 0;
  for (const auto& b : s.solids) {
    double v2 = 0;
    for (double c : b.velocity) v2 += c * c;
    fastest = std::max(fastest, std::sqrt(v2));
  }
  return fastest;
}

void resolve(Scene& sc, const toml::table& root, Validator& val) {
  if (sc.kernel != "mps")
    val.fail(root["particles"]["kernel"].node(), "particles.kernel",
             "method 'mph' has its own weight (1 - r/h)^2: leave kernel out, not '" + sc.kernel + "'");
  if (root["shifting"]["model"].value_or(std::string("none")) != "none")
    val.fail(root["shifting"]["model"].node(), "shifting.model",
             "method mph has no particle shifting (its particles stay ordered by its own potential); leave "
             "[shifting] out");
}

void validate(const Scene& sc, const toml::table& root, Validator& val) {
  if (sc.solver.krylov != "cg")
    val.fail(root["solver"]["krylov"].node(), "solver.krylov",
             "method mph's velocity equation is symmetric positive definite: krylov must be \"cg\"");
  double g2 = 0;
  for (double c : sc.gravity) g2 += c * c;
  if (g2 == 0 && surface_speed(sc) == 0 && sc.fixed_dt <= 0)
    val.fail(
        root["time"]["dt"].node(), "time.dt",
        "method mph takes its step from the flow's speed: without gravity or a sliding [[solid]] nothing "
        "sets the first one; give [time] dt");
  for (std::size_t i = 0; i < sc.solids.size(); ++i)
    if (sc.solids[i].moves())
      val.fail_entry(root, "solid", i, "displacement",
                     "method mph has no moving bodies yet (a [[solid]]'s surface velocity is supported)");
}

template <int D>
MphParameters<D> mph_parameters(const Scene& s) {
  MphParameters<D> p;
  p.domain = scene_domain<D>(s);
  p.gravity = scene_vector<D>(s.gravity);
  p.spacing = s.spacing;
  p.rho0 = s.density;
  p.mu = s.viscosity;
  p.lambda = s.method_params.number("bulk_viscosity");
  p.kappa = s.method_params.number("bulk_modulus");
  p.implicit_compression = s.method_params.flag("implicit_compression");
  p.set_radii(s.method_params.number("pressure_radius") * s.spacing,
              s.method_params.number("viscous_radius") * s.spacing);
  p.cfl = s.cfl;
  return p;
}

template <int D>
VelocityTimeStep<D> mph_time_step(const MphParameters<D>& p, double reference_speed) {
  // The particles' speed plus what gravity adds within the step (velocity_time_step.hpp); without
  // gravity the particles' speed, at least the fastest sliding surface's.
  const double g = p.gravity.norm();
  return VelocityTimeStep<D>(p.cfl, p.spacing, g > 0 ? 0.0 : reference_speed, 0.0, g);
}

template <int D>
MethodSetup<D> build_mph(const Scene& s, World<D>& world, const PipelineOptions& options) {
  const auto p = mph_parameters<D>(s);
  const auto appended = append_scene_particles<D>(
      s, p.rho0, world,
      [&](double, double) {
        return std::pair{p.rho0, 0.0};
      },
      [](int) { return kWall; });
  add_wall_normals(appended, world);
  {
    auto& depth = world.ensure(components::mph_wall_depth);
    const std::size_t first = world.size() - appended.wall.size();
    for (std::size_t k = 0; k < appended.wall.size(); ++k)
      depth[first + k] = (appended.wall_layer[k] - 0.5) * p.spacing;
  }
  world.ensure(components::mph_number_density);
  MethodSetup<D> m;
  m.context = method_context<D>(s, Kernel<D>(KernelType::Mps, p.h_v));
  // The list holds the step's motion: each particle moves at most cfl l (the time step), so two
  // close in by 2 cfl l; the Verlet skin on top.
  m.pipeline = {
      std::make_shared<NeighbourSearch<D>>(p.coupling_radius() + 2 * p.cfl * p.spacing, -1,
                                           s.neighbour_skin * s.spacing, false),
      std::make_shared<MphNumberDensity<D>>(p),
      std::make_shared<MphVelocityAssembly<D>>(p),
      std::make_shared<MphPreconditionerSetup<D>>(s.solver),
      std::make_shared<MphVelocitySolve<D>>(s.solver),
      std::make_shared<MphMove<D>>(),
  };
  if (!options.dump_matrix_dir.empty())  // after the solve, before the next step's time step
    m.pipeline.push_back(std::make_shared<MphSystemDump<D>>(options.dump_matrix_dir, options.dump_step));
  const auto step = mph_time_step<D>(p, surface_speed(s));
  if (s.fixed_dt <= 0) m.pipeline.push_back(std::make_shared<VelocityTimeStep<D>>(step));
  m.first_dt = step.limit(0.0);
  m.density_may_vanish = true;
  char b[160];
  std::snprintf(b, sizeof b, "h_p = %.4g m, h_v = %.4g m, n0 = %.4f, ", p.h_p, p.h_v, p.n0);
  m.summary = b + std::string("cg + ") + s.solver.preconditioner;
  m.parameters = {{"pressure_radius", p.h_p}, {"viscous_radius", p.h_v}, {"n0", p.n0}};
  m.frame_fields = {"number_density"};
  return m;
}

MethodSpec mph_spec() {
  MethodSpec spec;
  spec.doc =
      "moving particle hydrodynamics for incompressible flow, MPH-I (velocity and pressure implicit in one "
      "symmetric system, solved as set in [solver]; docs/mph.md)";
  spec.keys = mph_keys();
  spec.hooks.kernel = [](const Scene&) { return std::string("mps"); };
  spec.hooks.smoothing_ratio = [](const Scene& sc) { return sc.method_params.number("viscous_radius"); };
  spec.hooks.solves_pressure = true;
  spec.hooks.step_motion = 2.0;
  spec.hooks.jacobi_weight = 2.0 / 3.0;
  spec.hooks.bytes_per_particle = [](int dimension) { return dimension == 2 ? 6000.0 : 40000.0; };
  spec.hooks.resolve = resolve;
  spec.hooks.validate = validate;
  // Frozen walls with a face distance (wall_depth), which a system may place and move itself
  // (elastic_line_contact).
  spec.hooks.provides = [](const Scene&) { return std::vector<std::string>{"wall_depth"}; };
  return spec;
}

}  // namespace

RYUSHI_REGISTER_METHOD("mph", mph_spec(), build_mph);

}  // namespace ryushi
