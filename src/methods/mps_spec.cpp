// MPS's [method] keys and the scene rules that depend on it (scene/registered_keys.hpp):
// registered with the method in mps.cpp.
#include "methods/mps_spec.hpp"

#include <cmath>
#include <sstream>

#include "methods/common_method_keys.hpp"
#include "scene/scene.hpp"
#include "scene/validator.hpp"

namespace ryushi {

namespace {

using namespace keyspec;

std::vector<KeySpec> mps_keys() {
  using K = KeyType;
  return {
      ranged({"surface_threshold", K::Float, "", "0.97",
              "mps: a fluid or wall particle with number density n* < surface_threshold * n0 is on the free "
              "surface (pressure 0, Dirichlet). 0.97 is Koshizuka's value."},
             0.5, 1.0),
      ranged({"source_relaxation", K::Float, "", "0.2",
              "mps: the Poisson source (BMG paper eq. 4) is multiplied by this relaxation factor, as in the "
              "paper's dam break (0.2)."},
             1e-6, 1.0),
      choice("source_density", "(smooth in 2D, number_density in 3D)",
             "mps: the density whose deviation is the Poisson source (BMG paper eq. 4's (n* - n0)/n0): "
             "smooth, the sum of a Wendland C2 kernel of support source_support * r_e over the same "
             "neighbours against its value on the lattice; or number_density, n* with the MPS weight r_e/r - "
             "1 (Koshizuka's and the BMG paper's). The weight is singular at r = 0, so on disordered "
             "particles n* reads high at an unchanged area, and holding n* = n0 lets the fluid's area grow "
             "as the flow disorders it: in the sloshing tank the interior's mean Voronoi cell grew 0.9% by t "
             "= 0.3 s with number_density (0.2% with smooth, WCSPH 0.03%) and the water gained 18% of the "
             "wave's energy, none with smooth (docs/mps.md). The free-surface rule and the Laplacian keep "
             "the weight. In 3D (r_e = 2.1 l0) the smooth kernel's support holds only the first three shells "
             "of the lattice and reads a disordered interior 1.8% dense where n* reads it 2.0% sparse in the "
             "3D dam break: neither measure is sound there, and the 3D default stays the paper's.",
             {"smooth", "number_density"}),
      ranged(
          {"source_support", K::Float, "", "0.9",
           "mps: with source_density = smooth, the Wendland kernel's support as a fraction of r_e (its h = "
           "source_support * r_e / 2). In the two-period sloshing tank every value from 0.8 to 1.0 keeps the "
           "energy at or below its start; 0.9 keeps the most of the wave with the period (0.101 m after two "
           "periods, period 1.190 s; 0.8: 0.080 m; 1.0: 0.0995 m with the period 5.9% long; docs/mps.md)."},
          0.5, 1.0),
      ranged({"wall_pressure_layers", K::Integer, "", "1",
              "mps: the innermost wall layers whose pressure is solved (wall particles); the outer layers "
              "are dummy particles that only complete the number density. layers must be >= "
              "wall_pressure_layers + floor(r_e / spacing)."},
             1, 8),
      ranged({"collision_distance", K::Float, "spacing", "0.5",
              "mps: particles closer than this (times the spacing) that still approach collide inelastically "
              "(Koshizuka's collision model, mps_collision system); 0 leaves the system out."},
             0.0, 1.0),
      ranged({"wall_collision_distance", K::Float, "spacing", "0.8",
              "mps: the collision distance between a fluid and a wall or dummy particle. Longer than between "
              "fluid particles: a particle crossing a 3D wall layer through the middle of a lattice square "
              "passes 0.71 l0 from the nearest wall particles, and without it the 3D dam break leaks through "
              "the far wall at the impact. A fluid particle at rest is one spacing from the wall particles "
              "and never collides."},
             0.0, 1.0),
      ranged({"collision_restitution", K::Float, "", "0.2",
              "mps: restitution coefficient e of the collision model."},
             0.0, 1.0),
      {"clamp_negative_pressure", K::Bool, "", "true",
       "mps: negative pressure from the solve is taken as 0 in the pressure gradient (no tension in a "
       "free-surface liquid)."},
      hydrostatic_init_key()};
}

void resolve(Scene& sc, const toml::table& root, Validator& val) {
  if (sc.kernel != "mps")
    val.fail(
        root["particles"]["kernel"].node(), "particles.kernel",
        "method 'mps' uses the MPS weight: kernel must be \"mps\" (or left out), not '" + sc.kernel + "'");
  if (root["shifting"]["model"].value_or(std::string("none")) != "none")
    val.fail(root["shifting"]["model"].node(), "shifting.model",
             "method mps has no particle shifting; leave [shifting] out");
  if (!sc.method_params.given("source_density"))
    sc.method_params.set("source_density", std::string(sc.dimension == 2 ? "smooth" : "number_density"));
}

// The wall layers a pressure-solved first layer needs behind it for a complete number density
// (its dummy particles), for [[wall]] and [[solid]] alike.
void validate(const Scene& sc, const toml::table& root, Validator& val) {
  const int needed = static_cast<int>(sc.method_params.integer("wall_pressure_layers")) +
                     static_cast<int>(std::floor(sc.support_radius() / sc.spacing + 1e-9));
  for (std::size_t i = 0; i < sc.walls.size(); ++i)
    if (sc.walls[i].layers < needed) {
      std::ostringstream m;
      m << "[[wall]] #" << i << ": " << sc.walls[i].layers
        << " layers leave the innermost wall particles short of dummy particles; method mps needs layers >= "
           "wall_pressure_layers + floor(r_e / spacing) = "
        << needed;
      val.fail_entry(root, "wall", i, "layers", m.str());
    }
  for (std::size_t i = 0; i < sc.solids.size(); ++i) {
    const auto& b = sc.solids[i];
    if (b.shape == "mesh") continue;
    const std::string label = "[[solid]] #" + std::to_string(i) + " ";
    // As for [[wall]]: a paddle two spacings thick read 63% of the hydrostatic thrust, its wall
    // particles flagged as free surface.
    if (b.layers < needed)
      val.fail_entry(
          root, "solid", i, "layers",
          label + "has " + std::to_string(b.layers) +
              " layers; method mps needs layers >= wall_pressure_layers + floor(r_e / spacing) = " +
              std::to_string(needed));
    double thinnest = 2 * b.radius / sc.spacing;
    if (b.shape == "box") {
      thinnest = 1e300;
      for (int a = 0; a < sc.dimension; ++a)
        if (b.endless.empty() || !b.endless[a])
          thinnest = std::min(thinnest, (b.max[a] - b.min[a]) / sc.spacing);
    }
    if (!b.container && thinnest < needed - 1e-9) {
      std::ostringstream m;
      m << label << "is " << thinnest << " spacings thick; method mps needs " << needed
        << " (its first layer's dummy particles behind it: wall_pressure_layers + floor(r_e / spacing))";
      val.fail_entry(root, "solid", i, b.shape == "box" ? "max" : "radius", m.str());
    }
  }
}

}  // namespace

MethodSpec mps_spec() {
  MethodSpec spec;
  spec.doc =
      "moving particle semi-implicit (pressure from a Poisson equation each step, solved as set in [solver]; "
      "docs/mps.md)";
  spec.keys = mps_keys();
  spec.hooks.kernel = [](const Scene&) { return std::string("mps"); };
  spec.hooks.smoothing_ratio = [](const Scene& sc) { return sc.dimension == 2 ? 3.1 : 2.1; };
  spec.hooks.solves_pressure = true;
  spec.hooks.step_motion = 2.5;  // |u*| dt below 1.25 cfl l0 per particle (mps.cpp)
  // Peak resident, 4 steps of the dam break (2026-11-29): 2D 1,524 bytes per particle between 43k
  // and 149k particles, 3D 1,566 between 74k and 349k.
  spec.hooks.bytes_per_particle = [](int dimension) { return dimension == 2 ? 1700.0 : 1800.0; };
  spec.hooks.resolve = resolve;
  spec.hooks.validate = validate;
  return spec;
}

}  // namespace ryushi
