#pragma once
// Particle number density at the predicted positions, n*_i = sum_{j != i} w(r_ij) (BMG paper
// eq. 6), for fluid and wall particles, and the free-surface rule of MPS: a particle with
// n*_i < beta n0 is on the surface and gets the Dirichlet value p = 0 (Koshizuka's beta = 0.97).
// Writes the `pressure_role` of every particle (unknown, surface, none for dummies) and the
// density of the Poisson source: rho0 n* / n0, or with the smooth source rho0 s*_i / s0, s*_i =
// sum_{j != i} W(r_ij) with the Wendland kernel of MpsParameters::source_kernel over the same
// neighbours (the weight's singular core reads disorder as compression; docs/mps.md).
//
// The list it reads holds the step's motion (pairs within r_e + 2.5 cfl l0 at x^k); from x* on
// only the pairs within r_e count. This system narrows the list to r_e at x* in the same pass
// that computes the weights (filter_rows.hpp: each distance once, where a separate filter and
// this sum computed each twice), and keeps each pair's weight for the systems after it at the
// same positions (mps_pair_weights.hpp). The narrowed list is row for row the one
// filter_neighbour_list gives, and the weights and sums are the ones computed before, bit for
// bit.
#include "ecs/io.hpp"
#include "systems/loops/for_each_particle.hpp"
#include "systems/mps/mps_pair_weights.hpp"
#include "systems/mps/mps_parameters.hpp"
#include "systems/neighbour/filter_rows.hpp"
#include "systems/neighbour/neighbour_search.hpp"

namespace ryushi {

template <int D>
class MpsNumberDensity final : public System<D> {
 public:
  explicit MpsNumberDensity(const MpsParameters<D>& p) : p_(p) {}
  std::string name() const override { return "mps_number_density"; }
  static constexpr auto io = Io{reads(components::position, components::kind, domain_resource<D>),
                                writes(neighbours_resource, components::number_density, components::density,
                                       components::pressure_role, mps_pair_weights_resource)};
  Access access() const override { return io.access(); }
  void initialise(World<D>&, Resources& res) override { res.ensure(mps_pair_weights_resource); }
  void run(SystemContext<D>& ctx) override {
    auto [x, kind, domain, list, n, rho, role, weights] = io.fetch(ctx);
    double* weight = weights.w.ensure(list.indices.size());  // the narrowed list has the wide one's slots
    weights.slots = list.indices.size();
    // Per row, the survivors' weights from their squared distances (a loop the compiler
    // vectorises) into the row's slots, then their sum in the pairs' order. Dummy rows are
    // narrowed too (a later system may read them) but carry no number density.
    auto row = [&](std::size_t i, const double* r2) {
      if (kind[i] == kDummy) {
        n[i] = p_.n0;
        role[i] = kPressureNone;
        return;
      }
      const auto count = list.count(i);
      double* w = weight + list.offsets[i];
      p_.weight.mps_weights(r2, w, count);
      double sum = 0;
      for (std::uint32_t k = 0; k < count; ++k) sum += w[k];
      n[i] = sum;
      rho[i] = p_.smooth_source ? p_.rho0 * p_.source_kernel.wendland_sum(r2, count) / p_.source_n0
                                : p_.rho0 * sum / p_.n0;
      role[i] = sum < p_.surface_threshold * p_.n0 ? kPressureSurface : kPressureUnknown;
    };
    filter_rows<D, true>(domain, p_.weight.support(), x, list, list, row);  // in place
  }

 private:
  MpsParameters<D> p_;
};

}  // namespace ryushi
