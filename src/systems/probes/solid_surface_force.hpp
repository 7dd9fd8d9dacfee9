#pragma once
// The force of the fluid on a [[solid]] body (probe type `force`), the same for every method in
// its pressure part: the surface pressure of the wall sensors (wall_sensor.hpp) integrated over
// the body's surface,
//   F_p = sum_{w in body, layer 1} p_s(x_w - n_w d/2) S_w,
// S_w = A_w n_w the particle's surface element (its share A_w of the body's surface, n_w the unit
// normal from the fluid into the body; solid_shape.hpp) and x_w - n_w d/2 the point of the surface
// in front of it, so that a sensor on the body and its force read one pressure field. Before
// (2026-11-29) MPS and ISPH took the wall particle's own pressure carried half a spacing out,
// WCSPH the reaction to its pair forces: on a plate holding back a resting tank (H/d = 20) the
// three read -2.5% (WCSPH), +2.1% (MPS) and -0.02% (ISPH) of the hydrostatic thrust.
// The shear: MPS takes its own viscous term's reaction over the pairs of fluid and the body's
// pressure-layer particles (mps_explicit_forces.hpp), F_v = sum_f sum_w m_f nu 2D / (lambda0 n0)
// (v_f - v_w) w_fw; WCSPH the reaction to its laminar pair term (solid_force.hpp); ISPH the
// Shepard slope of the fluid beside each particle,
//   F_v = sum_w mu (v~_w - v_w)_t / delta_w A_w,
// v~_w and delta_w the Shepard averages (kernel weights) of the fluid's velocity and of its
// distance from the particle along -n_w, (.)_t the part along the wall: the slope of a velocity
// profile that is zero relative to the wall at the wall particle, where ISPH holds it. (The
// Shepard slope read 36% over the Couette series under MPS, whose velocity steepens next to its
// walls; the pair reaction is what the fluid actually felt.)
#include <cmath>
#include <span>

#include "ecs/world.hpp"
#include "kernels/kernel.hpp"
#include "systems/neighbour/domain.hpp"
#include "systems/probes/fluid_cells.hpp"
#include "systems/probes/wall_sensor.hpp"

namespace ryushi {

struct SurfaceForceParameters {
  double spacing = 1, rho0 = 1000, mu = 0;
  double mps_viscous = 0;  // MPS: nu 2D / (lambda0 n0), its Laplacian's; 0: the Shepard wall slope
};

// The pressure part F_p (above), every method's.
template <int D>
Vec<D> solid_pressure_force(int body, const World<D>& world, const SensorCells<D>& cells,
                            const Domain<D>& domain, const Vec<D>& gravity, const SurfaceForceParameters& q) {
  auto& x = world.column(components::position);
  auto& owner = world.column(components::body);
  auto& element = world.column(components::surface_element);
  std::span<const Vec<D>> acceleration;
  if (world.has(components::body_acceleration.name))
    acceleration = world.column(components::body_acceleration);
  const Kernel<D> sensor = sensor_kernel<D>(q.spacing);
  Vec<D> force = Vec<D>::Zero();
  for (std::size_t w = 0; w < world.size(); ++w) {
    if (owner[w] != body) continue;
    const double area = element[w].norm();
    if (area == 0) continue;
    const Vec<D> surface = x[w] - 0.5 * q.spacing / area * element[w];
    const Vec<D> felt = acceleration.empty() ? gravity : Vec<D>(gravity - acceleration[w]);
    force += surface_pressure_at(surface, world, cells, domain, sensor, q.rho0, felt) * element[w];
  }
  return force;
}

// The cells for both: a support of the method's kernel and of the sensor's.
template <int D>
SensorCells<D> force_cells(const World<D>& world, const Kernel<D>& kernel, const Domain<D>& domain,
                           double spacing) {
  return SensorCells<D>(world, domain, std::max(kernel.support(), sensor_kernel<D>(spacing).support()));
}

template <int D>
Vec<D> solid_surface_force(int body, const World<D>& world, const Kernel<D>& kernel, const Domain<D>& domain,
                           const Vec<D>& gravity, const SurfaceForceParameters& q) {
  auto& x = world.column(components::position);
  auto& owner = world.column(components::body);
  auto& v = world.column(components::velocity);
  auto& element = world.column(components::surface_element);
  auto& kind = world.column(components::kind);
  auto& m = world.column(components::mass);
  const SensorCells<D> cells = force_cells(world, kernel, domain, q.spacing);
  Vec<D> force = solid_pressure_force(body, world, cells, domain, gravity, q);
  for (std::size_t w = 0; w < world.size(); ++w) {
    if (owner[w] != body) continue;
    const double area = element[w].norm();
    if (area == 0) continue;
    const Vec<D> n = element[w] / area;
    double sum_w = 0, sum_depth = 0;
    Vec<D> sum_v = Vec<D>::Zero();
    cells.fluid.around(x[w], [&](std::size_t f) {
      const Vec<D> r = domain.offset(x[w], x[f]);  // from the wall particle to the fluid
      const double len = r.norm();
      if (len >= kernel.support()) return;
      const double W = kernel.w(len);
      sum_w += W;
      sum_depth += W * -n.dot(r);
      sum_v += W * v[f];
    });
    if (sum_w == 0) continue;  // dry: air on it (the tank's lid, a wall above the water)
    if (q.mps_viscous > 0) {
      if (kind[w] != kWall) continue;  // dummy particles take no part in MPS's viscous term
      cells.fluid.around(x[w], [&](std::size_t f) {
        const double len = domain.offset(x[w], x[f]).norm();
        if (len < kernel.support()) force += m[f] * q.mps_viscous * kernel.w(len) * (v[f] - v[w]);
      });
      continue;
    }
    if (q.mu == 0 || sum_depth <= 0) continue;
    Vec<D> slip = sum_v / sum_w - v[w];
    slip -= slip.dot(n) * n;  // along the wall
    force += q.mu * slip / (sum_depth / sum_w) * area;
  }
  return force;
}

}  // namespace ryushi
