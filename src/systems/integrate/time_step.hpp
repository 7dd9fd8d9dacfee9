#pragma once
// Adaptive time step for the next step: the smallest of
//   CFL:      cfl * h / (c0 + |v|max)
//   force:    0.25 * sqrt(h / |a|max)
//   viscous:  0.125 * h^2 / nu            (only with laminar viscosity; with a rheology model
//             nu is the largest apparent viscosity of the fluid this step over rho0)
//   thermal:  0.125 * h^2 / alpha         (only with heat conduction, alpha = k / (rho0 c))
//   solid:    cfl * h / (c_s + |v|max)    (only with elastic bodies, c_s their largest sound speed)
// or, with the seed001 rule, seed 001 eq. 35: 0.1 min(h / (|v|max + c0), h^2 / (6 nu)), both
// bounded by the thermal limit.
// The viscous and thermal limits are for the midpoint integrator. The leapfrog takes half of
// each (diffusion_scale 0.5): on a decaying mode dq/dt = -lambda q its half-step kick with the
// predicted full-step value gives q^{n+1} = (1 - 3z/2) q^n + (z/2) q^{n-1}, z = lambda dt, whose
// root reaches -1 at z = 1, where the two-stage midpoint is stable to z = 2 (measured: the
// conduction test at L/d = 40 grew to 1e5 K with the leapfrog at the midpoint's limit).
#include <tbb/blocked_range.h>
#include <tbb/parallel_reduce.h>

#include <algorithm>

#include "ecs/io.hpp"
#include "systems/fluid/wcsph_parameters.hpp"

namespace ryushi {

template <int D>
class TimeStepControl final : public System<D> {
 public:
  // thermal_limit: the heat conduction's fixed step limit (0: none); diffusion_scale: the
  // integrator's share of the diffusion limits (1 midpoint, 0.5 leapfrog).
  TimeStepControl(const WcsphParameters<D>& p, double cfl, double thermal_limit = 0,
                  bool seed001_rule = false, double diffusion_scale = 1)
      : p_(p),
        cfl_(cfl),
        thermal_limit_(diffusion_scale * thermal_limit),
        seed001_(seed001_rule),
        diffusion_scale_(diffusion_scale) {}
  std::string name() const override { return "time_step_control"; }
  auto io() const {
    return Io{reads(components::velocity, components::acceleration, components::kind), writes(resources::dt),
              optional(p_.variable_viscosity, reads(components::viscosity))};
  }
  Access access() const override { return io().access(); }
  void run(SystemContext<D>& ctx) override {
    auto [v, a, kind, dt, column] = io().fetch(ctx);
    using Pair = std::pair<double, double>;  // max |v|^2, max |a|^2
    Pair m = tbb::parallel_reduce(
        tbb::blocked_range<std::size_t>(0, v.size(), 4096), Pair{0, 0},
        [&](auto r, Pair acc) {
          for (std::size_t i = r.begin(); i != r.end(); ++i) {
            if (kind[i] != kFluid) continue;
            acc.first = std::max(acc.first, v[i].squaredNorm());
            acc.second = std::max(acc.second, a[i].squaredNorm());
          }
          return acc;
        },
        [](Pair x, Pair y) { return Pair{std::max(x.first, y.first), std::max(x.second, y.second)}; });
    double mu = p_.mu;
    if (p_.variable_viscosity) {
      mu = tbb::parallel_reduce(
          tbb::blocked_range<std::size_t>(0, column.size(), 4096), 0.0,
          [&](auto r, double acc) {
            for (std::size_t i = r.begin(); i != r.end(); ++i)
              if (kind[i] == kFluid) acc = std::max(acc, column[i]);
            return acc;
          },
          [](double x, double y) { return std::max(x, y); });
    }
    dt = limit(std::sqrt(m.first), std::sqrt(m.second), mu);
  }
  // mu: the largest dynamic viscosity present (negative: the scene's, p.mu).
  double limit(double vmax, double amax, double mu = -1) const {
    const double h = p_.kernel.h();
    if (mu < 0) mu = p_.mu;
    if (seed001_) {
      double dt = h / (vmax + std::max(p_.c0, p_.solid_sound_speed));
      if (mu > 0) dt = std::min(dt, h * h * p_.rho0 / (6.0 * mu));
      dt *= 0.1;
      return thermal_limit_ > 0 ? std::min(dt, thermal_limit_) : dt;
    }
    double dt = cfl_ * h / (p_.c0 + vmax);
    if (p_.solid_sound_speed > 0) dt = std::min(dt, cfl_ * h / (p_.solid_sound_speed + vmax));
    if (amax > 0) dt = std::min(dt, 0.25 * std::sqrt(h / amax));
    if (mu > 0) dt = std::min(dt, diffusion_scale_ * 0.125 * h * h * p_.rho0 / mu);
    if (thermal_limit_ > 0) dt = std::min(dt, thermal_limit_);
    return dt;
  }

 private:
  WcsphParameters<D> p_;
  double cfl_, thermal_limit_;
  bool seed001_;
  double diffusion_scale_;
};

}  // namespace ryushi
