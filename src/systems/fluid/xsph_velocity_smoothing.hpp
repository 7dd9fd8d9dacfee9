#pragma once
// XSPH velocity smoothing (seed 001 eq. 36; Monaghan 1989), after the step's integration:
//   v_i <- v_i + eps sum_j m_j / ((rho_i + rho_j)/2) (v_j - v_i) W_ij      (fluid neighbours)
// It damps the relative motion of neighbours (the seed: against inter-penetration) and, being
// antisymmetric in (i, j) with equal masses, keeps the momentum. Which velocity it smooths is the
// integrator's: the midpoint's v^{n+1} (`velocity`), the leapfrog's v^{n+1/2}, the one that moves
// the particles and carries to the next step (`velocity_start`).
#include <vector>

#include "ecs/io.hpp"
#include "kernels/kernel.hpp"
#include "systems/loops/for_each_particle.hpp"
#include "systems/neighbour/domain.hpp"
#include "systems/neighbour/neighbour_list.hpp"

namespace ryushi {

template <int D>
class XsphVelocitySmoothing final : public System<D> {
 public:
  XsphVelocitySmoothing(const Kernel<D>& kernel, const Domain<D>& domain, double epsilon, bool half_step)
      : kernel_(kernel),
        domain_(domain),
        epsilon_(epsilon),
        column_(half_step ? components::velocity_start : components::velocity) {}
  std::string name() const override { return "xsph_velocity_smoothing"; }
  // The smoothed column is the integrator's (fixed at construction).
  auto io() const {
    return Io{reads(components::position, components::density, components::mass, components::kind,
                    neighbours_resource),
              writes(column_)};
  }
  Access access() const override { return io().access(); }
  void run(SystemContext<D>& ctx) override {
    auto [x, rho, m, kind, nl, v] = io().fetch(ctx);
    before_.assign(v.begin(), v.end());  // each particle reads its neighbours' unsmoothed velocity
    const double support2 = kernel_.support() * kernel_.support();
    for_each_of_kind(kind, kFluid, [&](std::size_t i) {
      Vec<D> sum = Vec<D>::Zero();
      for (auto j : nl.of(i)) {
        if (kind[j] != kFluid) continue;
        const double r2 = domain_.displacement(x[i], x[j]).squaredNorm();
        if (r2 >= support2) continue;
        sum += (2.0 * m[j] / (rho[i] + rho[j]) * kernel_.w(std::sqrt(r2))) * (before_[j] - before_[i]);
      }
      v[i] = before_[i] + epsilon_ * sum;
    });
  }

 private:
  Kernel<D> kernel_;
  Domain<D> domain_;
  double epsilon_;
  Component<Vector> column_;
  std::vector<Vec<D>> before_;
};

}  // namespace ryushi
