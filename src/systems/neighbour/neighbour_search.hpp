#pragma once
// Neighbour search system: cell grid + counting sort, then a CSR list of all pairs within the
// search radius. Reads positions; writes the `neighbours` and `cell_grid` resources.
#include <span>

#include "ecs/system.hpp"
#include "systems/neighbour/cell_grid.hpp"
#include "systems/neighbour/domain.hpp"
#include "systems/neighbour/neighbour_list.hpp"

namespace ryushi {

template <int D>
inline constexpr Resource<CellGrid<D>> cell_grid_resource{"cell_grid"};

// Builds `out` for positions x (usable without a world: tests, tools and benchmarks). With a
// `kind` span, pairs in which both particles are of `skip_kind` are left out (walls need only
// their fluid neighbours). Each list is sorted by index.
template <int D>
void build_neighbour_list(const Domain<D>& domain, double radius, std::span<const Vec<D>> x,
                          CellGrid<D>& grid, NeighbourList& out, std::span<const std::int32_t> kind = {},
                          std::int32_t skip_kind = -1);

template <int D>
class NeighbourSearch final : public System<D> {
 public:
  // skip_kind: leave pairs of two particles of this kind out of the list (WCSPH never uses
  // wall-wall pairs, MPS never dummy-dummy pairs); -1 keeps every pair.
  explicit NeighbourSearch(double radius, std::int32_t skip_kind = -1) : radius_(radius), skip_kind_(skip_kind) {}
  std::string name() const override { return "neighbour_search"; }
  Access access() const override {
    return Access{}
        .read(components::position, components::kind, domain_resource<D>)
        .write(neighbours_resource, cell_grid_resource<D>);
  }
  void initialise(World<D>&, Resources& res) override {
    res.ensure(neighbours_resource);
    res.ensure(cell_grid_resource<D>);
  }
  void run(SystemContext<D>& ctx) override {
    std::span<const std::int32_t> kind;
    if (skip_kind_ >= 0) kind = ctx.read(components::kind);
    build_neighbour_list<D>(ctx.read(domain_resource<D>), radius_, ctx.read(components::position),
                            ctx.write(cell_grid_resource<D>), ctx.write(neighbours_resource), kind, skip_kind_);
  }

 private:
  double radius_;
  std::int32_t skip_kind_;
};

}  // namespace ryushi
