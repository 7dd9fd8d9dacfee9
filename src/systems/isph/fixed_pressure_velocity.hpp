#pragma once
// The velocity of an Eulerian inlet or outlet ([[fixed_pressure]] boxes): each particle there
// takes the velocity of the nearest particle whose pressure is solved for (zero gradient along
// the flow, the usual outflow condition). Evolved by the momentum equation instead, the buffer's
// outer column, whose support is cut in half, went unstable within 0.01 s (u up to 0.1 m/s in a
// 0.005 m/s flow) with the corrected viscous Laplacian, by 0.1 s with the standard one: the
// one-sided operators there are only first-order consistent.
// The source of each buffer particle is found once (Eulerian particles do not move) and kept as
// an id in the column `velocity_source` (-1 elsewhere), so a reordering of the particles is
// harmless.
#include <limits>
#include <unordered_map>
#include <utility>
#include <vector>

#include "ecs/io.hpp"
#include "systems/isph/isph_parameters.hpp"

namespace ryushi {

namespace components {
inline constexpr Component<Flags> velocity_source{"velocity_source"};
}

template <int D>
class FixedPressureVelocity final : public System<D> {
 public:
  explicit FixedPressureVelocity(const Domain<D>& domain) : domain_(domain) {}
  std::string name() const override { return "fixed_pressure_velocity"; }
  static constexpr auto io =
      Io{reads(components::id, components::velocity_source), writes(components::velocity)};
  Access access() const override { return io.access(); }
  void initialise(World<D>& world, Resources&) override {
    auto& source = world.ensure(components::velocity_source);
    auto& x = world.column(components::position);
    auto& kind = world.column(components::kind);
    auto& id = world.column(components::id);
    auto& fixed = world.column(components::fixed_pressure);
    for (std::size_t i = 0; i < world.size(); ++i) {
      source[i] = -1;
      if (kind[i] != kFluid || !std::isfinite(fixed[i])) continue;
      double nearest = std::numeric_limits<double>::infinity();
      for (std::size_t j = 0; j < world.size(); ++j) {
        if (kind[j] != kFluid || std::isfinite(fixed[j])) continue;
        const double r = domain_.offset(x[i], x[j]).squaredNorm();
        if (r < nearest) nearest = r, source[i] = id[j];
      }
    }
  }
  void run(SystemContext<D>& ctx) override {
    auto [id, source, v] = io.fetch(ctx);
    // The pairs (buffer particle, source) as indices, rebuilt only when the particles were
    // reordered since the last step (Eulerian particles stay; ISPH does not reorder them).
    bool valid = !pairs_.empty();
    for (std::size_t k = 0; valid && k < pairs_.size(); ++k) {
      auto [i, from] = pairs_[k];
      valid = i < id.size() && from < id.size() && source[i] >= 0 && id[from] == source[i];
    }
    if (!valid) {
      std::unordered_map<std::int32_t, std::size_t> index_of_id;
      for (std::size_t i = 0; i < id.size(); ++i) index_of_id[id[i]] = i;
      pairs_.clear();
      for (std::size_t i = 0; i < id.size(); ++i)
        if (source[i] >= 0) pairs_.emplace_back(i, index_of_id.at(source[i]));
    }
    for (auto& [i, from] : pairs_) v[i] = v[from];
  }

 private:
  Domain<D> domain_;
  std::vector<std::pair<std::size_t, std::size_t>> pairs_;
};

}  // namespace ryushi
