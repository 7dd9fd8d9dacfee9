#pragma once
// Pair collisions (Koshizuka et al. 1998; Lee et al. 2011): two particles closer than the
// collision distance that still approach each other exchange the approaching part of their
// relative velocity as an inelastic collision with restitution e,
//   du_i = -(1 + e) m_j / (m_i + m_j) ((u_i - u_j) . n) n,   n = (x_j - x_i) / |x_j - x_i|,
// with walls as infinite masses at rest; then x_i += dt du_i. Momentum is conserved pair by pair;
// kinetic energy is only lost. A pair at the lattice spacing or farther, or moving apart, is never
// touched, so a fluid at rest does not see it.
// Why a projection method needs it: the pressure gradient of a consistent (corrected) operator does
// not push a close pair apart, so nothing stops particles from closing in on each other in a
// violent flow (MPS: a fast particle reaching a wall particle, where the weight r_e / r - 1
// diverges; ISPH: the fragmented flow after a plunging wave, docs/isph.md, "One set-up").
// Wall pairs may take a longer distance: a particle crossing a wall layer through the middle of a
// lattice square passes 0.71 d from its four corners (3D); 0 leaves wall pairs alone. Every
// particle gathers from the velocities before the collision (no order dependence) and writes only
// itself.
#include <string>
#include <vector>

#include "ecs/io.hpp"
#include "systems/loops/for_each_particle.hpp"
#include "systems/neighbour/neighbour_list.hpp"

namespace ryushi {

struct PairCollisionParameters {
  std::string name;       // the system's name in the timings: mps_collision, isph_collision
  double fluid_distance;  // between fluid particles (m)
  double wall_distance;   // between a fluid and a wall or dummy particle (m); 0: none
  double restitution;     // e
};

template <int D>
class PairCollision final : public System<D> {
 public:
  explicit PairCollision(PairCollisionParameters p) : p_(std::move(p)) {}
  std::string name() const override { return p_.name; }
  static constexpr auto io =
      Io{reads(components::kind, neighbours_resource, resources::dt, domain_resource<D>),
         writes(components::position, components::velocity)};
  Access access() const override { return io.access(); }
  void run(SystemContext<D>& ctx) override {
    auto [kind, nl, dt, domain, x, v] = io.fetch(ctx);
    dv_.resize(x.size());
    auto& dv = dv_;
    const double fluid2 = p_.fluid_distance * p_.fluid_distance, wall2 = p_.wall_distance * p_.wall_distance;
    for_each_of_kind(kind, kFluid, [&](std::size_t i) {
      Vec<D> change = Vec<D>::Zero();
      for (auto j : nl.of(i)) {
        Vec<D> r = domain.offset(x[i], x[j]);
        double r2 = r.squaredNorm();
        if (r2 >= (kind[j] == kFluid ? fluid2 : wall2) || r2 == 0) continue;
        Vec<D> n = r / std::sqrt(r2);
        double approach = (v[i] - v[j]).dot(n);  // > 0: closing in
        if (approach <= 0) continue;
        double share = kind[j] == kFluid ? 0.5 : 1.0;  // equal masses; a wall does not move
        change -= (1 + p_.restitution) * share * approach * n;
      }
      dv[i] = change;
    });
    for_each_of_kind(kind, kFluid, [&](std::size_t i) {
      v[i] += dv[i];
      x[i] += dt * dv[i];
      domain.wrap(x[i]);
    });
  }

 private:
  PairCollisionParameters p_;
  std::vector<Vec<D>> dv_;  // this step's velocity change per particle (scratch)
};

}  // namespace ryushi
