#pragma once
// The scene loader's parts, each reading some sections of the validated tree into the Scene
// (loader.cpp calls them in order; load_elastic.hpp and load_heat_rheology.hpp are two more).
#include <toml++/toml.h>

#include <string>

namespace ryushi {

struct Scene;
class Validator;

// Applies one `section.key=value`, `section.table.key=value` or `section.N.key=value` override.
void apply_override(toml::table& root, const std::string& text, Validator& val);
// [[mesh]], [[fluid]], [[import]], [[wall]], [[solid]] and [[fixed_pressure]], with the checks
// across them (overlaps, containers); walls and solids without `layers` take default_layers,
// and must cover the support (covering layers) unless the method keeps fewer.
void load_bodies(toml::table& root, Validator& val, Scene& sc, int default_layers, int covering);
// import_checks.cpp: imported particles inside solids, wall layers or fluid blocks, or on top of
// each other (after the blocks, walls and solids are read).
void check_imports(toml::table& root, Validator& val, const Scene& sc, bool walls_hold_particles);
// [[probe]] and [[metric]] (reference tables read and checked).
void load_measurements(toml::table& root, Validator& val, Scene& sc);
// load_health.cpp: [health], and the refusal (at particles.smoothing_ratio) of a kernel whose
// support is too small for the lattice: its gradient of a linear field more than 10% off.
void load_health(const toml::table& root, Scene& sc);
void check_kernel_support(const toml::table& root, Validator& val, const Scene& sc);

}  // namespace ryushi
