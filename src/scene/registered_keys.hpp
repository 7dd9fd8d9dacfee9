#pragma once
// What the scene loader needs to know of the registered methods and systems, registered next to
// their code (RYUSHI_REGISTER_METHOD, RYUSHI_REGISTER_SYSTEM in src/methods/): a method's [method]
// keys and the hooks that give the scene's defaults and checks that depend on the method; a
// system's [[systems]] keys. The loader holds no method's name and no method's rule: it asks this
// registry. The scene layer owns it (methods, built on top of the scene, fill it), so the loader
// includes nothing above it.
#include <toml++/toml.h>

#include <functional>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "scene/schema.hpp"

namespace ryushi {

struct Scene;
class Validator;

// A method's validated [method] table: every key of the method, defaults inserted, and the
// set of keys the scene gave (a default that depends on the scene asks whether its key was given).
class MethodParams {
 public:
  MethodParams() = default;
  MethodParams(toml::table values, std::set<std::string> given)
      : values_(std::move(values)), given_(std::move(given)) {}
  double number(const std::string& key) const;
  long long integer(const std::string& key) const;
  bool flag(const std::string& key) const;
  std::string text(const std::string& key) const;
  bool has(const std::string& key) const { return values_.contains(key); }  // a value, given or default
  bool given(const std::string& key) const { return given_.count(key) != 0; }
  // A default that depends on the scene (a method's resolve hook): the key keeps `value`.
  template <class T>
  void set(const std::string& key, T value) {
    values_.insert_or_assign(key, std::move(value));
  }
  const toml::table& table() const { return values_; }

 private:
  const toml::node& at(const std::string& key) const;
  toml::table values_;
  std::set<std::string> given_;
};

// The scene's defaults and checks that depend on its method. Each is optional.
struct MethodHooks {
  // [particles] kernel and smoothing_ratio when the scene leaves them out (they may depend on the
  // dimension and on the [method] keys, read before them).
  std::function<std::string(const Scene&)> kernel;
  std::function<double(const Scene&)> smoothing_ratio;
  double cfl = 0.2;               // [time] cfl when left out
  double jacobi_weight = 1.0;     // [solver] jacobi_weight when left out
  std::string shifting = "none";  // [shifting] model when left out
  bool solves_pressure = false;   // reads [solver] (its pressure equation)
  bool multiphysics = false;      // models [material] rheology, activation_energy and conductivity
  // The most a particle moves in one step, in cfl spacings: the neighbour search's radius grows
  // by it (a periodic axis must hold three such radii).
  double step_motion = 0;
  // The method's own sections (MethodSpec::owns), read right after [method]: the defaults of
  // the plain sections (kernel, smoothing ratio) may depend on them.
  std::function<void(Scene&, const toml::table& root, Validator&)> read_sections;
  // [[wall]] boxes are layers of wall particles around min..max (false: the shallow water's
  // mirror lines, which hold none, so a fluid block cannot reach into them).
  bool walls_hold_particles = true;
  // [health] density_deviation when left out: the largest |rho / rho0 - 1| the method's
  // assumptions allow (none: the method's density is not a state that can drift, not checked).
  std::function<double(const Scene&)> health_density_deviation;
  // Whether [health]'s energy, pressure and wall checks apply (the shallow water's particles carry
  // a depth, not a pressure, and its energy is not the 3D fluid's).
  bool health_fluid_checks = true;
  // Peak resident bytes per particle of a run (columns, neighbour list, solver) at the default
  // neighbour skin, by dimension, for the memory estimate made before anything is allocated
  // (app/memory_estimate.hpp; unset: the estimate takes 3,000, more than any built-in method).
  std::function<double(int dimension)> bytes_per_particle;
  // After the scene's plain sections are read and before its geometry: defaults that depend on
  // the scene (which may set keys of the method's table) and the checks of the method's keys
  // against the rest of the scene. The root is the parsed file with --set applied, for the
  // places of errors.
  std::function<void(Scene&, const toml::table& root, Validator&)> resolve;
  // The default `layers` of [[wall]] and [[solid]] (0: enough to cover the kernel support).
  std::function<int(const Scene&)> wall_layers;
  // After the whole scene is read: the checks across sections (geometry, probes) of the method.
  std::function<void(const Scene&, const toml::table& root, Validator&)> validate;
  // What the method's step offers the [[systems]] that need it (SystemKeys::needs), given the
  // scene's [method] keys; unset: nothing.
  std::function<std::vector<std::string>(const Scene&)> provides;
};

struct MethodSpec {
  std::string doc;            // one line for docs/scenes.md
  std::vector<KeySpec> keys;  // its [method] keys besides name
  // Sections ("swe"), keys of other sections ("time.step_rule", "fluid.depth" in any [[fluid]])
  // and values of such keys ("probe.type=front_depth") only this method reads: a scene of
  // another method that writes one is an error there.
  std::vector<std::string> owns;
  // [method] keys this method once had, each with what replaced it ("use pressure_gradient =
  // \"corrected\""): a scene that still writes one is bad input at the key, naming the
  // replacement, not an unknown key.
  std::map<std::string, std::string> retired;
  MethodHooks hooks;
};

// False for a name registered twice, which is recorded: while a plugin loads for the plugin
// loader (begin_plugin_registrations), else in built_in_registration_clashes().
bool register_method_spec(const std::string& name, MethodSpec spec);
void unregister_method_spec(const std::string& name);  // a plugin that failed to load
std::vector<std::string> method_spec_names();          // sorted
const MethodSpec* find_method_spec(const std::string& name);
// The methods (sorted) that declare `key` among their [method] keys.
std::vector<std::string> methods_owning_key(const std::string& key);

// A registered system's [[systems]] keys (besides name) and its line for docs/scenes.md.
// `needs`: what the scene's method must provide for the system to run (MethodHooks::provides),
// e.g. "free_surface_pressure": free-surface rows whose Dirichlet value a system may set.
// `validate`: the checks across sections of a system's entry (the `entry`th of [[systems]]),
// after the whole scene is read; unset: none.
struct SystemKeys {
  std::string doc;
  std::vector<KeySpec> keys;
  std::vector<std::string> needs{};
  std::function<void(const Scene&, const toml::table& root, std::size_t entry, Validator&)> validate{};
};
bool register_system_keys(const std::string& name, SystemKeys keys);  // as register_method_spec
void unregister_system_keys(const std::string& name);
std::vector<std::string> system_key_names();  // sorted
const SystemKeys* find_system_keys(const std::string& name);
// Changes whenever a method or system is registered or removed (the schema's docs follow it).
unsigned long registered_keys_generation();

// A plugin library registers its methods and systems from its static initialisers, inside
// dlopen, where an exception would end the program. Between begin and end, a name already taken
// is recorded as a clash instead of thrown, and what was registered is listed, so the loader
// can report the clash (exit 2) and take the plugin's names back out.
struct PluginRegistrations {
  std::vector<std::string> methods, systems;  // registered while the plugin loaded
  std::vector<std::string> clashes;           // e.g. "method 'wcsph'"
};
// Names registered twice by the program itself (two of its translation units, or an in-tree
// extension, taking one name), e.g. "method 'wcsph'": main() refuses to run with any.
const std::vector<std::string>& built_in_registration_clashes();
void begin_plugin_registrations();
PluginRegistrations end_plugin_registrations();

}  // namespace ryushi
