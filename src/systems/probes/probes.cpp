#include "systems/probes/probes.hpp"

#include <tbb/blocked_range.h>
#include <tbb/parallel_reduce.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

#include "systems/elastic/elastic_parameters.hpp"
#include "systems/probes/solid_force.hpp"
#include "systems/probes/solid_surface_force.hpp"
#include "systems/probes/wall_sensor.hpp"

namespace ryushi {

namespace {

template <class Body>
auto reduce_particles(std::size_t n, std::pair<double, double> init, Body&& body, bool take_max) {
  using Pair = std::pair<double, double>;
  return tbb::parallel_reduce(
      tbb::blocked_range<std::size_t>(0, n, 4096), init,
      [&](auto r, Pair acc) {
        for (std::size_t i = r.begin(); i != r.end(); ++i) body(i, acc);
        return acc;
      },
      [take_max](Pair a, Pair b) {
        return take_max ? Pair{std::max(a.first, b.first), 0.0}
                        : Pair{a.first + b.first, a.second + b.second};
      });
}

// The leading edge of the water body along x: the largest x of a fluid particle with another
// fluid particle within 2 d (probes.hpp). Candidates are the particles in a strip behind the
// foremost one, x_max; a candidate is decided once its whole 2 d neighbourhood lies in the
// strip, and the strip doubles until one is (all particles isolated: x_max itself).
template <int D>
double body_front(const World<D>& world, double x_max, double d) {
  auto& x = world.column(components::position);
  auto& kind = world.column(components::kind);
  const double reach = 2 * d, reach2 = reach * reach;
  std::vector<std::size_t> strip;
  for (double width = 8 * d;; width *= 2) {
    strip.clear();
    for (std::size_t i = 0; i < world.size(); ++i)
      if (kind[i] == kFluid && x[i][0] >= x_max - width) strip.push_back(i);
    std::sort(strip.begin(), strip.end(), [&](auto a, auto b) { return x[a][0] > x[b][0]; });
    const bool whole = strip.size() == static_cast<std::size_t>(std::count(kind.begin(), kind.end(), kFluid));
    for (std::size_t c = 0; c < strip.size(); ++c) {
      const double xc = x[strip[c]][0];
      if (!whole && xc - reach < x_max - width) break;  // its neighbours may lie outside the strip
      for (std::size_t k = c + 1; k < strip.size() && x[strip[k]][0] >= xc - reach; ++k)
        if ((x[strip[k]] - x[strip[c]]).squaredNorm() <= reach2) return xc;
      for (std::size_t k = c; k-- > 0 && x[strip[k]][0] <= xc + reach;)
        if ((x[strip[k]] - x[strip[c]]).squaredNorm() <= reach2) return xc;
    }
    if (whole) return x_max;
  }
}

// The surface of the water column standing on the probe's base point (probes.hpp). Candidates are
// the particles within the support of the vertical line; the line is sampled every d/4.
template <int D>
double water_surface(const Vec<D>& base, const World<D>& world, const Kernel<D>& kernel, double rho0,
                     double top, double d) {
  auto& x = world.column(components::position);
  auto& kind = world.column(components::kind);
  auto& m = world.column(components::mass);
  const double support = kernel.support();
  std::vector<std::size_t> near;
  for (std::size_t i = 0; i < world.size(); ++i) {
    Vec<D> r = x[i] - base;
    r[D - 1] = 0;
    if (r.squaredNorm() < support * support) near.push_back(i);
  }
  // Sorted by height, each sample reads only the window within the support above and below it
  // (a tall column holds thousands of candidates; every sample reading all of them made this
  // probe 2% of an MPS step at 1.3M particles).
  std::sort(near.begin(), near.end(),
            [&](std::size_t a, std::size_t b) { return x[a][D - 1] < x[b][D - 1]; });
  std::size_t first = 0, last = 0;
  const double step = 0.25 * d;
  bool in_water = false;
  double previous_z = base[D - 1], previous_f = 0;
  for (double z = base[D - 1]; z <= top; z += step) {
    Vec<D> at = base;
    at[D - 1] = z;
    while (first < near.size() && x[near[first]][D - 1] <= z - support) ++first;
    while (last < near.size() && x[near[last]][D - 1] < z + support) ++last;
    double fluid = 0, wall = 0;
    for (std::size_t k = first; k < last; ++k) {
      const std::size_t i = near[k];
      double vw = m[i] / rho0 * kernel.w((x[i] - at).norm());
      (kind[i] == kFluid ? fluid : wall) += vw;
    }
    // Inside a wall the fraction means nothing: skip until the line leaves it.
    if (wall > 0.9) continue;
    const double f = fluid / (1 - wall);
    if (!in_water && f >= 0.5) in_water = true;
    if (in_water && f < 0.5)  // the crossing, interpolated between the two samples
      return previous_z + (previous_f - 0.5) / (previous_f - f) * (z - previous_z);
    previous_z = z;
    previous_f = f;
  }
  return in_water ? top : base[D - 1];
}

template <int D>
WallSensor<D> wall_sensor_of(const Probe& probe) {
  WallSensor<D> s;
  for (int a = 0; a < D; ++a) s.centre[a] = probe.position[a], s.normal[a] = probe.normal[a];
  s.normal.normalize();
  s.diameter = probe.diameter;
  return s;
}

}  // namespace

template <int D>
std::vector<SensorProblem> wall_sensor_problems(const std::vector<Probe>& probes, const World<D>& world,
                                                const MethodContext<D>& context) {
  std::vector<SensorProblem> problems;
  for (auto& probe : probes)
    problems.push_back(probe.type == "wall_pressure" ? wall_sensor_problem(wall_sensor_of<D>(probe), world,
                                                                           context.domain, context.spacing)
                                                     : SensorProblem{});
  return problems;
}

template <int D>
std::vector<double> sample_probes(const std::vector<Probe>& probes, const World<D>& world,
                                  const MethodContext<D>& context) {
  const Kernel<D>& kernel = context.kernel;
  const Domain<D>& domain = context.domain;
  const double d = context.spacing, rho0 = context.rho0;
  const Vec<D>& gravity = context.gravity;
  auto& x = world.column(components::position);
  auto& kind = world.column(components::kind);
  auto& p = world.column(components::pressure);
  auto& rho = world.column(components::density);
  auto& m = world.column(components::mass);
  auto& v = world.column(components::velocity);
  const double lowest = -std::numeric_limits<double>::infinity();
  std::vector<double> out;
  std::optional<SensorCells<D>> sensor_cells;  // built once, for the wall_pressure probes
  for (auto& probe : probes) {
    Vec<D> at = Vec<D>::Zero();
    for (std::size_t a = 0; a < probe.position.size(); ++a) at[a] = probe.position[a];
    if (probe.type == "pressure" || probe.type == "velocity") {
      const bool velocity = probe.type == "velocity";
      const double support2 = kernel.support() * kernel.support();
      auto [num, den] = reduce_particles(
          world.size(), {0.0, 0.0},
          [&](std::size_t i, auto& acc) {
            if (kind[i] != kFluid) return;
            const double r2 = (x[i] - at).squaredNorm();
            if (r2 >= support2 || !(rho[i] > 0)) return;  // MPS: a lone particle's rho0 n* / n0 is 0
            double w = kernel.w(std::sqrt(r2)) * m[i] / rho[i];
            acc.first += (velocity ? v[i][probe.axis] : p[i]) * w;
            acc.second += w;
          },
          false);
      out.push_back(den > 0 ? num / den : std::numeric_limits<double>::quiet_NaN());
    } else if (probe.type == "wall_pressure") {
      if (!sensor_cells)
        sensor_cells.emplace(world, domain, std::max(kernel.support(), sensor_kernel<D>(d).support()));
      out.push_back(
          wall_sensor_pressure(wall_sensor_of<D>(probe), world, *sensor_cells, domain, d, rho0, gravity));
    } else if (probe.type == "surge_front") {
      auto r = reduce_particles(
          world.size(), {lowest, 0.0},
          [&](std::size_t i, auto& acc) {
            if (kind[i] == kFluid) acc.first = std::max(acc.first, x[i][0]);
          },
          true);
      out.push_back(body_front(world, r.first, d) + 0.5 * d);
    } else if (probe.type == "particle_count") {
      std::size_t count = 0;
      for (std::size_t i = 0; i < world.size(); ++i) count += kind[i] == kFluid;
      out.push_back(double(count));
    } else if (probe.type == "front_depth") {  // swe: the depth of the foremost particle
      auto& depth = world.column(Component<Scalar>{"depth"});
      std::size_t front = world.size();
      for (std::size_t i = 0; i < world.size(); ++i)
        if (kind[i] == kFluid && (front == world.size() || x[i][0] > x[front][0])) front = i;
      out.push_back(front < world.size() ? depth[front] : std::numeric_limits<double>::quiet_NaN());
    } else if (probe.type == "kinetic_energy" || probe.type == "potential_energy") {
      const bool kinetic = probe.type == "kinetic_energy";
      auto r = reduce_particles(
          world.size(), {0.0, 0.0},
          [&](std::size_t i, auto& acc) {
            if (kind[i] == kFluid)
              acc.first += kinetic ? 0.5 * m[i] * v[i].squaredNorm() : -m[i] * gravity.dot(x[i]);
          },
          false);
      out.push_back(r.first);
    } else if (probe.type == "force") {
      // The surface pressure's integral (every method), and the shear as the method reads it: the
      // reaction to its laminar pair term (WCSPH), or on the first wall layer (MPS, ISPH).
      const SurfaceForceParameters surface{d, rho0, context.viscosity, context.wall_layer_viscous};
      Vec<D> force = Vec<D>::Zero();
      if (context.solid_force == SolidForceReading::PairReaction) {
        const SensorCells<D> cells = force_cells(world, kernel, domain, d);
        force = solid_pressure_force<D>(probe.solid, world, cells, domain, gravity, surface) +
                solid_force<D>(probe.solid, world, kernel, domain, cells.fluid, /*with_pressure=*/false);
      } else
        force = solid_surface_force<D>(probe.solid, world, kernel, domain, gravity, surface);
      out.push_back(force[probe.axis] * probe.scale);
    } else if (probe.type == "solid_displacement" || probe.type == "solid_stress") {
      // The elastic particle that started nearest the probe.
      auto& rest = world.column(components::rest_position);
      std::size_t nearest = world.size();
      for (std::size_t i = 0; i < world.size(); ++i)
        if (kind[i] == kElastic &&
            (nearest == world.size() || (rest[i] - at).squaredNorm() < (rest[nearest] - at).squaredNorm()))
          nearest = i;
      if (nearest == world.size()) {
        out.push_back(std::numeric_limits<double>::quiet_NaN());
      } else if (probe.type == "solid_displacement") {
        out.push_back(domain.displacement(x[nearest], rest[nearest])[probe.axis]);
      } else {
        out.push_back(world.column(components::stress)[nearest](probe.axis, probe.axis));
      }
    } else if (probe.type == "solid_energy") {
      auto& rho_s = world.column(components::solid_rest_density);
      auto& strain = world.column(components::strain_energy);
      const double volume = std::pow(d, D);
      double energy = 0;
      for (std::size_t i = 0; i < world.size(); ++i)
        if (kind[i] == kElastic) energy += 0.5 * rho_s[i] * volume * v[i].squaredNorm() + strain[i];
      out.push_back(energy);
    } else {  // water_height
      out.push_back(water_surface<D>(at, world, kernel, rho0, domain.max[D - 1], d));
    }
  }
  return out;
}

template std::vector<SensorProblem> wall_sensor_problems<2>(const std::vector<Probe>&, const World<2>&,
                                                            const MethodContext<2>&);
template std::vector<SensorProblem> wall_sensor_problems<3>(const std::vector<Probe>&, const World<3>&,
                                                            const MethodContext<3>&);
template std::vector<double> sample_probes<2>(const std::vector<Probe>&, const World<2>&,
                                              const MethodContext<2>&);
template std::vector<double> sample_probes<3>(const std::vector<Probe>&, const World<3>&,
                                              const MethodContext<3>&);

}  // namespace ryushi
