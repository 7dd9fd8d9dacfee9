#pragma once
// The last line of defence of ISPH's single wall layer: a fluid particle that came closer than
// `min_distance` to a wall plane loses the approaching normal velocity and is mirrored back to
// that distance. The planes are those of the wall particles it stands in front of (its offset
// along the wall within 0.75 d; wall particles beyond reach never judge it, so a particle above a
// step is not pushed off it by the step's side). Until 2026-11-28 only the nearest wall particle's
// plane counted; beside a box's corner that is the corner particle with the bisector normal, whose
// plane cuts the corner off: the coarse I-SPH(2) column put particle centres at (3.0017, -0.0034),
// past both faces (x = 3, y = 0), and the right-wall and floor particles beside the corner, which
// it stood in front of, did not count. Only the normal component is touched, so a sheet running
// fast along a wall keeps its speed. Without it,
// the fluid under the dam break's returning wave seeped through the floor at t = 1.1-1.3 s (one
// layer: nothing behind the Neumann rows); MPS's pair collision (mps_collision), tried in its
// place, took the tangential motion towards the next wall particle for an approach and threw the
// run-up sheet off the far wall at 8 m/s. A resting fluid lies one spacing from its walls and is
// never touched. Counts its interventions (`wall_guard_events`, in summary.json).
#include <atomic>

#include "ecs/io.hpp"
#include "systems/isph/isph_parameters.hpp"
#include "systems/loops/for_each_particle.hpp"
#include "systems/neighbour/neighbour_list.hpp"

namespace ryushi {

namespace resources {
inline constexpr Resource<std::size_t> wall_guard_events{"wall_guard_events"};
}

template <int D>
class IsphWallGuard final : public System<D> {
 public:
  IsphWallGuard(const Domain<D>& domain, double min_distance, double spacing)
      : domain_(domain), min_distance_(min_distance), lateral2_(0.5625 * spacing * spacing) {}
  std::string name() const override { return "wall_guard"; }
  static constexpr auto io =
      Io{reads(components::kind, components::wall_normal, neighbours_resource),
         writes(components::position, components::velocity, resources::wall_guard_events)};
  Access access() const override { return io.access(); }
  void initialise(World<D>&, Resources& res) override { res.ensure(resources::wall_guard_events); }
  void run(SystemContext<D>& ctx) override {
    auto [kind, normal, nl, x, v, total] = io.fetch(ctx);
    std::atomic<std::size_t> events{0};
    for_each_of_kind(kind, kFluid, [&](std::size_t i) {
      bool moved = false;
      for (auto j : nl.of(i)) {
        if (kind[j] != kWall) continue;
        const Vec<D>& n = normal[j];                  // out of the fluid
        const Vec<D> r = domain_.offset(x[j], x[i]);  // x_i - x_j
        const double depth = -n.dot(r);               // > 0 on the fluid side
        if (depth >= min_distance_ || (r + depth * n).squaredNorm() >= lateral2_) continue;
        // Mirrored about the plane at min_distance, not put onto it: two particles coming in one
        // behind the other keep their distance instead of landing on the same spot.
        x[i] += 2 * (min_distance_ - depth) * (-n);
        domain_.wrap(x[i]);
        // Relative to the wall: a piston moving into the fluid carries the particle with it.
        if (double towards = (v[i] - v[j]).dot(n); towards > 0) v[i] -= towards * n;
        moved = true;
      }
      if (moved) events.fetch_add(1, std::memory_order_relaxed);
    });
    total += events.load();
  }

 private:
  Domain<D> domain_;
  double min_distance_;
  double lateral2_;  // (0.75 d)^2: the wall particles whose patch the fluid particle stands in front of
};

}  // namespace ryushi
