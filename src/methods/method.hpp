#pragma once
// One entry point for every method: fills the world from the scene and returns the step
// pipeline, the first time step and the physical constants the driver needs (probes, health
// check, diagnostics, registered [[systems]]). The driver knows no method by name.
#include <filesystem>
#include <string>
#include <vector>

#include "ecs/system.hpp"
#include "scene/scene.hpp"
#include "systems/fluid/wcsph_parameters.hpp"

namespace ryushi {

struct PipelineOptions {
  std::filesystem::path dump_matrix_dir;  // empty: no dump
  long long dump_step = 0;
};

template <int D>
struct MethodSetup {
  // Kernel, domain, gravity, rho0 of the scene (c0 only means something for wcsph).
  WcsphParameters<D> physics;
  std::vector<SystemPtr<D>> pipeline;
  double first_dt = 0;
  std::string summary;  // one phrase for the start-up log line, e.g. "c0 = 19.8 m/s"
  // MPS density is rho0 n*/n0, a diagnostic: an isolated splash particle has n* = 0. WCSPH
  // divides by density, so there zero is a failure.
  bool density_may_vanish = false;
};

// Throws SceneError when the options do not fit the method (a matrix dump of an explicit method).
template <int D>
MethodSetup<D> build_method(const Scene& scene, World<D>& world, const PipelineOptions& options = {});

}  // namespace ryushi
