#pragma once
// Each fluid particle's shear rate and apparent viscosity (rheology.hpp) for the viscous term of
// the pair forces, from the renormalised velocity gradient
//   G_i = L_i sum_j V_j grad_i W_ij (v_j - v_i)^T,   L_i = [sum_j V_j grad_i W_ij (x_j - x_i)^T]^-1
// (exact for a linear velocity field; the uncorrected sum where L_i is ill-conditioned, as the
// operator library's corrected gradient), D = G + G^T (seed 001 eq. 3), gamma_dot = sqrt(D:D / 2).
// No-slip walls enter with their ghost velocity (Adami's, written by the wall system before
// this one), so the shear at the wall is seen; slip walls are left out. The model's viscosity
// then uses the particle's temperature when it depends on it (Arrhenius).
#include <cmath>

#include "ecs/io.hpp"
#include "ecs/outer_sum.hpp"
#include "materials/rheology.hpp"
#include "systems/heat/heat_parameters.hpp"
#include "systems/loops/for_each_particle.hpp"
#include "systems/neighbour/neighbour_list.hpp"
#include "systems/operators/renormalisation.hpp"

namespace ryushi {

namespace components {
inline constexpr Component<Scalar> shear_rate{"shear_rate"};  // 1/s
}

template <int D>
struct ApparentViscosityParameters {
  Kernel<D> kernel{KernelType::WendlandC2, 1.0};
  Domain<D> domain;
  Rheology rheology;
  bool no_slip_walls = true;  // walls enter the gradient with their ghost velocity
  bool walls = false;         // the scene has walls (the ghost-velocity column exists)
};

template <int D>
class ApparentViscosity final : public System<D> {
 public:
  explicit ApparentViscosity(const ApparentViscosityParameters<D>& p) : p_(p) {}
  std::string name() const override { return "viscosity_rheology"; }
  auto io() const {
    return Io{reads(components::position, components::velocity, components::density, components::mass,
                    components::kind, neighbours_resource),
              writes(components::shear_rate, components::viscosity),
              optional(uses_walls(), reads(components::wall_velocity)),
              optional(p_.rheology.temperature_dependent(), reads(components::temperature))};
  }
  Access access() const override { return io().access(); }
  // Before the first step (frame 0): the viscosity at rest, at each particle's temperature.
  void initialise(World<D>& world, Resources&) override {
    auto& mu = world.ensure(components::viscosity);
    world.ensure(components::shear_rate);
    const bool thermal = p_.rheology.temperature_dependent();
    for (std::size_t i = 0; i < mu.size(); ++i)
      mu[i] = p_.rheology.apparent(0.0, thermal ? world.column(components::temperature)[i] : 0.0);
  }
  void run(SystemContext<D>& ctx) override {
    // ghost, T: empty without no-slip walls, without a temperature-dependent model.
    auto [x, v, rho, m, kind, nl, rate, mu, ghost, T] = io().fetch(ctx);
    particle_volumes(m, rho, volume_);
    const double support2 = p_.kernel.support() * p_.kernel.support();
    for_each_of_kind(kind, kFluid, [&](std::size_t i) {
      OuterSum<D> moments, velocity_moments;
      for (auto j : nl.of(i)) {
        const bool fluid_j = kind[j] == kFluid;
        if (!fluid_j && ghost.empty()) continue;
        const Vec<D> r = p_.domain.offset(x[i], x[j]);  // x_j - x_i
        const double r2 = r.squaredNorm();
        if (r2 >= support2) continue;
        const Vec<D> gw = -volume_[j] * p_.kernel.grad_factor(std::sqrt(r2)) * r;  // V_j grad_i W_ij
        const Vec<D> vj = fluid_j ? v[j] : ghost[j];
        moments.add(gw, r);
        velocity_moments.add(gw, Vec<D>(vj - v[i]));
      }
      const Mat<D> M = moments.matrix();
      Mat<D> G = velocity_moments.matrix();
      if (M.determinant() > kMinRenormalisationDeterminant) G = M.inverse() * G;
      const Mat<D> Dm = G + G.transpose();
      rate[i] = std::sqrt(0.5 * Dm.squaredNorm());
      mu[i] = p_.rheology.apparent(rate[i], T.empty() ? 0.0 : T[i]);
    });
  }

 private:
  bool uses_walls() const { return p_.walls && p_.no_slip_walls; }
  ApparentViscosityParameters<D> p_;
  std::vector<double> volume_;
};

}  // namespace ryushi
