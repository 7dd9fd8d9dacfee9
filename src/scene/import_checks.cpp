// [[import]]'s particles against the rest of the scene, as [[fluid]] blocks are checked: none
// inside a [[solid]] (or outside a container), in a [[wall]]'s particle layers (below the floor,
// on a wall particle), inside a [[fluid]] block, or on top of another imported particle. Each is
// bad input at the import's `file` key naming the particle's position.
#include <cmath>
#include <cstdint>
#include <sstream>
#include <unordered_map>

#include "geometry/solid_shape.hpp"
#include "scene/load_common.hpp"
#include "scene/load_parts.hpp"
#include "scene/validator.hpp"

namespace ryushi {

namespace {

std::string place(const std::array<double, 3>& p, int D) {
  std::ostringstream m;
  m << "(" << p[0] << ", " << p[1];
  if (D == 3) m << ", " << p[2];
  m << ")";
  return m.str();
}

// How far x lies beyond wall box w's surface into its layers (0: in its interior, or not within
// its layers at all: beyond the outermost layer, past an open end or above an open top).
double depth_in_layers(const std::array<double, 3>& x, const WallBox& w, double spacing, int D) {
  double beyond = 0;
  for (int a = 0; a < D; ++a) {
    const bool open_end = a < static_cast<int>(w.open_ends.size()) && w.open_ends[a];
    const double thick = w.layers * spacing;
    const double below = w.min[a] - x[a], above = x[a] - w.max[a];
    if (open_end) {
      if (below > 0 || above > 0) return 0;  // outside the channel's length: no wall there
      continue;
    }
    if (below > thick || above > (a + 1 == D && w.open_top ? 0.0 : thick)) return 0;
    beyond = std::max({beyond, below, above});
  }
  return beyond;
}

}  // namespace

void check_imports(toml::table& root, Validator& val, const Scene& sc, bool walls_hold_particles) {
  const int D = sc.dimension;
  const double d = sc.spacing;
  const SceneEntries at{root, sc};
  auto refuse = [&](std::size_t i, const std::string& what) {
    val.fail(at.where("import", i, "file"), path_of("import", i, "file"),
             "[[import]] #" + std::to_string(i) + ": " + what);
  };
  // Imported particles are placed as given, not cut around bodies: one inside a body (outside a
  // container) is an error. Not one merely near it: a body's first wall layer lies half a spacing
  // inside its surface (a container's outside it), and a settled run's fluid comes as close as
  // that to the surface, closer than the generator's margin (a round tank's own frame was refused
  // when the test was half a spacing).
  for (std::size_t i = 0; i < sc.imports.size() && !sc.solids.empty(); ++i) {
    auto overlap = [&](auto dim) {
      constexpr int DD = decltype(dim)::value;
      for (std::size_t k = 0; k < sc.solids.size(); ++k) {
        SolidShape<DD> shape(sc.solids[k],
                             sc.solids[k].mesh >= 0 ? sc.meshes[sc.solids[k].mesh].mesh : nullptr);
        for (auto& p : sc.imports[i].particles->position) {
          Vec<DD> x;
          for (int a = 0; a < DD; ++a) x[a] = p[a];
          if (shape.within(x, 0.0))
            refuse(i, "a particle at " + place(p, D) + " lies " +
                          (sc.solids[k].container ? "outside container '" : "in [[solid]] '") +
                          sc.solids[k].name + "'");
        }
      }
    };
    if (D == 2)
      overlap(std::integral_constant<int, 2>{});
    else
      overlap(std::integral_constant<int, 3>{});
  }
  // A wall's first layer lies half a spacing beyond its surface; fluid that settled against the
  // wall stays on this side of the surface. A quarter spacing beyond it is inside the layers.
  for (std::size_t i = 0; i < sc.imports.size() && walls_hold_particles; ++i)
    for (auto& p : sc.imports[i].particles->position)
      for (std::size_t k = 0; k < sc.walls.size(); ++k)
        if (depth_in_layers(p, sc.walls[k], d, D) > 0.25 * d)
          refuse(i, "a particle at " + place(p, D) + " lies in the " + std::to_string(sc.walls[k].layers) +
                        " particle layers of [[wall]] #" + std::to_string(k) +
                        " (more than a quarter spacing beyond its min..max)");
  // A block's particles fill its box min..max to half a spacing from its faces.
  for (std::size_t i = 0; i < sc.imports.size(); ++i)
    for (auto& p : sc.imports[i].particles->position)
      for (std::size_t k = 0; k < sc.fluid.size(); ++k) {
        bool inside = true;
        for (int a = 0; a < D; ++a) inside = inside && p[a] > sc.fluid[k].min[a] && p[a] < sc.fluid[k].max[a];
        if (inside)
          refuse(i, "a particle at " + place(p, D) + " lies in [[fluid]] #" + std::to_string(k) +
                        " (their particles would sit on each other)");
      }
  // Two particles at one point (a frame imported twice, a CSV with a repeated row): r = 0 pairs.
  // Closer than a hundredth of a spacing, on a grid of that size (each point against its cell's
  // 3^D neighbourhood).
  const double cell = 0.01 * d;
  std::unordered_map<std::int64_t, std::vector<std::pair<std::size_t, std::size_t>>> grid;
  auto key = [&](const std::array<double, 3>& p, int dx, int dy, int dz) {
    const std::int64_t ix = std::llround(std::floor(p[0] / cell)) + dx,
                       iy = std::llround(std::floor(p[1] / cell)) + dy,
                       iz = std::llround(std::floor(p[2] / cell)) + dz;
    return (ix * 73856093) ^ (iy * 19349663) ^ (iz * 83492791);
  };
  for (std::size_t i = 0; i < sc.imports.size(); ++i) {
    const auto& points = sc.imports[i].particles->position;
    for (std::size_t n = 0; n < points.size(); ++n) {
      const auto& p = points[n];
      for (int dx = -1; dx <= 1; ++dx)
        for (int dy = -1; dy <= 1; ++dy)
          for (int dz = (D == 3 ? -1 : 0); dz <= (D == 3 ? 1 : 0); ++dz) {
            auto found = grid.find(key(p, dx, dy, dz));
            if (found == grid.end()) continue;
            for (auto [j, m] : found->second) {
              const auto& q = sc.imports[j].particles->position[m];
              double r2 = 0;
              for (int a = 0; a < D; ++a) r2 += (p[a] - q[a]) * (p[a] - q[a]);
              if (r2 < cell * cell)
                refuse(i, "a particle at " + place(p, D) + " lies on one of [[import]] #" +
                              std::to_string(j) + " at " + place(q, D) + " (closer than 0.01 spacing)");
            }
          }
      grid[key(p, 0, 0, 0)].push_back({i, n});
    }
  }
}

}  // namespace ryushi
