#pragma once
// XSPH as a shifting model (I-SPH(2) eq. 9, after Monaghan 1989): a particle is transported with
// its velocity smoothed over its neighbours, so the shift relative to the fluid is
//   dr_i = eps dt sum_j 2 m_j / (rho_i + rho_j) (v_j - v_i) W_ij      (fluid neighbours),
// and, as for the other models, the velocity is carried to the new place (ALE). The momentum
// velocity itself is not smoothed: what XSPH removes is the relative jitter of neighbours, which
// is what disorders the particles; the I-SPH(2) paper uses it for its rotating square. `eps` is a
// scene key (0.5 by default, Monaghan's value); the shift is capped at `max_shift` d.
#include <vector>

#include "ecs/io.hpp"
#include "systems/loops/for_each_particle.hpp"
#include "systems/neighbour/neighbour_list.hpp"
#include "systems/shifting/density_shifting.hpp"  // components::shift
#include "systems/shifting/shift_velocity.hpp"

namespace ryushi {

template <int D>
struct XsphShiftingParameters {
  Kernel<D> kernel{KernelType::CubicSpline, 1.0};
  Domain<D> domain;
  double spacing = 1;
  double epsilon = 0.5;
  double max_shift = 0.2;  // cap, in spacings
};

template <int D>
class XsphShifting final : public System<D> {
 public:
  explicit XsphShifting(const XsphShiftingParameters<D>& p) : p_(p) {}
  std::string name() const override { return "particle_shifting"; }
  static constexpr auto io =
      Io{reads(components::mass, components::density, components::kind, neighbours_resource, resources::dt),
         writes(components::position, components::velocity, components::shift)};
  Access access() const override { return io.access(); }
  void run(SystemContext<D>& ctx) override {
    auto [m, rho, kind, nl, dt, x, v, shift] = io.fetch(ctx);
    particle_volumes(m, rho, volume_);
    dv_.resize(m.size());
    ParticleView<D> view{std::span<const Vec<D>>(x.data(), x.size()), volume_, nl, p_.kernel, p_.domain};
    const double cap = p_.max_shift * p_.spacing;
    for_each_of_kind(kind, kFluid, [&](std::size_t i) {
      thread_local std::vector<Vec<D>> g;
      Vec<D> smoothing = Vec<D>::Zero();
      for (auto j : nl.of(i)) {
        if (kind[j] != kFluid) continue;
        const double len = view.r(i, j).norm();
        if (len >= p_.kernel.support()) continue;
        smoothing += 2 * m[j] / (rho[i] + rho[j]) * p_.kernel.w(len) * (v[j] - v[i]);
      }
      Vec<D> dr = p_.epsilon * dt * smoothing;
      const double len = dr.norm();
      if (len > cap) dr *= cap / len;
      shift[i] = dr;
      dv_[i] = shifted_velocity_change(view, std::span<const Vec<D>>(v.data(), v.size()), i, dr, g);
    });
    apply_shifts<D>(kind, p_.domain, shift, dv_, x, v);
  }

 private:
  XsphShiftingParameters<D> p_;
  std::vector<double> volume_;
  std::vector<Vec<D>> dv_;
};

}  // namespace ryushi
