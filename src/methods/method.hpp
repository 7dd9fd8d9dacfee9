#pragma once
// A method is a registered recipe, like a system: its own file fills the world from the scene
// and returns the step pipeline, the first time step and the context the driver and the
// [[systems]] need, and registers itself by name next to that code:
//
//   template <int D> MethodSetup<D> build_my_method(const Scene&, World<D>&, const PipelineOptions&);
//   RYUSHI_REGISTER_METHOD("my_method", my_method_spec(), build_my_method);
//
// where my_method_spec() returns the MethodSpec (scene/registered_keys.hpp): the line for
// docs/scenes.md, the method's [method] keys (read by the builder from scene.method_params) and
// its hooks (default kernel, wall layers, checks). The driver, the loader and build_method know
// no method by name.
#include <filesystem>
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "ecs/system.hpp"
#include "methods/method_context.hpp"
#include "methods/system_registry.hpp"  // RYUSHI_CONCAT
#include "scene/scene.hpp"

namespace ryushi {

struct PipelineOptions {
  std::filesystem::path dump_matrix_dir;  // empty: no dump
  long long dump_step = 0;
};

template <int D>
struct MethodSetup {
  MethodContext<D> context;
  std::vector<SystemPtr<D>> pipeline;
  double first_dt = 0;
  std::string summary;  // one phrase for the start-up log line, e.g. "c0 = 19.8 m/s"
  // Figures of the method written under "parameters" in summary.json, e.g. {"sound_speed", c0}.
  std::vector<std::pair<std::string, double>> parameters;
  // The method's own conservation figures, written under "diagnostics" in summary.json with
  // every frame (e.g. MPS: the interior number density against n0). Empty: none.
  std::function<std::vector<std::pair<std::string, double>>(const World<D>&, const Resources&)> diagnostics;
  // MPS density is rho0 n*/n0, a diagnostic: an isolated splash particle has n* = 0. WCSPH
  // divides by density, so there zero is a failure.
  bool density_may_vanish = false;
  // The cell of the neighbour search's grid (its radius plus the Verlet skin; build_method finds
  // it in the pipeline). The driver sorts the particles by a grid of this cell before the first
  // step, so the first list comes out in that grid's order; 0: no such search.
  double search_cell = 0;
  // Per-particle fields its physics makes worth seeing, written to every frame besides the
  // default ones and [output] fields (temperature, the apparent viscosity).
  std::vector<std::string> frame_fields;
  // Steps run before t = 0 with the velocities damped, so that a fluid at rest starts in the
  // discrete equilibrium near the scene's lattice (app/settle.hpp); 0: the lattice as it is.
  long settle_steps = 0;
};

template <int D>
using MethodBuilder = std::function<MethodSetup<D>(const Scene&, World<D>&, const PipelineOptions&)>;

struct MethodRegistryEntry {
  MethodBuilder<2> build2;
  MethodBuilder<3> build3;
};

// Registers the builders here and the spec with the scene loader. Throws std::logic_error for a
// name already registered (by ryushi or a plugin).
bool register_method(const std::string& name, MethodSpec spec, MethodRegistryEntry entry);
void unregister_method(const std::string& name);
std::vector<std::string> method_names();  // sorted
const MethodRegistryEntry& method_registry_entry(const std::string& name);

// The scene's method, with the scene's [[systems]] appended. Throws SceneError when the options
// do not fit the method (a matrix dump of an explicit method).
template <int D>
MethodSetup<D> build_method(const Scene& scene, World<D>& world, const PipelineOptions& options = {});

// Throws SceneError: `--dump-matrix` given to a method that assembles no linear system.
void refuse_matrix_dump(const Scene& scene, const PipelineOptions& options);

#define RYUSHI_REGISTER_METHOD(NAME, SPEC, BUILD)                                                 \
  [[maybe_unused]] static const bool RYUSHI_CONCAT(ryushi_method_registered_, __LINE__) =        \
      ::ryushi::register_method(NAME, SPEC, ::ryushi::MethodRegistryEntry{BUILD<2>, BUILD<3>})

}  // namespace ryushi
