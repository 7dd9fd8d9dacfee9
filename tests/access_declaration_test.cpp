// Every system fetches exactly what it declares (issue 48). The scheduler derives the flow
// graph's edges from the declarations, and SystemContext refuses a fetch outside them; a name
// declared but never fetched went unnoticed (the ISPH predictor declared the domain resource and
// used its parameters' copy): an edge for nothing, and a list that no longer says what the
// system touches. Each scene below runs a few steps of its method's pipeline; for every system
// the names its runs fetched (SystemContext records them) must be the names it declared, less
// those declared only to order it (io.hpp, order_only). Together the scenes build every system
// class of every method, the [[systems]] registry's, and the reference systems the fused WCSPH
// pass is checked against; a class no scene builds fails the coverage check by name.
#include <cxxabi.h>
#include <doctest/doctest.h>

#include <cstdlib>
#include <map>
#include <memory>
#include <set>
#include <string>
#include <typeinfo>
#include <vector>

#include "app/plugins.hpp"
#include "ecs/scheduler.hpp"
#include "methods/method.hpp"
#include "methods/system_registry.hpp"
#include "scene/scene.hpp"
#include "test_util.hpp"

using namespace ryushi;

namespace {

// The class of a system without namespace and dimension: "ryushi::IsphPredictor<2>" -> "IsphPredictor".
template <int D>
std::string class_of(const System<D>& system) {
  const char* mangled = typeid(system).name();
  int status = 0;
  std::unique_ptr<char, decltype(&std::free)> full(abi::__cxa_demangle(mangled, nullptr, nullptr, &status),
                                                   &std::free);
  std::string name = status == 0 ? full.get() : mangled;
  name = name.substr(0, name.find('<'));
  const auto colon = name.rfind("::");
  return colon == std::string::npos ? name : name.substr(colon + 2);
}

struct Findings {
  std::set<std::string> classes;      // every system class built
  std::vector<std::string> problems;  // "scene: system: declares ... but never fetches them"
};

// Compares each system's declaration with what its runs fetched.
template <int D>
void compare(const Scheduler<D>& s, const std::string& label, Findings& out) {
  for (std::size_t i = 0; i < s.pipeline().size(); ++i) {
    const Access& a = s.accesses()[i];
    const FetchedNames& fetched = s.fetched()[i];
    std::set<std::string> declared(a.reads.begin(), a.reads.end());
    declared.insert(a.writes.begin(), a.writes.end());
    std::string unused, ordering_fetched;
    for (auto& name : declared) {
      const bool was_fetched = fetched.count(name) != 0;
      if (a.ordering.count(name)) {
        if (was_fetched) ordering_fetched += " " + name;
      } else if (!was_fetched) {
        unused += " " + name;
      }
    }
    const auto& system = *s.pipeline()[i];
    const std::string who = label + ": " + system.name() + " (" + class_of(system) + ")";
    if (!unused.empty()) out.problems.push_back(who + " declares" + unused + " but never fetches them");
    if (!ordering_fetched.empty())
      out.problems.push_back(who + " fetches" + ordering_fetched + ", declared for ordering only");
    out.classes.insert(class_of(system));
  }
}

// The driver's loop, cut down: the resources it provides, then `steps` steps with the structural
// changes applied between them.
template <int D>
void run_scene_steps(const Scene& scene, const PipelineOptions& options, int steps, const std::string& label,
                     Findings& out) {
  World<D> world;
  Resources res;
  Profiler profiler;
  auto method = build_method<D>(scene, world, options);
  res.ensure(domain_resource<D>) = method.context.domain;
  res.ensure(resources::time) = 0.0;
  res.ensure(resources::step) = 0;
  Scheduler<D> scheduler(std::move(method.pipeline), world, res, profiler);
  scheduler.initialise();
  double& dt = res.ensure(resources::dt);
  dt = scene.fixed_dt > 0 ? scene.fixed_dt : method.first_dt;
  res.ensure(resources::dt_chosen) = dt;
  double time = 0;
  for (int k = 0; k < steps; ++k) {
    if (scene.fixed_dt > 0) dt = scene.fixed_dt;
    res.get(resources::dt_chosen) = dt;
    res.get(resources::step) = k;
    scheduler.step();
    if (res.has(structural_changes_resource<D>.name)) {
      auto& changes = res.get(structural_changes_resource<D>);
      if (!changes.empty()) changes.apply(world);
    }
    time += dt;
    res.get(resources::time) = time;
  }
  compare(scheduler, label, out);
}

struct Case {
  std::string scene;              // under scenes/, or a path
  std::vector<std::string> sets;  // overrides, as --set
  std::string label;
  PipelineOptions options{};
};

void run_case(const Case& c, Findings& out, int steps = 3) {
  const std::string path = c.scene.find('/') == std::string::npos ? test::scene_path(c.scene) : c.scene;
  Scene scene = load_scene(path, c.sets);
  const std::string label = c.label.empty() ? c.scene : c.label;
  INFO("scene " << label);
  auto run = [&](auto dim) {
    constexpr int D = decltype(dim)::value;
    run_scene_steps<D>(scene, c.options, steps, label, out);
  };
  if (scene.dimension == 2)
    run(std::integral_constant<int, 2>{});
  else
    run(std::integral_constant<int, 3>{});
}

std::string joined(const std::vector<std::string>& lines) {
  std::string s;
  for (auto& l : lines) s += "\n  " + l;
  return s;
}

// A WCSPH scene with every registered [[systems]] entry that needs nothing of its method (and
// free_surface_detection once more with its optional moment matrix); a registered name missing
// from `params` fails the test. Those that need something (surface_tension) run in the cases.
std::string registry_scene(const std::map<std::string, std::string>& params) {
  std::string text = test::block_scene("[0.2, 0.2]", "[0.6, 0.6]", 1.0);
  for (auto& name : system_registry_names()) {
    if (!system_registry_entry(name).keys.needs.empty()) continue;
    auto it = params.find(name);
    REQUIRE_MESSAGE(it != params.end(), "registered system '" << name << "' has no parameters in this test");
    text += "[[systems]]\nname = \"" + name + "\"\n" + it->second;
  }
  return text + "[[systems]]\nname = \"free_surface_detection\"\nmoment_matrix = true\n";
}

}  // namespace

TEST_CASE("access: every system of every method fetches exactly what it declares") {
  load_plugins({RYUSHI_EXAMPLE_PLUGIN});  // the example plugin's system and method count too
  Findings found;
  const auto dump_dir = test::scratch("access_declaration_dump");
  const std::vector<Case> cases = {
      // WCSPH: the leapfrog, then the midpoint with smoothing, shifting and laminar viscosity.
      {"dam_break_2d.toml", {}, "", {}},
      {"dam_break_2d.toml",
       {"method.integrator=\"midpoint\"", "method.velocity_smoothing=0.05", "shifting.model=\"xsph\"",
        "material.viscosity=1e-3"},
       "dam_break_2d (midpoint, xsph)",
       {}},
      {"dam_break_2d.toml", {"shifting.model=\"fickian\""}, "dam_break_2d (fickian)", {}},
      {"conduction_2d.toml", {}, "", {}},
      {"conduction_2d.toml", {"method.integrator=\"midpoint\""}, "conduction_2d (midpoint)", {}},
      {"cooling_slump_2d.toml", {}, "", {}},
      {"poiseuille_bingham_2d.toml", {}, "", {}},
      {"couette_2d.toml", {}, "", {}},
      {"wave_flume_2d.toml", {}, "", {}},
      {"elastic_gate_2d.toml", {}, "", {}},
      {"elastic_plate_2d.toml", {"method.solid_formulation=\"updated\""}, "elastic_plate_2d (updated)", {}},
      // MPS, once with the matrix dump (its system reads the step to dump).
      {"dam_break_mps_2d.toml", {}, "", {}},
      {"hydrostatic_mps_2d.toml", {}, "", PipelineOptions{dump_dir, 1}},
      // ISPH: each shifting model, the Eulerian pipe with fixed pressures, a moving body.
      {"dam_break_isph_2d.toml", {}, "", {}},
      {"dam_break_isph_2d.toml", {"shifting.model=\"density\""}, "dam_break_isph_2d (density shifting)", {}},
      {"dam_break_isph_2d.toml", {"shifting.model=\"xsph\""}, "dam_break_isph_2d (xsph shifting)", {}},
      {"dam_break_isph2_2d.toml", {}, "", {}},
      {"poiseuille_isph_2d.toml", {}, "", {}},
      {"wave_flume_isph_2d.toml", {}, "", {}},
      // Surface tension, with the paper's force, the detection's normal and a contact angle.
      {"square_drop_2d.toml", {}, "", {}},
      {"square_drop_2d.toml",
       {"systems.0.delta_coefficient=0.1", "systems.0.normal=\"kernel_sum\"", "systems.0.contact_angle=60"},
       "square_drop_2d (force, kernel-sum normal, contact angle)",
       {}},
      // Shallow water with particle splitting.
      {"dam_break_ritter_swe.toml", {}, "", {}},
      // The example plugin's method (examples/out_of_tree/ballistic.cpp).
      {"sloshing_2d.toml", {"method.name=ballistic", "time.dt=0.001"}, "sloshing_2d (ballistic)", {}},
  };
  for (auto& c : cases) run_case(c, found);

  // The [[systems]] registry, every entry by name.
  const auto dir = test::scratch("access_declaration_registry");
  test::write_text(dir / "registry.toml",
                   registry_scene({{"passive_scalar_diffusion", "diffusivity = 1e-3\n"},
                                   {"free_surface_detection", "rule = \"marrone\"\n"}}));
  run_case({(dir / "registry.toml").string(), {}, "registry scene", {}}, found);

  INFO("systems whose declaration and fetches differ:" << joined(found.problems));
  CHECK(found.problems.empty());

  // Coverage: every system class in src/systems and the example plugin (a new one is added here, with a
  // scene that builds it).
  const std::vector<std::string> expected = {"NeighbourSearch",
                                             "SupportFilter",
                                             "AdamiWall",
                                             "PrescribedMotion",
                                             "RenormalisedDensityGradient",
                                             "WcsphPairForces",
                                             "TaitEquationOfState",
                                             "XsphVelocitySmoothing",
                                             "ApparentViscosity",
                                             "HeatConduction",
                                             "TemperaturePredictor",
                                             "TemperatureCorrector",
                                             "LeapfrogIntegrator",
                                             "MidpointPredictor",
                                             "MidpointCorrector",
                                             "TimeStepControl",
                                             "VelocityTimeStep",
                                             "FluidOnSolid",
                                             "ElasticSubsteps",
                                             "ElasticForces",
                                             "ElasticCorrector",
                                             "XsphShifting",
                                             "FickianShifting",
                                             "ShiftingDensity",
                                             "DensityShifting",
                                             "FreeSurfaceDetection",
                                             "MpsNumberDensity",
                                             "MpsExplicitForces",
                                             "MpsPressureEquation",
                                             "MpsPressureCorrection",
                                             "PairCollision",
                                             "PreconditionerSetup",
                                             "LinearSolve",
                                             "PressureSystemDump",
                                             "IsphPredictor",
                                             "IsphPressureEquation",
                                             "IsphPressureCorrection",
                                             "FixedPressureVelocity",
                                             "IsphWallGuard",
                                             "SweInfluenceRadius",
                                             "SweGhostWalls",
                                             "SweNeighbourSearch",
                                             "SweDepth",
                                             "SweAcceleration",
                                             "SweIntegrate",
                                             "SweTimeStep",
                                             "ParticleSplitting",
                                             "PassiveScalarDiffusion",
                                             "RegisteredSurfaceTension",
                                             "BallisticDrag"};
  std::string missing;
  for (auto& name : expected)
    if (!found.classes.count(name)) missing += " " + name;
  std::string built;
  for (auto& name : found.classes) built += " " + name;
  INFO("built:" << built);
  CHECK_MESSAGE(missing.empty(), "no scene here builds:" << missing);
}
