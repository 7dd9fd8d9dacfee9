#pragma once
// Adaptive time step for the next step: the smallest of
//   CFL:      cfl * h / (c0 + |v|max)
//   force:    0.25 * sqrt(h / |a|max)
//   viscous:  0.125 * h^2 / nu            (only with laminar viscosity)
// (cf. seed 001 eq. 35, which takes h/(|v|+c) and h^2/(6 nu) with a factor 1/10.)
#include <tbb/blocked_range.h>
#include <tbb/parallel_reduce.h>

#include <algorithm>

#include "ecs/system.hpp"
#include "systems/fluid/wcsph_parameters.hpp"

namespace ryushi {

template <int D>
class TimeStepControl final : public System<D> {
 public:
  TimeStepControl(const WcsphParameters<D>& p, double cfl) : p_(p), cfl_(cfl) {}
  std::string name() const override { return "time_step_control"; }
  Access access() const override {
    return Access{}
        .read(components::velocity, components::acceleration, components::kind)
        .write(resources::dt);
  }
  void run(SystemContext<D>& ctx) override {
    auto v = ctx.read(components::velocity);
    auto a = ctx.read(components::acceleration);
    auto kind = ctx.read(components::kind);
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
    ctx.write(resources::dt) = limit(std::sqrt(m.first), std::sqrt(m.second));
  }
  double limit(double vmax, double amax) const {
    const double h = p_.kernel.h();
    double dt = cfl_ * h / (p_.c0 + vmax);
    if (amax > 0) dt = std::min(dt, 0.25 * std::sqrt(h / amax));
    if (p_.mu > 0) dt = std::min(dt, 0.125 * h * h * p_.rho0 / p_.mu);
    return dt;
  }

 private:
  WcsphParameters<D> p_;
  double cfl_;
};

}  // namespace ryushi
