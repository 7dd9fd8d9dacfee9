#include "app/memory_estimate.hpp"

#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <numbers>
#include <sstream>

#include "geometry/triangle_mesh.hpp"
#include "scene/registered_keys.hpp"

namespace ryushi {

namespace {

// A method without a figure of its own (a plugin): more than any built-in method measured.
constexpr double kUnknownMethodBytes = 3000;
// The process before its particles: the binary, TBB's and HDF5's start (20-25 MB measured).
constexpr double kBaseBytes = 32.0 * (1 << 20);

// Lattice cells of [lo, hi] grown by `grow` spacings on each side (axes not in `grown`: not grown).
double cells(const std::vector<double>& lo, const std::vector<double>& hi, double d, double grow,
             const std::vector<bool>& grown) {
  double n = 1;
  for (std::size_t a = 0; a < lo.size(); ++a)
    n *= std::max(0.0, std::round((hi[a] - lo[a]) / d) + (grown[a] ? 2 * grow : 0.0));
  return n;
}

double fluid_particles(const Scene& s, const FluidBlock& b) {
  const int D = s.dimension;
  const double d = s.spacing;
  const double box = cells(b.min, b.max, d, 0, std::vector<bool>(D, false));
  if (b.mesh >= 0) return std::min(box, s.meshes[b.mesh].mesh->volume() / std::pow(d, 3));
  if (b.shape == "sphere") return std::min(box, 4.0 / 3.0 * std::numbers::pi * std::pow(b.radius / d, 3));
  if (b.shape == "cylinder") {
    const double disc = std::numbers::pi * std::pow(b.radius / d, 2);
    return std::min(box, D == 2 ? disc : disc * (b.max[b.axis] - b.min[b.axis]) / d);
  }
  return box;
}

double wall_particles(const Scene& s, const WallBox& w) {
  const int D = s.dimension;
  std::vector<double> hi = w.max;
  std::vector<bool> grown(D, true);
  for (int a = 0; a < D; ++a)
    if (a < static_cast<int>(w.open_ends.size()) && w.open_ends[a]) grown[a] = false;
  // An open top: the layers below only (grow both sides, then take the top's away).
  double outer = cells(w.min, hi, s.spacing, w.layers, grown);
  if (w.open_top && grown[D - 1])
    outer *= 1 - w.layers / (std::round((w.max[D - 1] - w.min[D - 1]) / s.spacing) + 2.0 * w.layers);
  return std::max(0.0, outer - cells(w.min, w.max, s.spacing, 0, grown));
}

double solid_particles(const Scene& s, const SolidSpec& b) {
  const int D = s.dimension;
  const double d = s.spacing, layers = b.layers;
  if (b.mesh >= 0) return s.meshes[b.mesh].mesh->area() / (d * d) * layers * 1.5;  // corners, curvature
  const double r = b.radius + (b.container ? layers * d : 0.0);
  if (b.shape == "sphere") return 4 * std::numbers::pi * r * r / (d * d) * layers;
  if (b.shape == "cylinder") {
    const double ring = 2 * std::numbers::pi * r / d * layers;
    return D == 2 ? ring : ring * (s.domain_max[b.axis] - s.domain_min[b.axis]) / d;
  }
  // A box: its layers inside it, or outside it for a container.
  const std::vector<bool> grown(D, true);
  return b.container ? cells(b.min, b.max, d, layers, grown) - cells(b.min, b.max, d, 0, grown)
                     : cells(b.min, b.max, d, 0, grown) - cells(b.min, b.max, d, -layers, grown);
}

// The smallest (limit - usage) of this process's cgroup and its ancestors (v2), or of the v1
// memory controller; infinity where there is no limit.
double cgroup_headroom() {
  auto read_number = [](const std::string& file, double& value) {
    std::ifstream in(file);
    std::string text;
    if (!(in >> text) || text == "max") return false;
    try {
      value = std::stod(text);
    } catch (const std::exception&) {
      return false;
    }
    return true;
  };
  double headroom = INFINITY;
  std::ifstream groups("/proc/self/cgroup");
  std::string line;
  while (std::getline(groups, line)) {
    if (line.rfind("0::", 0) != 0) continue;
    std::string path = line.substr(3);
    while (true) {
      double limit = 0, usage = 0;
      const std::string dir = "/sys/fs/cgroup" + (path == "/" ? std::string() : path);
      if (read_number(dir + "/memory.max", limit) && read_number(dir + "/memory.current", usage))
        headroom = std::min(headroom, limit - usage);
      if (path.empty() || path == "/") break;
      path = path.substr(0, path.rfind('/'));
    }
  }
  double limit = 0, usage = 0;
  if (read_number("/sys/fs/cgroup/memory/memory.limit_in_bytes", limit) && limit < 1e18 &&
      read_number("/sys/fs/cgroup/memory/memory.usage_in_bytes", usage))
    headroom = std::min(headroom, limit - usage);
  return headroom;
}

}  // namespace

MemoryEstimate estimate_memory(const Scene& s) {
  MemoryEstimate e;
  for (auto& b : s.fluid) e.particles += fluid_particles(s, b);
  for (auto& i : s.imports) e.particles += i.particles ? double(i.particles->position.size()) : 0.0;
  for (auto& e_body : s.elastic)
    e.particles += cells(e_body.min, e_body.max, s.spacing, 0, std::vector<bool>(s.dimension, false));
  const MethodSpec* method = find_method_spec(s.method);
  if (!method || method->hooks.walls_hold_particles)
    for (auto& w : s.walls) e.particles += wall_particles(s, w);
  for (auto& b : s.solids) e.particles += solid_particles(s, b);
  const double per_particle = method && method->hooks.bytes_per_particle
                                  ? method->hooks.bytes_per_particle(s.dimension)
                                  : kUnknownMethodBytes;
  e.bytes = kBaseBytes + e.particles * per_particle;
  return e;
}

AvailableMemory available_memory() {
  AvailableMemory m{INFINITY, ""};
  std::ifstream info("/proc/meminfo");
  std::string key;
  double kib = 0;
  std::string unit;
  while (info >> key >> kib >> unit)
    if (key == "MemAvailable:") m = {kib * 1024, "MemAvailable in /proc/meminfo"};
  const double cgroup = cgroup_headroom();
  if (cgroup < m.bytes) m = {std::max(0.0, cgroup), "the cgroup's memory limit less its usage"};
  // `ulimit -v` (RLIMIT_AS) less the address space the process holds already.
  rlimit limit{};
  if (getrlimit(RLIMIT_AS, &limit) == 0 && limit.rlim_cur != RLIM_INFINITY) {
    double pages = 0;
    std::ifstream("/proc/self/statm") >> pages;
    const double headroom = double(limit.rlim_cur) - pages * double(sysconf(_SC_PAGESIZE));
    if (headroom < m.bytes) m = {std::max(0.0, headroom), "ulimit -v less the address space in use"};
  }
  return m;
}

std::string format_bytes(double bytes) {
  char text[48];
  if (bytes >= 1024.0 * 1024 * 1024)
    std::snprintf(text, sizeof text, "%.3g GiB", bytes / (1024.0 * 1024 * 1024));
  else
    std::snprintf(text, sizeof text, "%.3g MiB", bytes / (1024.0 * 1024));
  return text;
}

void guard_memory(const Scene& s, const MemoryEstimate& e) {
  const AvailableMemory available = available_memory();
  if (!(e.bytes > available.bytes)) return;
  std::ostringstream m;
  m.precision(3);
  m << s.path << ": the scene's about " << e.particles << " particles need about " << format_bytes(e.bytes)
    << " (" << s.method << ", " << s.dimension << "D), more than the " << format_bytes(available.bytes)
    << " available (" << available.source
    << "); make particles.spacing larger (the count goes as its power of -" << s.dimension
    << ") or the fluid smaller";
  throw SceneError(m.str());
}

}  // namespace ryushi
