// Shallow-water MPS with dynamic particle splitting (Saigo & Koshizuka, seed 000; docs/swe.md)
// as a recipe, registered as "swe". Particles live in the plan view (x, y); each carries a volume
// V, a depth h and an area A = V / h. One step (src/systems/swe/swe_systems.hpp):
//   swe_influence_radius, swe_ghost_walls, swe_neighbour_search, swe_depth, swe_acceleration,
//   swe_integrate, time_step_control, particle_splitting (when [splitting] enabled)
#include <cmath>
#include <cstdio>
#include <limits>

#include "ecs/lattice.hpp"
#include "methods/method.hpp"
#include "methods/swe_spec.hpp"
#include "scene/block_fields.hpp"
#include "systems/splitting/particle_splitting.hpp"
#include "systems/swe/ghost_images.hpp"
#include "systems/swe/ritter.hpp"
#include "systems/swe/swe_systems.hpp"

namespace ryushi {

namespace {

SweParameters swe_parameters(const Scene& s) {
  SweParameters p;
  p.g = s.swe.gravity;
  p.manning = s.swe.manning;
  p.alpha_e = s.swe.influence_ratio;
  p.cfl = s.cfl;
  p.rho0 = s.density;
  p.area0 = s.spacing * s.spacing;
  p.slip = s.swe.slip;
  p.edge_correction = s.swe.edge_correction;
  p.momentum = s.swe.momentum == "sph" ? SweParameters::Momentum::Sph : SweParameters::Momentum::Mps;
  p.bed = s.swe.bed;
  // Each closed axis of a [[wall]] box gives two mirror lines, spanning the box.
  for (auto& w : s.walls)
    for (int a = 0; a < 2; ++a) {
      if (a < int(w.open_ends.size()) && w.open_ends[a]) continue;
      p.walls.push_back({a, w.min[a], +1, w.min[1 - a], w.max[1 - a]});
      p.walls.push_back({a, w.max[a], -1, w.min[1 - a], w.max[1 - a]});
    }
  return p;
}

// The fluid blocks' lattice points that hold water, with their target depth.
struct InitialWater {
  std::vector<Vec<2>> x, v;
  std::vector<double> depth;
};

InitialWater initial_water(const Scene& s, const Bed& bed) {
  InitialWater out;
  const double d = s.spacing;
  for (std::size_t index = 0; index < s.fluid.size(); ++index) {
    const FluidBlock& b = s.fluid[index];
    const BlockFields fields(b, index);
    std::array<long, 2> from{}, to{};
    for (int a = 0; a < 2; ++a) to[a] = std::lround((b.max[a] - b.min[a]) / d);
    for_each_lattice_point<2>(scene_vector<2>(b.min), d, from, to, [&](const Vec<2>& x) {
      if (bed.raster && bed.raster->nodata_at(x[0], x[1])) return;  // dry high ground
      double h = std::isnan(b.depth) ? b.surface_elevation - bed.elevation(x[0], x[1]) : b.depth;
      if (!(h > 0)) return;  // above the surface: dry
      out.x.push_back(x);
      out.v.push_back(Vec<2>(fields.velocity(0, x.data(), 2), fields.velocity(1, x.data(), 2)));
      out.depth.push_back(h);
    });
  }
  return out;
}

// Volumes V_i such that the SPH depth (eq. 7) starts at the blocks' depth. First V = h A0, then,
// for every particle whose neighbourhood is complete (ghosts included: its kernel sum over
// lattice areas is the full lattice's), V_i scaled by h_target / h_sum until the sums match to
// round-off. The areas A_i = V_i / h_i and r_e = alpha_e sqrt(A_max) that the first step will
// compute depend on the volumes (a lattice's kernel sum is not exactly 1), so the balance is
// repeated with that r_e until r_e no longer changes: the first step then finds the same r_e
// and the same depths. A lake over a bumpy bed starts with a flat surface at every particle
// (well balanced from the first step); the particles at a free edge (a dam-break front) keep
// their plain volume h A0, so the edge is not made heavier to fake a full depth there.
struct InitialBalance {
  std::vector<double> volume, area;
  double influence_radius = 0;
};

InitialBalance initial_volumes(const Scene& s, const SweParameters& p, const InitialWater& water) {
  const double d = s.spacing, A0 = p.area0;
  const std::size_t n = water.x.size();
  InitialBalance out;
  out.volume.resize(n);
  out.area.assign(n, A0);
  for (std::size_t i = 0; i < n; ++i) out.volume[i] = water.depth[i] * A0;
  double r_e = p.alpha_e * d;
  for (int round = 0; round < 100; ++round) {
    const Kernel<2> w(KernelType::Spiky, r_e);
    double full = 0;  // the kernel's sum over a complete lattice of areas A0
    const long reach = long(std::ceil(w.support() / d)) + 1;
    for (long i = -reach; i <= reach; ++i)
      for (long j = -reach; j <= reach; ++j) full += A0 * w.w(d * std::hypot(double(i), double(j)));
    GhostImages<2> g;
    build_ghost_images<2>(water.x, p.walls, p.slip, w.support(), g);
    CellGrid<2> grid;
    NeighbourList nl;
    build_neighbour_list<2>(scene_domain<2>(s), w.support(), std::span<const Vec<2>>(g.position), grid, nl);
    auto depth_sum = [&](std::size_t i) {
      double h = out.volume[i] * w.w(0);
      for (auto j : nl.of(i)) h += out.volume[g.owner(j)] * w.w((g.position[j] - water.x[i]).norm());
      return h;
    };
    std::vector<char> complete(n);
    for (std::size_t i = 0; i < n; ++i) {
      double shepard = A0 * w.w(0);
      for (auto j : nl.of(i)) shepard += A0 * w.w((g.position[j] - water.x[i]).norm());
      complete[i] = shepard > (1 - 1e-9) * full;
    }
    for (int sweep = 0; sweep < 200; ++sweep) {
      std::vector<double> scale(n, 1.0);
      double worst = 0;
      for (std::size_t i = 0; i < n; ++i) {
        if (!complete[i]) continue;
        scale[i] = water.depth[i] / depth_sum(i);
        worst = std::max(worst, std::abs(scale[i] - 1));
      }
      for (std::size_t i = 0; i < n; ++i) out.volume[i] *= scale[i];
      if (worst < 1e-14) break;
    }
    double amax = 0;
    for (std::size_t i = 0; i < n; ++i) amax = std::max(amax, out.area[i] = out.volume[i] / depth_sum(i));
    const double next = p.alpha_e * std::sqrt(amax);
    out.influence_radius = r_e;
    if (std::abs(next - r_e) <= 1e-14 * r_e) break;
    r_e = next;
  }
  return out;
}

template <int D>
MethodSetup<D> build_swe(const Scene& s, World<D>& world, const PipelineOptions& options) {
  if constexpr (D != 2) {
    throw SceneError(s.path + ": method 'swe' is 2D (the loader refuses dimension 3)");
  } else {
    refuse_matrix_dump(s, options);
    const SweParameters p = swe_parameters(s);
    const auto water = initial_water(s, *p.bed);
    if (water.x.empty())
      throw SceneError(s.path + ": [[fluid]]: no lattice point holds water (depth <= 0 everywhere)");
    const auto balance = initial_volumes(s, p, water);
    const auto& V = balance.volume;
    std::size_t first = world.append(water.x.size(), kFluid);
    auto& x = world.ensure(components::position);
    auto& v = world.ensure(components::velocity);
    auto& m = world.ensure(components::mass);
    auto& rho = world.ensure(components::density);
    auto& vol = world.ensure(components::water_volume);
    auto& h = world.ensure(components::depth);
    auto& A = world.ensure(components::area);
    auto& zb = world.ensure(components::bed_elevation);
    auto& zs = world.ensure(components::surface_elevation);
    auto& pr = world.ensure(components::pressure);
    auto& parent = world.ensure(components::parent_id);
    for (std::size_t k = 0; k < water.x.size(); ++k) {
      const std::size_t i = first + k;
      x[i] = water.x[k];
      v[i] = water.v[k];
      vol[i] = V[k];
      m[i] = p.rho0 * V[k];
      rho[i] = p.rho0;  // the water's own density: m / rho is the particle's volume
      h[i] = water.depth[k];
      A[i] = balance.area[k];  // the first step's r_e is then the one the volumes were balanced with
      zb[i] = p.bed->elevation(x[i][0], x[i][1]);
      zs[i] = zb[i] + h[i];
      pr[i] = p.rho0 * p.g * h[i];
      parent[i] = -1;
    }

    MethodSetup<D> m_;
    const Kernel<2> kernel(KernelType::Spiky, balance.influence_radius);
    m_.context = method_context<D>(s, kernel);
    m_.context.gravity_magnitude = s.swe.gravity;  // along -z, out of the plan view
    m_.pipeline = {
        std::make_shared<SweInfluenceRadius<D>>(p.alpha_e),
        std::make_shared<SweGhostWalls<D>>(p.walls, p.slip, kernel.support_factor()),
        std::make_shared<SweNeighbourSearch<D>>(),
        std::make_shared<SweDepth<D>>(p),
        std::make_shared<SweAcceleration<D>>(p),
        std::make_shared<SweIntegrate<D>>(p),
    };
    if (s.fixed_dt <= 0) m_.pipeline.push_back(std::make_shared<SweTimeStep<D>>(p));
    if (s.swe.splitting) {
      SplitParameters sp;
      sp.area_ratio = s.swe.split_area_ratio;
      sp.alpha_s = s.swe.split_distance;
      sp.area0 = p.area0;
      sp.rho0 = p.rho0;
      sp.along_gap = s.swe.split_along_gap;
      sp.max_particles = s.swe.max_particles > 0 ? std::size_t(s.swe.max_particles) : 20 * water.x.size();
      m_.pipeline.push_back(std::make_shared<ParticleSplitting<D>>(sp));
    }
    double hmax = 0, umax = 0, amin = std::numeric_limits<double>::infinity();
    for (std::size_t k = 0; k < water.x.size(); ++k)
      hmax = std::max(hmax, water.depth[k]), umax = std::max(umax, water.v[k].norm()),
      amin = std::min(amin, A[first + k]);
    m_.first_dt = p.cfl * std::sqrt(amin) / (std::sqrt(p.g * hmax) + umax);
    char b[96];
    std::snprintf(b, sizeof b, "r_e = %.4g m at start, g = %.4g, n_M = %.3g, splitting %s", kernel.h(), p.g,
                  p.manning, s.swe.splitting ? "on" : "off");
    m_.summary = b;
    m_.parameters = {{"influence_radius_initial", kernel.h()}, {"gravity", p.g}, {"manning", p.manning}};
    const RitterReference ritter{s.swe.ritter_dam_x, s.swe.ritter_depth, p.g};
    m_.diagnostics = [ritter](const World<D>& w,
                              const Resources& res) -> std::vector<std::pair<std::string, double>> {
      std::vector<std::pair<std::string, double>> out;
      if (res.has(splitting_statistics_resource.name))
        out.push_back({"splits", double(res.get(splitting_statistics_resource).splits)});
      if (res.has(swe_influence_radius_resource.name))
        out.push_back({"influence_radius", res.get(swe_influence_radius_resource)});
      if (ritter.enabled() && w.has(components::depth.name)) {
        auto e = ritter_errors(w.column(components::position), w.column(components::depth), ritter,
                               res.get(resources::time));
        out.push_back({"ritter_front_depth_error", e.front_depth_error});
        out.push_back({"ritter_depth_error", e.depth_error});
        out.push_back({"front_position", e.front});
        out.push_back({"ritter_front_position", e.analytic_front});
        out.push_back({"ritter_front_particles", double(e.front_particles)});
      }
      return out;
    };
    return m_;
  }
}

}  // namespace

RYUSHI_REGISTER_METHOD("swe", swe_spec(), build_swe);

}  // namespace ryushi
