#pragma once
// The memory guard: before a run or `check` allocates a particle, the scene's particle count is
// estimated from its geometry (lattice cells of the fluid blocks, wall shells and body layers,
// imported particles) and multiplied by the method's measured peak bytes per particle
// (MethodHooks::bytes_per_particle); a scene that would need more than the memory available to
// this process (MemAvailable, the cgroup's limit less its usage, ulimit -v less the address
// space in use) is bad input, refused
// before it ends in std::bad_alloc or the kernel's OOM killer.
#include <cstddef>
#include <string>

#include "scene/scene.hpp"

namespace ryushi {

struct MemoryEstimate {
  double particles = 0;  // upper estimate: solids are not cut out of the fluid blocks
  double bytes = 0;      // at the start (a shallow-water run that splits particles grows)
};

struct AvailableMemory {
  double bytes = 0;
  std::string source;  // "MemAvailable", "the cgroup's limit", ... (what bounded it)
};

MemoryEstimate estimate_memory(const Scene& scene);
AvailableMemory available_memory();
// Throws SceneError("<scene>: the scene's ~N particles need about X GiB ..., Y GiB available
// (<source>); ...") when the estimate exceeds what is available.
void guard_memory(const Scene& scene, const MemoryEstimate& estimate);
// "1.2 GiB", "340 MiB".
std::string format_bytes(double bytes);

}  // namespace ryushi
