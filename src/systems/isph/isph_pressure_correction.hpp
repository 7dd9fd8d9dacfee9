#pragma once
// ISPH corrector (ISPH paper eq. 4) at the predicted positions:
//   v^{n+1} = v* - dt/rho0 <grad p>_i,   x^{n+1} = x* + dt (v^{n+1} - v*)   (x fixed if Eulerian)
// <grad p>: corrected difference form L_i sum_j V_j (p_j - p_i) gW_ij (eq. 9), or the symmetric
// form sum_j V_j (p_i + p_j) gW_ij (I-SPH(2) eq. 11: pairwise antisymmetric, momentum-conserving,
// not consistent on a cut support). Free-surface particles carry p = 0 and wall particles their
// solved pressure. The gradient is kept in `pressure_gradient` (an output field).
#include <vector>

#include "ecs/system.hpp"
#include "systems/fluid/for_each_fluid.hpp"
#include "systems/isph/isph_parameters.hpp"
#include "systems/mps/mps_parameters.hpp"  // components::pressure_gradient
#include "systems/neighbour/neighbour_list.hpp"
#include "systems/operators/gradient.hpp"

namespace ryushi {

template <int D>
class IsphPressureCorrection final : public System<D> {
 public:
  explicit IsphPressureCorrection(const IsphParameters<D>& p) : p_(p) {}
  std::string name() const override { return "isph_pressure_correction"; }
  Access access() const override {
    return Access{}
        .read(components::pressure, components::kind, components::mass, components::density,
              pressure_neighbours_resource, resources::dt)
        .write(components::position, components::velocity, components::pressure_gradient);
  }
  void run(SystemContext<D>& ctx) override {
    const double dt = ctx.read(resources::dt);
    const auto& nl = ctx.read(pressure_neighbours_resource);  // without dry walls
    auto p = ctx.read(components::pressure);
    auto kind = ctx.read(components::kind);
    auto m = ctx.read(components::mass);
    auto rho = ctx.read(components::density);
    auto x = ctx.write(components::position);
    auto v = ctx.write(components::velocity);
    auto grad = ctx.write(components::pressure_gradient);
    particle_volumes(m, rho, volume_);
    ParticleView<D> view{std::span<const Vec<D>>(x.data(), x.size()), volume_, nl, p_.kernel, p_.domain};
    for_each_of_kind(kind, kFluid, [&](std::size_t i) {
      grad[i] = p_.symmetric_gradient ? gradient_symmetric(view, p, i) : gradient_corrected(view, p, i);
    });
    const double scale = dt / p_.rho0;
    const bool eulerian = p_.description == IsphDescription::Eulerian;
    for_each_of_kind(kind, kFluid, [&](std::size_t i) {
      Vec<D> dv = -scale * grad[i];
      v[i] += dv;
      if (!eulerian) {
        x[i] += dt * dv;
        p_.domain.wrap(x[i]);
      }
    });
  }

 private:
  IsphParameters<D> p_;
  std::vector<double> volume_;
};

}  // namespace ryushi
