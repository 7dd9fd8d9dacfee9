// The [[probe]] section of the scene schema (schema.cpp): the probe types and their keys.
#include "scene/schema.hpp"

namespace ryushi {

SectionSpec probe_section() {
  using namespace keyspec;
  using K = KeyType;
  return {
      "probe",
      true,
      false,
      "Measurements written to probes.csv (one column each).",
      {{"name", K::String, "", "", "Column name.", true},
       choice("type", "",
              "pressure: kernel-interpolated (Shepard) fluid pressure at `position`; velocity: "
              "component `axis` of the fluid velocity at `position`, interpolated the same way (m/s; with `end` and "
              "`points` a line of them); surge_front: the "
              "leading edge of the water body, max x + d/2 over the fluid particles with another fluid "
              "particle within 2 d (a droplet thrown ahead is not the front; docs/output.md); water_height: "
              "surface elevation of the water column standing on `position` (where the kernel-interpolated "
              "fill fraction, walls discounted, first falls below 1/2 going up; drops and wall films above "
              "a gap do not count; docs/output.md); kinetic_energy: sum of m |v|^2 / 2 over the fluid (J, "
              "per metre of depth in 2D); potential_energy: sum of -m g . x over the fluid (zero at the "
              "origin); particle_count: the number of fluid particles (grows with particle splitting); "
              "front_depth: swe only, the depth of the foremost particle (largest x).; force: component "
              "`axis` of the force of the fluid on the [[solid]] named `solid` (N; N/m in 2D), pressure and "
              "viscosity: the wall sensors' surface pressure (wall_pressure below) at the surface in front "
              "of each "
              "of the body's first-layer particles times its share of the surface and normal, for every "
              "method, plus the wall shear as the method's viscous term sees it (wcsph: the reaction to its "
              "Morris pair term; mps: to its own viscous term; isph: mu (fluid velocity - wall velocity "
              "along the wall) / distance, Shepard averages of the fluid beside each particle; "
              "docs/geometry.md); "
              "solid_displacement: component `axis` of the displacement of the [[elastic]] particle that "
              "started nearest `position` (a plate's tip deflection, m); solid_stress: the stress component "
              "sigma(axis, axis) of that particle (Pa; sigma = -p I + s, tension positive); solid_energy: "
              "the elastic bodies' kinetic plus strain energy, sum of m |v|^2 / 2 + V (s:s / (4 G) + p^2 / "
              "(2 K)) (J; J/m in 2D); wall_pressure: a pressure sensor on a wall or body surface at "
              "`position` facing along `normal`, the fluid's pressure on its face of `diameter` (Pa): the "
              "mean over the face of the Shepard average of the fluid pressures within 2 d, each carried to "
              "the face along rho0 (g - a_wall), the same for every method and wall type (docs/output.md)",
              {"pressure", "velocity", "surge_front", "water_height", "kinetic_energy", "potential_energy",
               "particle_count", "front_depth", "force", "solid_displacement", "solid_stress", "solid_energy",
               "wall_pressure"},
              true),
       {"position", K::Vector, "m", "",
        "Where to measure (pressure, velocity; for water_height the base of the vertical line, which "
        "reads this height when dry; for wall_pressure the centre of the sensor's face, on the wall's "
        "surface: within a spacing of the first wall layer, which lies d/2 behind it)."},
       {"end", K::Vector, "m", "",
        "pressure, velocity: the other end of a line of `points` probes from `position` (both ends "
        "included), written as the columns NAME_0 ... NAME_{points-1} (a velocity profile along a "
        "cavity's centreline; docs/output.md)."},
       ranged(
           {"points", K::Integer, "", "", "pressure, velocity with `end`: how many probes the line holds."},
           2, 10000),
       {"normal", K::Vector, "", "",
        "wall_pressure: the direction the sensor faces, out of the wall into the fluid (made unit; "
        "required)."},
       positive(
           "diameter", "m", "",
           "wall_pressure: the width of the sensor's face (a disc in 3D, a segment across the normal in 2D; "
           "required). Experiments' sensors are a few mm wide; the reading is averaged over the face."),
       {"solid", K::String, "", "", "force: the [[solid]] (its name) the fluid pushes on."},
       positive("reference_speed", "m/s", "",
                "force, with reference_length: the probe reads the force coefficient F / (rho0 U^2 L / 2) "
                "(2D, F per unit depth; 3D: F / (rho0 U^2 L^2 / 2)) instead of the force: the drag (axis "
                "along the flow) and lift coefficients of a body of size L in a stream of speed U."),
       positive("reference_length", "m", "",
                "force, with reference_speed: the body's size L (a cylinder's diameter) in the coefficient."),
       ranged({"axis", K::Integer, "", "0",
               "force, solid_displacement, solid_stress, velocity: the component (0 = x, 1 = y, 2 = z)."},
              0, 2)}};
}

}  // namespace ryushi
