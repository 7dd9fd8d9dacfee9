#pragma once
// Particle number density at the predicted positions, n*_i = sum_{j != i} w(r_ij) (BMG paper
// eq. 6), for fluid and wall particles, and the free-surface rule of MPS: a particle with
// n*_i < beta n0 is on the surface and gets the Dirichlet value p = 0 (Koshizuka's beta = 0.97).
// Writes the `pressure_role` of every particle (unknown, surface, none for dummies) and, for
// output, density = rho0 n* / n0. Each pair's weight is kept for the systems after it at the
// same positions (mps_pair_weights.hpp).
#include "ecs/system.hpp"
#include "systems/fluid/for_each_fluid.hpp"
#include "systems/mps/mps_pair_weights.hpp"
#include "systems/mps/mps_parameters.hpp"
#include "systems/neighbour/neighbour_list.hpp"

namespace ryushi {

template <int D>
class MpsNumberDensity final : public System<D> {
 public:
  explicit MpsNumberDensity(const MpsParameters<D>& p) : p_(p) {}
  std::string name() const override { return "mps_number_density"; }
  Access access() const override {
    return Access{}
        .read(components::position, components::kind, neighbours_resource, domain_resource<D>)
        .write(components::number_density, components::density, components::pressure_role,
               mps_pair_weights_resource);
  }
  void initialise(World<D>&, Resources& res) override { res.ensure(mps_pair_weights_resource); }
  void run(SystemContext<D>& ctx) override {
    const auto& nl = ctx.read(neighbours_resource);
    const auto& domain = ctx.read(domain_resource<D>);
    auto x = ctx.read(components::position);
    auto kind = ctx.read(components::kind);
    auto n = ctx.write(components::number_density);
    auto rho = ctx.write(components::density);
    auto role = ctx.write(components::pressure_role);
    auto& weights = ctx.write(mps_pair_weights_resource);
    double* weight = weights.w.ensure(nl.indices.size());
    weights.slots = nl.indices.size();
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, x.size(), 1024), [&](auto range) {
      for (std::size_t i = range.begin(); i != range.end(); ++i) {
        if (kind[i] == kDummy) {
          n[i] = p_.n0;
          role[i] = kPressureNone;
          continue;
        }
        // Squared distances into the row's weight slots, then the weights in place (a loop
        // the compiler vectorises), then their sum in the pairs' order.
        const auto first = nl.offsets[i], count = nl.count(i);
        double* w = weight + first;
        for (std::uint32_t k = 0; k < count; ++k)
          w[k] = domain.offset(x[i], x[nl.indices[first + k]]).squaredNorm();
        p_.weight.mps_weights(w, w, count);
        double sum = 0;
        for (std::uint32_t k = 0; k < count; ++k) sum += w[k];
        n[i] = sum;
        rho[i] = p_.rho0 * sum / p_.n0;
        role[i] = sum < p_.surface_threshold * p_.n0 ? kPressureSurface : kPressureUnknown;
      }
    });
  }

 private:
  MpsParameters<D> p_;
};

}  // namespace ryushi
