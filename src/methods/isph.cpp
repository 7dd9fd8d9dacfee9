// Incompressible SPH as a recipe, registered as "isph": the corrected ALE-ISPH of Morikawa,
// Tsuji & Asai (seed 000) with the I-SPH(2) free-surface rule. One step:
//   neighbour_search          pairs within the support + a skin at x^n (reused at x*)
//   isph_predictor            v* = v + dt (nu lap v + g), x* = x + dt v*           (eq. 3)
//   support_filter            the list narrowed to the kernel support at x* (not Eulerian)
//   free_surface_detection    the I-SPH(2) rule at x* (det M_i < 0.6, Marrone's test)
//   ppe_assembly              fluid rows (eq. 5), Neumann wall rows (eq. 17), p = 0 on the surface
//   multigrid_setup           (or jacobi_setup) the preconditioner
//   linear_solve              BiCGSTAB (the system is not symmetric)
//   isph_pressure_correction  v, x corrected by -dt/rho0 grad p                      (eq. 4)
//   shifting_density, particle_shifting   ALE only: density-based shifting     (eqs. 19-25)
//   time_step_control         CFL on the velocity and the viscous limit (no sound speed)
// Fluid at rho0 with mass rho0 d^D; walls are the innermost layer of the scene's containers
// with their normals (kind 1), or with wall_rows = "adami" all the layers that cover the support.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include "methods/isph2_surface_detection.hpp"
#include "methods/isph_spec.hpp"
#include "methods/method.hpp"
#include "methods/scene_particles.hpp"
#include "scene/registered_keys.hpp"
#include "systems/fluid/pair_collision.hpp"
#include "systems/integrate/velocity_time_step.hpp"
#include "systems/isph/fixed_pressure_velocity.hpp"
#include "systems/isph/implicit_density_solve.hpp"
#include "systems/isph/isph_parameters.hpp"
#include "systems/isph/isph_predictor.hpp"
#include "systems/isph/isph_pressure_correction.hpp"
#include "systems/isph/isph_pressure_equation.hpp"
#include "systems/isph/isph_wall_guard.hpp"
#include "systems/neighbour/neighbour_search.hpp"
#include "systems/neighbour/support_filter.hpp"
#include "systems/pressure/linear_solve.hpp"
#include "systems/pressure/preconditioner_setup.hpp"
#include "systems/pressure/pressure_system_dump.hpp"
#include "systems/shifting/density_shifting.hpp"
#include "systems/shifting/fickian_shifting.hpp"
#include "systems/shifting/xsph_shifting.hpp"

namespace ryushi {

namespace {

template <int D>
IsphParameters<D> isph_parameters(const Scene& s) {
  IsphParameters<D> p;
  const auto& mp = s.method_params;
  p.kernel = Kernel<D>(kernel_from_name(s.kernel), s.smoothing_length());
  p.domain = scene_domain<D>(s);
  p.gravity = scene_vector<D>(s.gravity);
  p.spacing = s.spacing;
  p.rho0 = s.density;
  p.nu = s.viscosity / s.density;
  p.description = mp.text("description") == "lagrangian" ? IsphDescription::Lagrangian
                  : mp.text("description") == "eulerian" ? IsphDescription::Eulerian
                                                     : IsphDescription::Ale;
  p.ppe_laplacian = laplacian_order(mp.text("ppe_laplacian"));
  p.viscous_laplacian = laplacian_order(mp.text("viscous_laplacian"));
  p.pressure_gradient = mp.text("pressure_gradient") == "symmetric" ? PressureGradientForm::Symmetric
                        : mp.text("pressure_gradient") == "hybrid"  ? PressureGradientForm::Hybrid
                                                           : PressureGradientForm::Corrected;
  p.symmetric_gradient_det = mp.number("symmetric_gradient_det");
  p.uncorrected_divergence_det = mp.number("uncorrected_divergence_det");
  // Fixed particles cannot answer a density error by moving: Eulerian rows keep the paper's
  // divergence-free source.
  p.compression_relaxation =
      p.description == IsphDescription::Eulerian ? 0.0 : mp.number("compression_relaxation");
  p.compression_density = mp.text("compression_density") == "full_support" ? CompressionDensity::FullSupport
                                                                  : CompressionDensity::FirstShell;
  p.compression_dead_band = mp.number("compression_dead_band");
  p.extrapolated_surface = mp.text("free_surface_pressure") == "extrapolated";
  p.wall_no_slip = !mp.flag("wall_slip");
  p.wall_shepard = mp.text("wall_rows") == "shepard" || mp.text("wall_rows") == "shepard_hydrostatic";
  p.wall_shepard_hydrostatic = mp.text("wall_rows") == "shepard_hydrostatic";
  p.wall_adami = mp.text("wall_rows") == "adami";
  p.implicit_density = mp.text("formulation") == "implicit_density";
  p.wall_acceleration = std::any_of(s.solids.begin(), s.solids.end(), [](const SolidSpec& b) { return b.moves(); });
  for (const auto& b : s.solids) p.moving_bodies.push_back(b.moves());
  p.fixed_pressure = !s.fixed_pressure.empty();
  for (auto& extra : s.systems)  // a system that sets the surface's Dirichlet values (surface tension)
    for (auto& need : find_system_keys(extra.name)->needs)
      p.surface_pressure |= need == "free_surface_pressure";
  p.cfl = s.cfl;
  double u = std::sqrt(2.0 * s.gravity_magnitude() * s.fluid_height());
  p.reference_speed = u > 0 ? u : 1e-9;
  return p;
}

// CFL on the velocity and the explicit viscosity's 0.125 h^2 / nu: no sound speed. The velocity is
// the particles' own plus what gravity adds within the step (DFSPH's rule); the column's free-fall
// speed sqrt(2 g H) is no floor: with it the a/d = 100 dam break took 1,830 steps to T = 2.5, with
// its fastest particle's speed 1,295 at the same CFL (docs/isph.md, "The step"). Water at rest
// takes kSurfaceWaveStep sqrt(d / g) at most (isph_parameters.hpp). Without gravity the
// reference speed bounds a fluid that starts at rest.
template <int D>
VelocityTimeStep<D> isph_time_step(const IsphParameters<D>& p) {
  const double h = p.kernel.h();
  const double g = p.gravity.norm();
  const double wave = g > 0 ? kSurfaceWaveStep * std::sqrt(p.spacing / g) : 0.0;
  return VelocityTimeStep<D>(p.cfl, p.spacing, p.reference_speed, p.nu > 0 ? 0.125 * h * h / p.nu : 0.0, g,
                             wave);
}

template <int D>
void populate_isph_world(const Scene& s, const IsphParameters<D>& p, World<D>& world) {
  const double g_up = -p.gravity[D - 1];
  // Incompressible: density rho0 everywhere; the hydrostatic pressure is the first solve's guess.
  const auto appended = append_scene_particles<D>(
      s, p.rho0, world,
      [&](double depth, double given) {
        return std::pair{p.rho0, !std::isnan(given) ? given : s.method_params.flag("hydrostatic_init") ? p.rho0 * g_up * depth : 0.0};
      },
      [](int) { return kWall; }, [&](int layer) { return layer == 1 || p.wall_adami || p.implicit_density; },
      !p.wall_adami && !p.implicit_density);
  add_wall_normals(appended, world);  // of the kept wall particles (layer 1, or all with Adami rows)
  add_surface_elements(s, appended, world);
  if (s.method_params.flag("confined")) {  // read by the pressure rows; no system writes them
    world.ensure(components::free_surface);
    world.ensure(components::surface_normal);
  }
  if (!p.fixed_pressure) return;
  // [[fixed_pressure]]: the fluid particles inside a box hold p = pressure + gradient . x.
  auto& fixed = world.ensure(components::fixed_pressure);
  auto& kind = world.column(components::kind);
  auto& x = world.column(components::position);
  auto& pressure = world.column(components::pressure);
  for (std::size_t i = 0; i < world.size(); ++i) {
    fixed[i] = std::numeric_limits<double>::quiet_NaN();
    if (kind[i] != kFluid) continue;
    for (auto& b : s.fixed_pressure) {
      bool inside = true;
      for (int a = 0; a < D; ++a) inside = inside && x[i][a] >= b.min[a] && x[i][a] <= b.max[a];
      if (!inside) continue;
      fixed[i] = b.pressure;
      for (int a = 0; a < D; ++a) fixed[i] += b.gradient[a] * x[i][a];
      pressure[i] = fixed[i];
    }
  }
}

// formulation = "implicit_density": after the predictor, the density solve at x* corrects v and x,
// its particle-scale damping (particle_damping) taking the jitter out of v; no free-surface
// detection, no shifting.
template <int D>
std::vector<SystemPtr<D>> implicit_density_pipeline(const Scene& s, const IsphParameters<D>& p,
                                                    std::vector<SystemPtr<D>> list) {
  list.push_back(std::make_shared<SupportFilter<D>>(p.kernel.support()));
  ImplicitDensitySettings settings;
  settings.tolerance = s.method_params.number("density_tolerance");
  settings.relaxation = s.method_params.number("density_relaxation");
  settings.damping = s.method_params.number("particle_damping");
  list.push_back(std::make_shared<ImplicitDensitySolve<D>>(p, settings));
  const double collision = s.method_params.number("collision_distance");
  if (collision > 0)
    list.push_back(std::make_shared<PairCollision<D>>(PairCollisionParameters{
        "isph_collision", collision * p.spacing, 0.0, s.method_params.number("collision_restitution"),
        s.method_params.text("collision_approach") == "beyond_resolved_flow"}));
  list.push_back(std::make_shared<IsphWallGuard<D>>(p.domain, 0.5 * p.spacing, p.spacing));
  if (s.fixed_dt <= 0) list.push_back(std::make_shared<VelocityTimeStep<D>>(isph_time_step<D>(p)));
  return list;
}

template <int D>
std::vector<SystemPtr<D>> isph_pipeline(const Scene& s, const IsphParameters<D>& p) {
  MethodContext<D> context = method_context<D>(s, p.kernel);
  SolverSpec solver = s.solver;
  solver.krylov = "bicgstab";
  std::vector<SystemPtr<D>> list{
      // The implicit density formulation's step moves the fastest particle 0.4 d at its CFL: a
      // Verlet skin would be outgrown every step (a/d = 100: 610 builds in 698 steps with the
      // default 0.6 d, the search 10.0 ms a step; rebuilt each step without it, 6.9 ms).
      std::make_shared<NeighbourSearch<D>>(p.search_radius(), kDummy,
                                           p.implicit_density ? 0.0 : s.neighbour_skin * s.spacing, false),
      std::make_shared<IsphPredictor<D>>(p),
  };
  if (p.implicit_density) return implicit_density_pipeline<D>(s, p, std::move(list));
  // The list holds the step's motion; from x* on only the pairs within the support count.
  if (p.description != IsphDescription::Eulerian)
    list.push_back(std::make_shared<SupportFilter<D>>(p.kernel.support()));
  // A confined fluid has no surface to find (populate_isph_world leaves the flags cleared).
  if (!s.method_params.flag("confined")) list.push_back(isph2_surface_detection<D>(context));
  list.push_back(std::make_shared<IsphPressureEquation<D>>(p));
  if (solver.preconditioner != "none") list.push_back(std::make_shared<PreconditionerSetup<D>>(solver));
  list.push_back(std::make_shared<LinearSolve<D>>(solver));
  list.push_back(std::make_shared<IsphPressureCorrection<D>>(p));
  if (p.fixed_pressure) list.push_back(std::make_shared<FixedPressureVelocity<D>>(p.domain));
  // Pairs closing in below collision_distance collide (fluid pairs only: the walls have the guard
  // below). The corrected gradient does not push a close pair apart (pair_collision.hpp).
  const double collision = s.method_params.number("collision_distance");
  if (p.description != IsphDescription::Eulerian && collision > 0)
    list.push_back(std::make_shared<PairCollision<D>>(PairCollisionParameters{
        "isph_collision", collision * p.spacing, 0.0, s.method_params.number("collision_restitution"),
        s.method_params.text("collision_approach") == "beyond_resolved_flow"}));
  if (p.description == IsphDescription::Ale && s.shifting_model == "density") {
    ShiftingParameters<D> sp{p.kernel, p.domain, p.spacing, p.rho0, s.shifting_coefficient, kTunedCfl,
                             p.reference_speed};
    list.push_back(std::make_shared<ShiftingDensity<D>>(sp));
    list.push_back(std::make_shared<DensityShifting<D>>(sp));
  } else if (p.description == IsphDescription::Ale &&
             (s.shifting_model == "fickian" || s.shifting_model == "optimised")) {
    list.push_back(std::make_shared<FickianShifting<D>>(
        FickianShiftingParameters<D>{p.kernel, p.domain, p.spacing, s.fickian_coefficient, s.anti_clumping,
                                     s.max_shift, true, s.shifting_model == "optimised"}));
  } else if (p.description == IsphDescription::Ale && s.shifting_model == "xsph") {
    list.push_back(std::make_shared<XsphShifting<D>>(
        XsphShiftingParameters<D>{p.kernel, p.domain, p.spacing, s.xsph_epsilon, s.max_shift}));
  }
  if (p.description != IsphDescription::Eulerian)
    list.push_back(std::make_shared<IsphWallGuard<D>>(p.domain, 0.5 * p.spacing, p.spacing));
  if (s.fixed_dt <= 0) list.push_back(std::make_shared<VelocityTimeStep<D>>(isph_time_step<D>(p)));
  return list;
}

template <int D>
MethodSetup<D> build_isph(const Scene& s, World<D>& world, const PipelineOptions& options) {
  auto p = isph_parameters<D>(s);
  populate_isph_world<D>(s, p, world);
  MethodSetup<D> m;
  m.context = method_context<D>(s, p.kernel);
  double vmax = 0;  // a scene may start moving (the rotating square)
  for (auto& u : world.column(components::velocity)) vmax = std::max(vmax, u.norm());
  m.first_dt = isph_time_step<D>(p).limit(vmax);
  // A time of the flow, not of the step: the step of the flow at rest at the CFL number of 0.2 the
  // term was tuned at (the sloshing tank's volume, docs/isph.md), whatever the scene's CFL.
  p.relaxation_time = kTunedCfl * p.spacing / std::max(vmax, p.reference_speed);
  m.pipeline = isph_pipeline<D>(s, p);
  if (p.implicit_density) m.settle_steps = s.method_params.integer("settle_steps");
  char b[96];
  std::snprintf(b, sizeof b, "h = %.4g m, %s, bicgstab + ", p.kernel.h(), s.method_params.text("description").c_str());
  m.summary = b + s.solver.preconditioner;
  m.parameters = {{"smoothing_length", p.kernel.h()}, {"search_radius", p.search_radius()}};
  if (!options.dump_matrix_dir.empty())
    m.pipeline.push_back(std::make_shared<PressureSystemDump<D>>(options.dump_matrix_dir, options.dump_step));
  m.diagnostics = [](const World<D>&, const Resources& res) -> std::vector<std::pair<std::string, double>> {
    if (!res.has(resources::wall_guard_events.name)) return {};
    return {{"wall_guard_events", double(res.get(resources::wall_guard_events))}};
  };
  return m;
}

}  // namespace

RYUSHI_REGISTER_METHOD("isph", isph_spec(), build_isph);

}  // namespace ryushi
