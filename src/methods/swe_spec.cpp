// The shallow-water method's scene rules (scene/registered_keys.hpp): registered with the
// method in swe.cpp. Its parameters are in its own sections ([swe], [bed], [splitting]).
#include "methods/swe_spec.hpp"

#include "scene/scene.hpp"
#include "scene/validator.hpp"

namespace ryushi {

namespace {

// A plan view on the lattice, the spiky kernel of eq. 8 and the water's weight along -z.
void resolve(Scene& sc, const toml::table& root, Validator& val) {
  if (sc.disorder > 0)
    val.fail(root["particles"]["disorder"].node(), "particles.disorder",
             "method 'swe' places its particles on the lattice; disorder is for wcsph, mps and isph");
  if (sc.dimension != 2)
    val.fail(root["scene"]["dimension"].node(), "scene.dimension",
             "method 'swe' is 2D (a plan view: x and y horizontal); set dimension = 2");
  if (sc.kernel != "spiky")
    val.fail(root["particles"]["kernel"].node(), "particles.kernel",
             "method 'swe' uses the spiky kernel (eq. 8): leave kernel out");
  if (root["particles"]["smoothing_ratio"])
    val.fail(root["particles"]["smoothing_ratio"].node(), "particles.smoothing_ratio",
             "method 'swe' sets r_e from the particle areas: use [swe] influence_ratio");
  if (root["physics"]["gravity"])
    val.fail(root["physics"]["gravity"].node(), "physics.gravity",
             "method 'swe' has no in-plane gravity: set [swe] gravity (along -z) and the bed's slope in "
             "[[bed_ramp]] or [bed]");
  sc.gravity.assign(sc.dimension, 0.0);
  // A fluid block is a depth over the plan; the particle methods' bodies and fields are not.
  if (const auto* blocks = root["fluid"].as_array())
    for (std::size_t i = 0; i < blocks->size(); ++i) {
      const std::string label = "[[fluid]] #" + std::to_string(i);
      if (root["fluid"][i]["pressure"])
        val.fail_entry(root, "fluid", i, "pressure",
                       label + ": pressure is for the particle methods (swe sets depth)");
      if (bool(root["fluid"][i]["depth"]) == bool(root["fluid"][i]["surface_elevation"]))
        val.fail_entry(root, "fluid", i, "depth",
                       label + ": method swe needs one of depth and surface_elevation");
    }
  if (root["import"])
    val.fail_entry(root, "import", 0, "file", "[[import]] #0 is for the particle methods, not swe");
  if (root["solid"])
    val.fail_entry(root, "solid", 0, "shape",
                   "[[solid]] #0 is for the particle methods, not swe (its walls are [[wall]] mirror lines)");
}

}  // namespace

MethodSpec swe_spec() {
  MethodSpec spec;
  spec.doc =
      "shallow-water MPS in the plan view with dynamic particle splitting (Saigo & Koshizuka; [swe], [bed], "
      "[splitting]; docs/swe.md)";
  spec.owns = {"swe",
               "bed",
               "bed_hump",
               "bed_ramp",
               "splitting",
               "fluid.depth",
               "fluid.surface_elevation",
               "probe.type=front_depth",
               "metric.type=ritter_depth"};
  spec.hooks.kernel = [](const Scene&) { return std::string("spiky"); };
  spec.hooks.smoothing_ratio = [](const Scene& sc) { return sc.swe.influence_ratio; };
  spec.hooks.cfl = 0.5;
  spec.hooks.read_sections = read_swe_sections;
  // Fewer columns than WCSPH's 2D pipeline, whose figure it takes (splitting adds particles
  // later: the estimate is of the start).
  spec.hooks.bytes_per_particle = [](int) { return 800.0; };
  spec.hooks.resolve = resolve;
  spec.hooks.walls_hold_particles = false;
  spec.hooks.health_fluid_checks = false;  // a depth per particle, no pressure; not the 3D energy
  return spec;
}

}  // namespace ryushi
