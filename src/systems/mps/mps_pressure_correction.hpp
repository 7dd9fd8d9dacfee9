#pragma once
// The implicit part of an MPS step (BMG paper eq. 3): with the pressure of the Poisson equation,
//   <grad p>_i = d/n0 sum_j (p_j - p^_i) r_ij / |r_ij|^2 w_ij,   p^_i = min(p_i, p_j : j in r_e)
//   u^{k+1} = u* - dt/rho0 <grad p>_i,   x^{k+1} = x* + dt (u^{k+1} - u*)
// The local minimum p^_i makes every pair term repulsive (Koshizuka's stabilisation). Fluid and
// wall particles carry pressure; dummies are left out. With clamp_negative_pressure, p < 0 is
// read as 0. The gradient is written to `pressure_gradient` (an output field).
#include <algorithm>

#include "ecs/io.hpp"
#include "systems/loops/for_each_particle.hpp"
#include "systems/mps/mps_pair_weights.hpp"
#include "systems/mps/mps_parameters.hpp"
#include "systems/neighbour/neighbour_list.hpp"

namespace ryushi {

template <int D>
class MpsPressureCorrection final : public System<D> {
 public:
  explicit MpsPressureCorrection(const MpsParameters<D>& p) : p_(p) {}
  std::string name() const override { return "mps_pressure_correction"; }
  static constexpr auto io =
      Io{reads(components::pressure, components::kind, neighbours_resource, mps_pair_weights_resource,
               resources::dt, domain_resource<D>),
         writes(components::position, components::velocity, components::pressure_gradient)};
  Access access() const override { return io.access(); }
  void run(SystemContext<D>& ctx) override {
    auto [p, kind, nl, weights, dt, domain, x, v, grad] = io.fetch(ctx);
    const double* weight = weights.of(nl, "mps_pressure_correction");
    auto pressure = [&](std::size_t j) { return p_.clamp_negative_pressure ? std::max(p[j], 0.0) : p[j]; };
    // One pass over the pairs: sum_j (p_j - p^) e_j = sum_j p_j e_j - p^ sum_j e_j with
    // e_j = r_ij w_ij / |r_ij|^2, so the local minimum p^ is applied after the loop.
    for_each_of_kind(kind, kFluid, [&](std::size_t i) {
      double low = pressure(i);
      Vec<D> weighted = Vec<D>::Zero(), directions = Vec<D>::Zero();
      for (auto k = nl.offsets[i], end = nl.end(i); k != end; ++k) {
        const auto j = nl.indices[k];
        const double w = weight[k];
        if (kind[j] == kDummy || w <= 0) continue;
        Vec<D> r = domain.offset(x[i], x[j]);
        Vec<D> e = w / r.squaredNorm() * r;
        low = std::min(low, pressure(j));
        weighted += pressure(j) * e;
        directions += e;
      }
      grad[i] = (D / p_.n0) * (weighted - low * directions);
    });
    const double scale = dt / p_.rho0;
    for_each_of_kind(kind, kFluid, [&](std::size_t i) {
      Vec<D> dv = -scale * grad[i];
      v[i] += dv;
      x[i] += dt * dv;
      domain.wrap(x[i]);
    });
  }

 private:
  MpsParameters<D> p_;
};

}  // namespace ryushi
