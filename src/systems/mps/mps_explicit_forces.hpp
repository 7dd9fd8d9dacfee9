#pragma once
// The explicit part of an MPS step (BMG paper eq. 3 without the pressure term): viscosity and
// gravity give the predicted velocity and position
//   u* = u^k + dt (nu <lap u>_i + g),   x* = x^k + dt u*,
// with the MPS Laplacian (eq. 7) over fluid and wall neighbours (walls at rest: no-slip).
#include <vector>

#include "ecs/io.hpp"
#include "systems/loops/for_each_particle.hpp"
#include "systems/mps/mps_parameters.hpp"
#include "systems/neighbour/neighbour_list.hpp"

namespace ryushi {

template <int D>
class MpsExplicitForces final : public System<D> {
 public:
  explicit MpsExplicitForces(const MpsParameters<D>& p) : p_(p) {}
  std::string name() const override { return "mps_explicit_forces"; }
  static constexpr auto io =
      Io{reads(components::kind, neighbours_resource, resources::dt, domain_resource<D>),
         writes(components::position, components::velocity, components::acceleration)};
  Access access() const override { return io.access(); }
  void run(SystemContext<D>& ctx) override {
    auto [kind, nl, dt, domain, x, v, a] = io.fetch(ctx);
    const double viscous = p_.nu * p_.laplacian_coefficient();
    // Gather every acceleration from u^k first, then move: a particle never reads a neighbour's
    // already-updated velocity.
    for_each_of_kind(kind, kFluid, [&](std::size_t i) {
      Vec<D> lap = Vec<D>::Zero();
      if (viscous > 0) {
        // The weights first, in a loop the compiler vectorises (square roots and divisions
        // were most of this system's time), then the sum in the pairs' order.
        thread_local std::vector<double> w;
        const auto neighbours = nl.of(i);
        w.resize(neighbours.size());
        for (std::size_t k = 0; k < neighbours.size(); ++k)
          w[k] = domain.offset(x[i], x[neighbours[k]]).squaredNorm();
        p_.weight.mps_weights(w.data(), w.data(), w.size());
        for (std::size_t k = 0; k < neighbours.size(); ++k) {
          const auto j = neighbours[k];
          if (kind[j] == kDummy) continue;
          lap += (v[j] - v[i]) * w[k];
        }
      }
      a[i] = viscous * lap + p_.gravity;
    });
    for_each_of_kind(kind, kFluid, [&](std::size_t i) {
      v[i] += dt * a[i];
      x[i] += dt * v[i];
      domain.wrap(x[i]);
    });
  }

 private:
  MpsParameters<D> p_;
};

}  // namespace ryushi
