// WCSPH's [method] keys and the scene rules that depend on it (scene/registered_keys.hpp):
// registered with the method in wcsph.cpp.
#include "methods/wcsph_spec.hpp"

#include <cmath>
#include <sstream>

#include "methods/common_method_keys.hpp"
#include "scene/scene.hpp"
#include "scene/validator.hpp"

namespace ryushi {

namespace {

using namespace keyspec;

std::vector<KeySpec> wcsph_keys() {
  using K = KeyType;
  return {
      non_negative("delta", "", "0.1",
                   "delta-SPH density diffusion coefficient (seed 002 eq. 18); 0 turns it off."),
      non_negative("artificial_viscosity", "", "0.02",
                   "Monaghan artificial viscosity alpha (linear term, seed 002 eq. 23 'A')."),
      non_negative("artificial_viscosity_quadratic", "", "0.0", "Quadratic term beta ('B')."),
      choice(
          "dissipation", "\"artificial_viscosity\"",
          "wcsph: the momentum equation's pair dissipation. artificial_viscosity: Monaghan's (the two keys "
          "above); riemann: the pressure P* of the linearised acoustic Riemann problem between each pair "
          "with the low-dissipation limiter of Zhang, Hu & Adams (2017, J. Comput. Phys. 335), beta = "
          "min(eta "
          "U / c0, 1) for an approach speed U, which damps impacts and hardly shears slow flow (a wall's "
          "state is the fluid's mirror along its normal), and the continuity's density diffusion is the same "
          "problem's, without its linear part (delta and the two artificial viscosity keys are refused "
          "beside it; docs/wcsph.md).",
          {"artificial_viscosity", "riemann"}),
      ranged({"riemann_limiter", K::Float, "", "3.0",
              "wcsph with dissipation = \"riemann\": eta of the limiter (Zhang, Hu & Adams use 3)."},
             0.0, 100.0),
      non_negative("solid_artificial_viscosity", "", "1.0",
                   "wcsph with [[elastic]]: A of the solid's artificial viscosity (seed 002 eq. 23; the seed "
                   "uses 1)."),
      non_negative("solid_artificial_viscosity_quadratic", "", "1.0",
                   "wcsph with [[elastic]]: B (the seed uses 1)."),
      choice(
          "solid_formulation", "\"total_lagrangian\"",
          "wcsph with [[elastic]]: total_lagrangian: sums over each particle's rest-configuration "
          "neighbours, deformation gradient and St Venant-Kirchhoff stress (free of the tensile instability; "
          "docs/multiphysics.md); updated: seed 002's own form (eqs. 1, 5-8, 22-26): continuity, Hooke's law "
          "with the Jaumann rate, Monaghan's artificial stress, over the current neighbours.",
          {"total_lagrangian", "updated"}),
      ranged({"solid_artificial_stress", K::Float, "", "0.3",
              "wcsph with [[elastic]] and solid_formulation = \"updated\": eps of Monaghan's artificial "
              "stress (seed 002 eq. 26; the seed and Gray et al. use 0.3, with exponent n = 4 and W(d) the "
              "reference)."},
             0.0, 10.0),
      choice(
          "solid_walls", "\"contact\"",
          "wcsph with [[elastic]]: how walls hold a solid. contact: a stiff spring (c_s^2/d)(1 - r/d) inside "
          "the spacing, with the artificial viscosity; seed: seed 002 section 4.1, wall particles at rest in "
          "the solid's momentum sum with the pressure of eq. 28 interpolated from the solid particles and "
          "the density of the solid's equation of state (solid_formulation = \"updated\" only).",
          {"contact", "seed"}),
      ranged({"solid_substeps", K::Integer, "", "1",
              "wcsph with [[elastic]]: the most velocity-Verlet substeps the solids take in one step of the "
              "fluid. 1: the step keeps the stiffest body's wave limit cfl h / c_s (c_s = sqrt((K + 4G/3) / "
              "rho0)), as in seed 002; N > 1: the step is bounded by N times that limit (with the fluid's "
              "own limits) and the solids take ceil(dt / limit) substeps, so a stiff body in slow water does "
              "not set the water's step (about c_s / c0 is the useful N; docs/multiphysics.md)."},
             1, 1000),
      choice(
          "integrator", "\"leapfrog\"",
          "wcsph: time integration. leapfrog: seed 001 eqs. 15-17, one force evaluation per step, velocity "
          "and density on the half steps (the frames show the full-step values predicted from them, eq. 16); "
          "midpoint: the two-stage predictor-corrector (seed 002 eqs. 29-31), two force evaluations per "
          "step, the same answer at the same step (docs/wcsph.md) for twice the pair work. A scene with "
          "[[elastic]] bodies or heat conduction that names none takes the midpoint (the leapfrog does not "
          "move solids, and its viscous and conduction step limits are half the midpoint's).",
          {"midpoint", "leapfrog"}),
      ranged({"velocity_smoothing", K::Float, "", "0.0",
              "wcsph: epsilon of XSPH velocity smoothing after each step (seed 001 eq. 36), v_i += eps sum_j "
              "m_j/((rho_i + rho_j)/2) (v_j - v_i) W_ij over fluid neighbours; 0 leaves the system out."},
             0.0, 1.0),
      wall_slip_key(),
      hydrostatic_init_key()};
}

// Before the geometry: the integrator's default and the solids' options that go together.
void resolve(Scene& sc, const toml::table& root, Validator& val) {
  auto& params = sc.method_params;
  // The leapfrog is WCSPH's default (the same answer as the midpoint at half the force
  // evaluations: docs/wcsph.md). Elastic bodies are moved by the midpoint's stages only, and the
  // leapfrog's conduction step is half the midpoint's (time_step.hpp), so a scene with either
  // that does not name an integrator takes the midpoint.
  const bool conducts = root["material"]["conductivity"].value_or(0.0) > 0;
  if (!params.given("integrator") && (root.contains("elastic") || conducts))
    params.set("integrator", std::string("midpoint"));
  if (params.text("solid_walls") == "seed" && params.text("solid_formulation") != "updated")
    val.fail(root["method"]["solid_walls"].node(), "method.solid_walls",
             "solid_walls = \"seed\" (seed 002 eq. 28) is for solid_formulation = \"updated\": the total "
             "Lagrangian form's sums run over the rest configuration, where walls have no place");
  if (params.text("dissipation") == "riemann")
    for (const char* key : {"artificial_viscosity", "artificial_viscosity_quadratic", "delta"})
      if (params.given(key))
        val.fail(
            root["method"][key].node(), std::string("method.") + key,
            std::string(key) +
                " is read by dissipation = \"artificial_viscosity\" only; \"riemann\" takes "
                "its dissipation from the pair's Riemann problem (its one parameter is riemann_limiter)");
  if (root["shifting"]["model"].value_or(std::string()) == "density")
    val.fail(root["shifting"]["model"].node(), "shifting.model",
             "[shifting] model = \"density\" is ISPH's (its beta, eqs. 19-25); wcsph takes none, fickian, "
             "optimised or xsph");
}

// After the whole scene: the elastic bodies' integrator (their step is checked as they load),
// and a CFL number beyond the integrator's stable range.
void validate(const Scene& sc, const toml::table& root, Validator& val) {
  const auto& params = sc.method_params;
  // The leapfrog's acoustic limit is half the midpoint's (docs/stability.md, time_step_test):
  // a tank at rest holds at 0.5 h / c0, is noisy at 0.7 and fails at 0.85 (the midpoint holds at
  // 1, the schema's bound). A fixed dt or seed 001's rule does not read the number.
  if (sc.fixed_dt <= 0 && sc.step_rule == "cfl" && params.text("integrator") == "leapfrog" && sc.cfl > 0.5) {
    std::ostringstream m;
    m << "time.cfl = " << sc.cfl
      << " is beyond the leapfrog integrator's stable range (at most 0.5: a tank at rest is noisy at 0.7 "
         "and fails at 0.85, docs/stability.md); use cfl <= 0.5, or [method] integrator = \"midpoint\" "
         "(stable to 1)";
    val.fail(root["time"]["cfl"].node(), "time.cfl", m.str());
  }
  for (std::size_t i = 0; i < sc.elastic.size(); ++i) {
    const std::string label = "[[elastic]] #" + std::to_string(i),
                      path = "elastic." + std::to_string(i) + ".min";
    if (params.text("integrator") != "midpoint")
      val.fail(root["elastic"][i]["min"].node(), path,
               label + " needs [method] integrator = \"midpoint\" (the leapfrog does not move solids yet)");
  }
}

}  // namespace

MethodSpec wcsph_spec() {
  MethodSpec spec;
  spec.doc = "weakly compressible SPH (explicit, Tait equation of state; docs/wcsph.md)";
  spec.keys = wcsph_keys();
  spec.owns = {"elastic", "time.step_rule"};
  spec.hooks.multiphysics = true;
  // [health] density_deviation: twice what the flow's own pressure, rho0 (g H + U^2 / 2) = rho0 U^2
  // with U = sqrt(2 g H), does to a weakly compressible fluid: 2 (U / c0)^2 (2% at the default
  // sound_speed_factor of 10). The dam break at a / d = 40 keeps 99% of its fluid within 1.04%.
  spec.hooks.health_density_deviation = [](const Scene& sc) {
    const double u = std::sqrt(2 * sc.gravity_magnitude() * sc.fluid_height());
    const double mach = sc.sound_speed <= 0 ? 1 / sc.sound_speed_factor : u > 0 ? u / sc.sound_speed : 0.1;
    return 2 * mach * mach;  // no gravity and a given c0: the usual Mach number 0.1
  };
  // Peak resident, 4 steps of the dam break (2026-11-29): 2D 714 bytes per particle between 40k
  // and 143k particles; 3D 1,033 between 74k and 349k, 1,422 at 1M and about 1,600 at 10M
  // (docs/benchmarks.md): the larger figures, rounded up.
  spec.hooks.bytes_per_particle = [](int dimension) { return dimension == 2 ? 800.0 : 1700.0; };
  spec.hooks.resolve = resolve;
  spec.hooks.validate = validate;
  return spec;
}

}  // namespace ryushi
