#pragma once
// A pressure sensor on a wall (probe type `wall_pressure`): the pressure the fluid exerts on a
// face of diameter `diameter` centred at `position` on a wall surface, facing along the unit
// `normal` (out of the wall, into the fluid), the mean over the face of the surface pressure
//   p_s(x) = sum_f W_f [p_f + rho0 (g - a_w) . (x - x_f)] / sum_f W_f,
// W_f = V_f W(|x - x_f|) over the fluid particles within the sensor kernel's support of x: each
// particle's pressure carried to the wall along the pressure gradient a fluid at the wall feels,
// rho0 (g - a_w), a_w the wall's acceleration (Adami et al. 2012, seed 002 eq. 27, read from the
// fluid side). The same for every method and wall type: it reads the fluid, not the wall's
// particles, whose pressure each method defines its own way (WCSPH's extrapolated dummies, MPS's
// solved first layer, ISPH's Neumann or Shepard rows). The kernel is the sensor's, not the
// method's: Wendland C2 with h = d (support 2 d, the two fluid rows beside the wall), so that MPS's
// wide weight (r_e = 3.1 d) does not average the impact's peak over six rows. A point of the face
// that the fluid does not wet (below) reads 0 (air). In 2D the face is the segment of length `diameter`
// across the normal, in 3D the disc, sampled at points at most d/4 apart.
#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "ecs/world.hpp"
#include "kernels/kernel.hpp"
#include "systems/neighbour/domain.hpp"
#include "systems/probes/fluid_cells.hpp"

namespace ryushi {

template <int D>
struct WallSensor {
  Vec<D> centre = Vec<D>::Zero(), normal = Vec<D>::UnitX();
  double diameter = 0;
};

// The sensor kernel (above): Wendland C2, h = d.
template <int D>
Kernel<D> sensor_kernel(double spacing) {
  return Kernel<D>(KernelType::WendlandC2, spacing);
}

// The points of the face: the centre, then a lattice across the normal at most d/4 apart.
template <int D>
std::vector<Vec<D>> sensor_face_points(const WallSensor<D>& s, double spacing) {
  Vec<D> t1 = Vec<D>::Zero(), t2 = Vec<D>::Zero();
  if constexpr (D == 2) {
    t1 = Vec<D>(-s.normal[1], s.normal[0]);
  } else {
    const Vec<D> other = std::abs(s.normal[0]) < 0.9 ? Vec<D>::UnitX() : Vec<D>::UnitY();
    t1 = (other - other.dot(s.normal) * s.normal).normalized();
    const Vec<D>& n = s.normal;  // t2 = n x t1
    t2[0] = n[1] * t1[2] - n[2] * t1[1];
    t2[1] = n[2] * t1[0] - n[0] * t1[2];
    t2[2] = n[0] * t1[1] - n[1] * t1[0];
  }
  const int per_side = static_cast<int>(std::ceil(0.5 * s.diameter / (0.25 * spacing)));
  const double step = per_side > 0 ? 0.5 * s.diameter / per_side : 0;
  std::vector<Vec<D>> points;
  for (int a = -per_side; a <= per_side; ++a)
    for (int b = (D == 3 ? -per_side : 0); b <= (D == 3 ? per_side : 0); ++b) {
      const double u = a * step, w = b * step;
      if (u * u + w * w <= 0.25 * s.diameter * s.diameter * (1 + 1e-12))
        points.push_back(s.centre + u * t1 + w * t2);
    }
  return points;
}

// The fluid and the solid particles around the sensors' points, binned once per sample.
template <int D>
struct SensorCells {
  SensorCells(const World<D>& world, const Domain<D>& domain, double support)
      : fluid(world, domain, support), solid(world, domain, support, true) {}
  FluidCells<D> fluid, solid;
};

// The surface pressure p_s(x) (above); felt = g - a_w. A point is wet where the fluid fills at
// least a quarter of the support the walls leave, sum_f V_f W / (1 - sum_w V_w W) >= 1/4 (the
// water_height probe's fill, probes.hpp), and reads 0 (air) elsewhere: above the water line the
// hydrostatic carry would go on below zero (a plate holding back a resting tank read 0.4% of its
// thrust less from the two elements above the water). On a lattice beside a flat wall the fill
// is 0.97 two spacings under the surface, 0.84 at the face particle below the water line, 0.47 at
// the line and 0.13 at the particle above it (the sensor kernel, one wall layer or three); at 1/2
// an ISPH run-up at H/d = 20, its particles kept a little off the wall, read dry 80% of the time.
template <int D>
double surface_pressure_at(const Vec<D>& at, const World<D>& world, const SensorCells<D>& cells,
                           const Domain<D>& domain, const Kernel<D>& kernel, double rho0,
                           const Vec<D>& felt) {
  auto& x = world.column(components::position);
  auto& p = world.column(components::pressure);
  auto& m = world.column(components::mass);
  auto& rho = world.column(components::density);
  double sum = 0, weight = 0, solid = 0;
  cells.fluid.around(at, [&](std::size_t f) {
    const Vec<D> r = domain.offset(x[f], at);  // from the fluid particle to the point
    const double len = r.norm();
    // MPS's density column is its source density rho0 n* / n0: 0 for a lone splash particle,
    // which has no volume to weigh (its m / rho made a 3D column's force NaN at 45 samples).
    if (len >= kernel.support() || !(rho[f] > 0)) return;
    const double w = m[f] / rho[f] * kernel.w(len);
    sum += w * (p[f] + rho0 * felt.dot(r));
    weight += w;
  });
  cells.solid.around(at, [&](std::size_t s) {
    const double len = domain.offset(x[s], at).norm();
    if (len < kernel.support() && rho[s] > 0) solid += m[s] / rho[s] * kernel.w(len);
  });
  return weight >= 0.25 * (1 - std::min(solid, 1.0)) && weight > 0 ? sum / weight : 0.0;
}

// The wall particle nearest the sensor's centre (any kind but fluid and elastic), if one lies
// within a support of the sensor kernel.
template <int D>
std::optional<std::size_t> nearest_wall_particle(const Vec<D>& at, const World<D>& world,
                                                 const Domain<D>& domain, double reach) {
  auto& x = world.column(components::position);
  auto& kind = world.column(components::kind);
  std::optional<std::size_t> best;
  double best2 = reach * reach;
  for (std::size_t i = 0; i < world.size(); ++i) {
    if (kind[i] == kFluid || kind[i] == kElastic) continue;
    const double r2 = domain.offset(x[i], at).squaredNorm();
    if (r2 < best2) best2 = r2, best = i;
  }
  return best;
}

// Why a sensor cannot read a wall (an empty text if it can): no wall particle within a spacing of its
// centre (the first layer lies d/2 behind the surface), or its normal not pointing away from the
// wall's particles around it (their kernel-weighted mean offset must lie within 60 degrees of
// -normal).
struct SensorProblem {
  std::string text;            // "" : none
  bool about_position = true;  // else about the normal
};

template <int D>
SensorProblem wall_sensor_problem(const WallSensor<D>& s, const World<D>& world, const Domain<D>& domain,
                                  double spacing) {
  auto& x = world.column(components::position);
  auto& kind = world.column(components::kind);
  if (!nearest_wall_particle(s.centre, world, domain, spacing)) {
    auto far = nearest_wall_particle(s.centre, world, domain, std::numeric_limits<double>::infinity());
    const double distance = far ? domain.offset(x[*far], s.centre).norm() : 0;
    return {far ? "the sensor lies off any wall: the nearest wall particle is " + std::to_string(distance) +
                      " m away (the first wall layer lies half a spacing, " + std::to_string(0.5 * spacing) +
                      " m, behind the surface)"
                : "the sensor lies off any wall: the scene has no wall particles"};
  }
  const Kernel<D> kernel = sensor_kernel<D>(spacing);
  Vec<D> towards_wall = Vec<D>::Zero();
  for (std::size_t i = 0; i < world.size(); ++i) {
    if (kind[i] == kFluid || kind[i] == kElastic) continue;
    const Vec<D> r = domain.offset(s.centre, x[i]);  // from the centre to the wall particle
    if (r.norm() < kernel.support()) towards_wall += kernel.w(r.norm()) * r;
  }
  if (!(s.normal.dot(towards_wall) < -0.5 * towards_wall.norm()))
    return {
        "the sensor's normal points into the wall or along it: it must point out of the wall, into the fluid",
        false};
  return {};
}

// The sensor's reading: the mean of p_s over its face; felt = g - a_w of the nearest wall particle.
template <int D>
double wall_sensor_pressure(const WallSensor<D>& s, const World<D>& world, const SensorCells<D>& cells,
                            const Domain<D>& domain, double spacing, double rho0, const Vec<D>& gravity) {
  Vec<D> felt = gravity;
  if (world.has(components::body_acceleration.name)) {
    // The nearest wall particle within 2 d, from the cells (every sample: no scan of the world).
    auto& x = world.column(components::position);
    auto& kind = world.column(components::kind);
    std::optional<std::size_t> nearest;
    double best2 = 4 * spacing * spacing;
    cells.solid.around(s.centre, [&](std::size_t w) {
      const double r2 = domain.offset(x[w], s.centre).squaredNorm();
      if (kind[w] != kElastic && r2 < best2) best2 = r2, nearest = w;
    });
    if (nearest) felt -= world.column(components::body_acceleration)[*nearest];
  }
  const Kernel<D> kernel = sensor_kernel<D>(spacing);
  const auto points = sensor_face_points(s, spacing);
  double sum = 0;
  for (const auto& at : points) sum += surface_pressure_at(at, world, cells, domain, kernel, rho0, felt);
  return sum / static_cast<double>(points.size());
}

}  // namespace ryushi
