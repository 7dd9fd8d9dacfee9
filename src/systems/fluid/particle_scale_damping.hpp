#pragma once
// Damping of the velocity's particle-scale part (a biharmonic filter), after the step's solve:
//   L v_i = 1 / (S m_i) sum_j mu_ij W_ij (v_j - v_i)    (fluid neighbours; S the lattice's kernel
//                                                        sum, mu_ij = 2 m_i m_j / (m_i + m_j))
//   v_i  <- v_i - eps L(L v)_i
// L is XSPH's smoothing without its coefficient. For a smooth field L v ~ (sigma^2 / 2) lap v, so
// XSPH (v + eps L v) damps a wave of length lambda at a rate of eps (k sigma)^2 / 2 a step: with
// the few-hundred steps a sloshing period takes it is a viscosity of hundreds of times water's.
// L applied twice damps it at eps (k sigma)^4 / 4 instead (a 1 m wave against a support of 3 cm:
// 400x less) while a particle-scale mode, where L v ~ -v, still loses about eps a step. Each pair
// term is antisymmetric, so the momentum is kept; L is symmetric in the mass-weighted product, so
// the kinetic energy can only fall (by eps sum_i m_i |L v_i|^2). What it is for (docs/isph.md,
// "Particle-scale damping"): the implicit density formulation's resting tanks jitter at 6-8e-4 sqrt(g H)
// below the surface rows, where water's viscosity damps nothing at the particle scale.
#include <vector>

#include "ecs/io.hpp"
#include "kernels/kernel.hpp"
#include "kernels/lattice_kernel_sum.hpp"
#include "systems/loops/for_each_particle.hpp"
#include "systems/neighbour/domain.hpp"
#include "systems/neighbour/neighbour_list.hpp"

namespace ryushi {

template <int D>
class ParticleScaleDamping final : public System<D> {
 public:
  ParticleScaleDamping(const Kernel<D>& kernel, const Domain<D>& domain, double spacing, double epsilon)
      : kernel_(kernel),
        domain_(domain),
        inverse_sum_(1.0 / lattice_kernel_sum(kernel, spacing, kernel.support())),
        epsilon_(epsilon) {}
  std::string name() const override { return "particle_scale_damping"; }
  static constexpr auto io =
      Io{reads(components::position, components::mass, components::kind, neighbours_resource),
         writes(components::velocity)};
  Access access() const override { return io.access(); }
  void run(SystemContext<D>& ctx) override {
    auto [x, m, kind, nl, v] = io.fetch(ctx);
    once_.assign(v.size(), Vec<D>::Zero());
    smoothing(x, m, kind, nl, v, once_);
    twice_.assign(v.size(), Vec<D>::Zero());
    smoothing(x, m, kind, nl, once_, twice_);
    for_each_of_kind(kind, kFluid, [&](std::size_t i) { v[i] -= epsilon_ * twice_[i]; });
  }

 private:
  // out_i = L in_i over the fluid neighbours within the support.
  template <class Positions, class Masses, class Kinds, class Field>
  void smoothing(const Positions& x, const Masses& m, const Kinds& kind, const NeighbourList& nl,
                 const Field& in, std::vector<Vec<D>>& out) const {
    const double support2 = kernel_.support() * kernel_.support();
    for_each_of_kind(kind, kFluid, [&](std::size_t i) {
      Vec<D> sum = Vec<D>::Zero();
      for (auto j : nl.of(i)) {
        if (kind[j] != kFluid) continue;
        const double r2 = domain_.displacement(x[i], x[j]).squaredNorm();
        if (r2 >= support2) continue;
        sum += (2.0 * m[j] / (m[i] + m[j]) * kernel_.w(std::sqrt(r2))) * (in[j] - in[i]);
      }
      out[i] = inverse_sum_ * sum;
    });
  }

  Kernel<D> kernel_;
  Domain<D> domain_;
  double inverse_sum_, epsilon_;
  std::vector<Vec<D>> once_, twice_;
};

}  // namespace ryushi
