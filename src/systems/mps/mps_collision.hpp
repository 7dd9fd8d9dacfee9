#pragma once
// Collision model of MPS (Koshizuka et al. 1998; Lee et al. 2011): two particles closer than
// the collision distance alpha l0 that still approach each other exchange the approaching part
// of their relative velocity as an inelastic collision with restitution e,
//   du_i = -(1 + e) m_j / (m_i + m_j) ((u_i - u_j) . n) n,   n = (x_j - x_i) / |x_j - x_i|,
// with walls as infinite masses at rest; then x_i += dt du_i. The pressure gradient alone lets
// fast particles reach a wall particle at a violent impact (the dam break's far wall), where the
// weight r_e / r - 1 diverges. Wall pairs use a longer distance: a particle crossing a wall
// layer through the middle of a lattice square passes 0.71 l0 from its four corners (3D), so a
// 0.5 l0 distance never fires there; at 0.8 l0 an approaching particle is turned back before it
// is 0.62 l0 from the wall plane, and a fluid particle at rest (l0 from the wall) is untouched. Every
// particle gathers from the velocities before the collision (no order dependence) and writes only itself.
#include "ecs/io.hpp"
#include "systems/loops/for_each_particle.hpp"
#include "systems/mps/mps_parameters.hpp"
#include "systems/neighbour/neighbour_list.hpp"

namespace ryushi {

template <int D>
class MpsCollision final : public System<D> {
 public:
  MpsCollision(const MpsParameters<D>& p, double distance, double wall_distance, double restitution)
      : p_(p),
        distance_(distance * p.spacing),
        wall_distance_(wall_distance * p.spacing),
        restitution_(restitution) {}
  std::string name() const override { return "mps_collision"; }
  static constexpr auto io =
      Io{reads(components::kind, neighbours_resource, resources::dt, domain_resource<D>),
         writes(components::position, components::velocity)};
  Access access() const override { return io.access(); }
  void run(SystemContext<D>& ctx) override {
    auto [kind, nl, dt, domain, x, v] = io.fetch(ctx);
    dv_.resize(x.size());
    auto& dv = dv_;
    const double fluid2 = distance_ * distance_, wall2 = wall_distance_ * wall_distance_;
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
        change -= (1 + restitution_) * share * approach * n;
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
  MpsParameters<D> p_;
  double distance_, wall_distance_, restitution_;
  std::vector<Vec<D>> dv_;  // this step's velocity change per particle (scratch)
};

}  // namespace ryushi
