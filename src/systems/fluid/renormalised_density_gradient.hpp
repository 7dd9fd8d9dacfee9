#pragma once
// Renormalised density gradient <grad rho>_i = L_i sum_j V_j (rho_j - rho_i) grad_i W_ij
// (seed 002 eqs. 20-21), feeding the delta-SPH diffusion term. It is the corrected gradient of
// the operator library (systems/operators/gradient.hpp) applied to the density with volumes
// V_j = m_j / rho_j, including its documented fallback to the uncorrected gradient where L_i is
// ill-conditioned (a splash).
#include "ecs/io.hpp"
#include "systems/fluid/wcsph_parameters.hpp"
#include "systems/loops/for_each_particle.hpp"
#include "systems/operators/gradient.hpp"

namespace ryushi {

template <int D>
class RenormalisedDensityGradient final : public System<D> {
 public:
  explicit RenormalisedDensityGradient(const WcsphParameters<D>& p) : p_(p) {}
  std::string name() const override { return "density_gradient_renormalised"; }
  static constexpr auto io = Io{reads(components::position, components::density, components::mass,
                                      components::kind, neighbours_resource),
                                writes(components::density_gradient)};
  Access access() const override { return io.access(); }
  void run(SystemContext<D>& ctx) override {
    auto [x, rho, m, kind, nl, grad] = io.fetch(ctx);
    particle_volumes(m, rho, volume_);
    ParticleView<D> view{x, volume_, nl, p_.kernel, p_.domain};
    for_each_of_kind(kind, kFluid, [&](std::size_t i) { grad[i] = gradient_corrected(view, rho, i); });
  }

 private:
  WcsphParameters<D> p_;
  std::vector<double> volume_;
};

}  // namespace ryushi
