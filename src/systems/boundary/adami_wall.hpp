#pragma once
// Generalised wall boundary condition (Adami, Hu & Adams 2012; seed 002 eqs. 27-28):
// each wall particle takes the Shepard-weighted pressure of the fluid around it plus the
// correction (g - a_w) . sum(rho_f (x_w - x_f) W), a_w the wall's prescribed acceleration (a
// piston, a shaken tank; zero for walls at rest or sliding at a constant velocity), its density
// from the inverse equation of state, and (when laminar viscosity is on) a ghost velocity
// 2 v_wall - v~ for no-slip, v_wall being the wall particle's own velocity: zero for containers,
// a [[solid]]'s prescribed velocity for a lid, a sliding plate or a moving body. The particles of
// [[elastic]] bodies get the same rows: to the fluid they are walls that move.
#include "ecs/io.hpp"
#include "systems/fluid/wcsph_parameters.hpp"
#include "systems/loops/for_each_particle.hpp"
#include "systems/neighbour/neighbour_list.hpp"

namespace ryushi {

template <int D>
class AdamiWall final : public System<D> {
 public:
  explicit AdamiWall(const WcsphParameters<D>& p) : p_(p) {}
  std::string name() const override { return "wall_boundary_adami"; }
  auto io() const {
    return Io{reads(components::position, components::velocity, components::kind, neighbours_resource),
              writes(components::pressure, components::density),
              optional(p_.viscous(), writes(components::wall_velocity)),
              optional(p_.wall_acceleration, reads(components::body_acceleration))};
  }
  Access access() const override { return io().access(); }
  void run(SystemContext<D>& ctx) override {
    auto [x, v, kind, nl, p, rho, ghost, acceleration] = io().fetch(ctx);
    const bool periodic = p_.domain.any_periodic();
    // felt(w): the acceleration the fluid's weight presses the wall with, g - a_w.
    auto condition = [&](std::size_t w, auto&& felt) {
      double sum_w = 0, sum_p = 0;
      Vec<D> sum_rho_r = Vec<D>::Zero(), sum_v = Vec<D>::Zero();
      for (auto f : nl.of(w)) {
        if (kind[f] != kFluid) continue;
        Vec<D> r = periodic ? p_.domain.displacement(x[w], x[f]) : Vec<D>(x[w] - x[f]);
        double W = p_.kernel.w(r.norm());
        sum_w += W;
        sum_p += p[f] * W;
        sum_rho_r += rho[f] * r * W;
        sum_v += v[f] * W;
      }
      double pw = sum_w > 0 ? (sum_p + felt(w).dot(sum_rho_r)) / sum_w : 0.0;
      p[w] = pw;
      rho[w] = p_.density(pw);
      if (!ghost.empty()) ghost[w] = sum_w > 0 ? Vec<D>(2 * v[w] - sum_v / sum_w) : v[w];
    };
    for_each_of_kind(kind, kWall, [&](std::size_t w) {
      condition(w, [&](std::size_t i) {
        return acceleration.empty() ? p_.gravity : Vec<D>(p_.gravity - acceleration[i]);
      });
    });
    // An elastic body's particles are walls that move with the solid, felt with g alone: their
    // acceleration carries the body's elastic vibration (c_s ~ 150 m/s, 1e4 m/s^2), and taken
    // into the wall pressure it drove the water beside a gate to negative density at t = 0.044 s.
    if (p_.elastic_bodies)
      for_each_of_kind(kind, kElastic,
                       [&](std::size_t w) { condition(w, [&](std::size_t) { return p_.gravity; }); });
  }

 private:
  WcsphParameters<D> p_;
};

}  // namespace ryushi
