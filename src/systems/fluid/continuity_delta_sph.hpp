#pragma once
// Continuity equation with delta-SPH density diffusion (seed 002 eqs. 17-19):
//   drho_i/dt = rho_i sum_j V_j (v_i - v_j) . grad_i W_ij + delta h c0 sum_j V_j psi_ij . grad_i W_ij
//   psi_ij = 2 (rho_j - rho_i) (x_j - x_i) / |x_ij|^2 - (<grad rho>_i + <grad rho>_j)
// The gradient pair enters as a sum: that subtracts the linear part of rho_j - rho_i (so a
// hydrostatic density field does not diffuse) and keeps the term antisymmetric, hence mass-
// conserving. (The seed prints a difference; with x_ij = x_i - x_j the sum is what follows
// from Marrone et al. 2011.) Diffusion acts between fluid particles only; walls enter the
// divergence term with their own (prescribed) velocity.
#include "ecs/io.hpp"
#include "systems/fluid/for_each_fluid.hpp"
#include "systems/fluid/wcsph_parameters.hpp"
#include "systems/neighbour/neighbour_list.hpp"

namespace ryushi {

template <int D>
class ContinuityDeltaSph final : public System<D> {
 public:
  explicit ContinuityDeltaSph(const WcsphParameters<D>& p) : p_(p) {}
  std::string name() const override { return p_.delta > 0 ? "continuity_delta_sph" : "continuity"; }
  auto io() const {
    return Io{reads(components::position, components::velocity, components::density, components::mass,
                    components::kind, neighbours_resource),
              writes(components::density_rate), optional(p_.delta > 0, reads(components::density_gradient))};
  }
  Access access() const override { return io().access(); }
  void run(SystemContext<D>& ctx) override {
    auto [x, v, rho, m, kind, nl, drho, grad] = io().fetch(ctx);
    const bool periodic = p_.domain.any_periodic();
    const double diffusion = p_.delta * p_.kernel.h() * p_.c0;
    for_each_of_kind(kind, kFluid, [&](std::size_t i) {
      double divergence = 0, diffusive = 0;
      for (auto j : nl.of(i)) {
        Vec<D> xij = periodic ? p_.domain.displacement(x[i], x[j]) : Vec<D>(x[i] - x[j]);
        const double F = p_.kernel.grad_factor(std::sqrt(xij.squaredNorm()));
        Vec<D> gradW = xij * F;
        double Vj = m[j] / rho[j];
        divergence += Vj * (v[i] - v[j]).dot(gradW);
        if (diffusion > 0 && kind[j] == kFluid) {
          // (x_j - x_i) . grad_i W_ij / r^2 = -F exactly, so no division per pair.
          double pair = -2.0 * (rho[j] - rho[i]) * F;
          diffusive += Vj * (pair - (grad[i] + grad[j]).dot(gradW));
        }
      }
      drho[i] = rho[i] * divergence + diffusion * diffusive;
    });
  }

 private:
  WcsphParameters<D> p_;
};

}  // namespace ryushi
