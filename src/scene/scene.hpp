#pragma once
// A validated scene: plain values with every default resolved. Produced only by load_scene,
// which reports any problem as SceneError("file:line:column: message").
#include <toml++/toml.h>

#include <cmath>
#include <cstdint>
#include <limits>
#include <memory>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "functions/motion_table.hpp"
#include "geometry/bed.hpp"
#include "geometry/shape_spec.hpp"
#include "geometry/triangle_mesh.hpp"
#include "materials/rheology.hpp"
#include "scene/particle_import.hpp"
#include "scene/registered_keys.hpp"
#include "solvers/solver_options.hpp"

namespace ryushi {

class SceneError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct FluidBlock {
  std::vector<double> min, max;
  std::vector<double> velocity;  // initial velocity (empty: at rest)
  // Initial fields as formulas of x, y, z (functions/expression.hpp): per axis, "" where `velocity`
  // holds a number; pressure "" for the method's own start (hydrostatic). *_where is the key's
  // "file:line:column", for errors found when the particles are made.
  std::vector<std::string> velocity_expression;
  std::string pressure_expression, velocity_where, pressure_where;
  int mesh = -1;  // only the lattice points inside this [[mesh]] (index; -1: the whole box)
  // Round blocks: only the lattice points within radius of centre (cylinder, sphere; "box": all).
  std::string shape = "box";
  std::vector<double> centre;
  double radius = 0;
  int axis = 2;
  double angular_velocity = 0;  // 2D: initial rigid rotation (omega (y - yc), -omega (x - xc))
  // swe: the water depth, or the surface elevation (depth = surface - bed), NaN when not given.
  double depth = std::numeric_limits<double>::quiet_NaN();
  double surface_elevation = std::numeric_limits<double>::quiet_NaN();
  double temperature = std::numeric_limits<double>::quiet_NaN();  // K (NaN: [material] temperature)
};
// A wall's or body's thermal condition in a scene with heat: a fixed temperature (Dirichlet), a
// heat flux into the fluid (Neumann), or neither (adiabatic).
struct ThermalCondition {
  double temperature = std::numeric_limits<double>::quiet_NaN();  // K
  double heat_flux = std::numeric_limits<double>::quiet_NaN();    // W/m^2 into the fluid
  bool fixed() const { return !std::isnan(temperature); }
  bool flux() const { return !std::isnan(heat_flux); }
};
struct WallBox {
  std::vector<double> min, max;
  int layers = 3;
  bool open_top = true;
  std::vector<bool> open_ends;  // per axis: no wall at either end (a channel's inlet and outlet)
  ThermalCondition thermal;
};
// [[mesh]]: an STL surface placed in the scene (geometry/triangle_mesh.hpp), read and checked by
// the loader; fluid blocks fill it, solids are made of it.
struct MeshSpec {
  std::string name, file;
  std::shared_ptr<const TriangleMesh> mesh;
};
// [[solid]]: an obstacle, a plate or a lid, as `layers` of wall particles inside its shape
// (src/geometry/solid_shape.hpp). Fluid within half a spacing of it is cut out of the blocks.
struct SolidSpec : ShapeSpec {
  std::string name;
  int mesh = -1;                 // shape = "mesh": the [[mesh]]'s index
  std::vector<double> velocity;  // prescribed, constant (a lid, a plate); the particles stay put
  // Prescribed motion: per axis a formula of t and the particle's rest position x, y, z (the
  // particles move; empty: none). *_where: the key's place, for errors.
  std::vector<std::string> displacement;
  std::string displacement_where;
  std::vector<MotionSample> displacement_table;  // or tabulated (functions/motion_table.hpp)
  bool moves() const { return !displacement.empty() || !displacement_table.empty(); }  // its particles
  ThermalCondition thermal;
};
// [[elastic]]: a linear-elastic solid body of particles on the lattice in [min, max] (WCSPH;
// src/systems/elastic/). Particles inside [clamp_min, clamp_max] are held in place.
struct ElasticSpec {
  std::string name;
  std::vector<double> min, max, clamp_min, clamp_max;
  double density = 0, bulk_modulus = 0, shear_modulus = 0;
  FluidBlock initial;  // its initial velocity (numbers and formulas), read as a fluid block's
  double sound_speed() const { return std::sqrt((bulk_modulus + 4.0 / 3.0 * shear_modulus) / density); }
  bool clamped() const { return !clamp_min.empty(); }
};
// Fluid particles inside [min, max] at the start hold p = pressure + gradient . x (Dirichlet):
// the inlet and outlet of an Eulerian ISPH channel.
struct FixedPressureBox {
  std::vector<double> min, max, gradient;
  double pressure = 0;
};
struct ProbeSpec {
  std::string name, type;
  std::vector<double> position;
  int solid = -1, axis = 0;  // force: the [[solid]]'s index and the component
  std::vector<double> normal;  // wall_pressure
  double diameter = 0;         // wall_pressure
  // force: with both > 0 the probe reads the coefficient F / (rho0 U^2 L^(D-1) / 2) (drag, lift)
  double reference_speed = 0, reference_length = 0;
  // "file:line:col" of `position` and `normal`, for what only the particles can show (a sensor
  // off any wall, a normal into the wall: checked when the run starts).
  std::string position_where, normal_where;
};
// [[metric]] (src/metrics/metrics.hpp).
struct MetricSpec {
  std::string name, type, probe;
  std::string reference;                         // resolved path ("" : the type's default)
  std::vector<std::pair<double, double>> table;  // the reference, read and checked by the loader
  double width = 0;                              // dam_break_front: a (0: the first fluid block's width)
  double height_ratio = 0;  // dam_break_front: n^2, the column's height over a (0: the first block's)
  double surface = std::numeric_limits<double>::quiet_NaN();  // hydrostatic_pressure
  double max_shift = 0.3, t_max = 2.5;
  double force = std::numeric_limits<double>::quiet_NaN();  // poiseuille_profile: F, m/s^2
  double depth = std::numeric_limits<double>::quiet_NaN();  // ritter_depth: h0 (NaN: the first block's)
  std::vector<double> position;  // poiseuille_profile: (x of the column, y of the wall); ritter_depth:
                                 // (x of the dam); rotating_square_pressure: the square's centre
  double angular_velocity = 0;   // rotating_square_pressure: the first fluid block's
};
struct SystemSpec {
  std::string name;
  toml::table params;
};

// [solver]: SolverSpec, the options of an implicit method's linear solve (solvers/solver_options.hpp).

// [swe], [bed] and [splitting]: the shallow-water method (docs/swe.md).
struct SweSpec {
  double gravity = 9.81, manning = 0, influence_ratio = 1.3;
  bool slip = true, edge_correction = true;
  std::string momentum = "mps";
  // Ritter dry-bed dam-break reference (summary.json metrics); NaN: none.
  double ritter_dam_x = std::numeric_limits<double>::quiet_NaN(), ritter_depth = 0;
  bool splitting = true, split_along_gap = true;
  double split_area_ratio = 1.5, split_distance = 0.7;
  long long max_particles = 0;
  std::shared_ptr<Bed> bed = std::make_shared<Bed>();
};

// [[import]]: fluid particles read from a ryushi frame or a CSV (scene/particle_import.hpp).
struct ImportSpec {
  std::string file;
  std::shared_ptr<const ImportedParticles> particles;
};

// [health]: the run's physical checks after every step (app/health_monitor.hpp).
struct HealthSpec {
  bool warn = false;             // action = "warn": warn once per check and go on (default: stop, exit 3)
  double density_deviation = 0;  // |rho / rho0 - 1| that 2% of the fluid may exceed (0: not checked)
  double sound_speed = 0;        // c0: the density check waits a pressure wave's crossing of the fluid
  double energy_rise = 0.05;     // of the energy scale, above E(0) (0: not checked)
  double pressure_factor = 0;    // times the hydrostatic and dynamic pressure scale (0: not checked)
  bool wall_penetration = true;  // fluid particles deep inside static wall layers
};

struct Scene {
  std::string path, name, description;
  std::string text;  // the scene file's text as it was read (checkpoints keep it)
  int dimension = 2;
  std::vector<double> domain_min, domain_max;
  std::vector<bool> periodic;
  bool outflow_removes = false;  // [domain] outflow = "remove"
  double spacing = 0, smoothing_ratio = 1.5;
  double disorder = 0;     // fluid displaced by U[-disorder d, disorder d] per axis
  std::uint64_t seed = 1;  // of the disorder
  std::string kernel = "wendland_c2";
  int reorder_interval = 25;
  double neighbour_skin = 0.6;  // Verlet skin in spacings
  double density = 1000, viscosity = 0, sound_speed = 0, sound_speed_factor = 10, gamma = 7;
  Rheology rheology;  // [material] rheology and its parameters (viscosity: rheology.viscosity too)
  // Heat ([material] conductivity > 0, docs/multiphysics.md): k, c and the blocks' default start.
  double conductivity = 0, heat_capacity = 4186;
  double temperature = std::numeric_limits<double>::quiet_NaN();
  std::vector<double> gravity;
  std::string method = "wcsph";
  // The method's own [method] keys, validated against what it registered, defaults inserted
  // (scene/registered_keys.hpp); read by the method's builder.
  MethodParams method_params;
  // [shifting]
  std::string shifting_model = "density";
  double shifting_coefficient = 0.005;
  double fickian_coefficient = 2.0, anti_clumping = 0.2, max_shift = 0.2, xsph_epsilon = 0.5;
  SolverSpec solver;
  SweSpec swe;
  double end_time = 0, cfl = 0.2, fixed_dt = 0, dt_min = 1e-9;
  std::string step_rule = "cfl";  // wcsph: cfl or seed001 (seed 001 eq. 35)
  long long max_steps = 0;
  double steady_tolerance = 0, steady_window = 0;  // [time]: the steady-state stop (0: off)
  double output_interval = 0, probe_interval = 0, checkpoint_interval = 0;
  std::vector<std::string> output_fields;
  std::vector<FluidBlock> fluid;
  std::vector<WallBox> walls;
  std::vector<SolidSpec> solids;
  std::vector<ElasticSpec> elastic;
  std::vector<MeshSpec> meshes;
  std::vector<ImportSpec> imports;
  std::vector<FixedPressureBox> fixed_pressure;
  std::vector<ProbeSpec> probes;
  std::vector<MetricSpec> metrics;
  std::vector<SystemSpec> systems;
  HealthSpec health;

  double smoothing_length() const { return smoothing_ratio * spacing; }
  // Whether particles carry a temperature: conduction, or a viscosity that depends on it.
  bool models_heat() const { return conductivity > 0 || rheology.temperature_dependent(); }
  double support_radius() const;  // the kernel's support (2h for most kernels)
  // Height of the tallest fluid block along the last axis (for c0 and hydrostatics).
  double fluid_height() const;
  double gravity_magnitude() const;
  double resolved_sound_speed() const;
};

// Loads, applies `key=value` overrides (section.key or section.N.key) and validates.
// With `text`, that is the scene's text in place of the file's (a checkpoint's copy); `path` still
// names it in messages and places the files it refers to.
Scene load_scene(const std::string& path, const std::vector<std::string>& overrides = {},
                 const std::string* text = nullptr);

}  // namespace ryushi
