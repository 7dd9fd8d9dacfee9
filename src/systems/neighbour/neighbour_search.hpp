#pragma once
// Neighbour search system: cell grid + counting sort, then a CSR list of all pairs within the
// search radius. Reads positions; writes the `neighbours` and `cell_grid` resources.
#include <span>
#include <utility>
#include <vector>

#include "ecs/io.hpp"
#include "systems/neighbour/candidate_list.hpp"
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

// The same pairs (radius + a Verlet skin) kept as compact candidates (candidate_list.hpp),
// encoded straight from the build's own buffers, without the full list in between.
template <int D>
void build_candidate_list(const Domain<D>& domain, double radius, std::span<const Vec<D>> x,
                          CellGrid<D>& grid, CandidateList& out, std::span<const std::int32_t> kind = {},
                          std::int32_t skip_kind = -1);

// `out` = the pairs of `candidates` (a list built with a larger radius) within `radius`, in the
// same order: row for row the list that build_neighbour_list gives for `radius`, at a fraction
// of its cost. `out` has NeighbourList::ends and the candidates' slots (filter_rows.hpp).
template <int D>
void filter_neighbour_list(const Domain<D>& domain, double radius, std::span<const Vec<D>> x,
                           const NeighbourList& candidates, NeighbourList& out);

// The same from the Verlet list's compact candidates, into storage of about the kept pairs'
// size (not the candidates'): rows packed, in blocks placed in the order they finish
// (NeighbourList::ends). kept_fraction: the caller's record of the kept share, which sizes the
// storage (10% spare; a call that runs out of room goes again with more); 0 at first.
template <int D>
void filter_candidates(const Domain<D>& domain, double radius, std::span<const Vec<D>> x,
                       const CandidateList& candidates, NeighbourList& out, double& kept_fraction);

// Largest |x_i - ref_i| (minimum image on periodic axes) and largest |v_i| (the Verlet list's
// rebuild test); an empty v gives speed 0.
template <int D>
std::pair<double, double> max_displacement_and_speed(const Domain<D>& domain, std::span<const Vec<D>> x,
                                                     std::span<const Vec<D>> ref, std::span<const Vec<D>> v);

template <int D>
class NeighbourSearch final : public System<D> {
 public:
  // skip_kind: leave pairs of two particles of this kind out of the list (WCSPH never uses
  // wall-wall pairs, MPS never dummy-dummy pairs); -1 keeps every pair.
  // skin > 0 keeps a Verlet list of candidates: pairs within radius + skin, kept over the
  // following steps until a pair left out might have come within `radius`. Two particles farther
  // apart than radius + skin at the build each move at most delta, so they stay beyond `radius`
  // while delta <= skin / 2. The test before each step bounds delta by the largest displacement
  // since the build plus v_max dt (the predictor moves by dt/2 v: a factor two to spare). Any
  // structural change (reordering, removal, insertion) rebuilds. Each step the candidates are
  // filtered into the exact list within `radius`: the systems see the same list, in the same
  // order, as without a skin (measured: a skin seen by the pair loops costs them more than the
  // filter, since every candidate beyond the support is still gathered).
  // moves_within_step: the list is used again after the particles move within the step (WCSPH's
  // midpoint predictor), so the test keeps v_max dt in hand; false where the search radius itself
  // holds the step's motion (MPS, ISPH) and the list only has to be exact at the start of the step.
  explicit NeighbourSearch(double radius, std::int32_t skip_kind = -1, double skin = 0,
                           bool moves_within_step = true)
      : radius_(radius), skip_kind_(skip_kind), skin_(skin), moves_within_step_(moves_within_step) {}
  std::string name() const override { return "neighbour_search"; }
  double cell_size() const { return radius_ + skin_; }  // of the grid it builds
  // The grid is written at every build (with a skin: not every step). The velocity and dt are
  // for the Verlet list's validity test within a step that moves the particles.
  auto io() const {
    return Io{reads(components::position, domain_resource<D>),
              writes(neighbours_resource, cell_grid_resource<D>),
              optional(skip_kind_ >= 0, reads(components::kind)),
              optional(skin_ > 0 && moves_within_step_, reads(components::velocity, resources::dt))};
  }
  Access access() const override { return io().access(); }
  void initialise(World<D>&, Resources& res) override {
    res.ensure(neighbours_resource);
    res.ensure(cell_grid_resource<D>);
  }
  void run(SystemContext<D>& ctx) override {
    // kind: empty when no kind is skipped; v, dt: empty and null without the in-step test.
    auto [x, domain, out, grid, kind, v, dt] = io().fetch(ctx);
    if (skin_ <= 0) {
      build_neighbour_list<D>(domain, radius_, x, grid, out, kind, skip_kind_);
      return;
    }
    bool valid = builds_ > 0 && ctx.structure_version() == version_ && x.size() == reference_.size();
    if (valid) {
      auto [moved, vmax] = max_displacement_and_speed<D>(domain, x, reference_, v);
      valid = moved + (moves_within_step_ ? vmax * *dt : 0.0) <= 0.5 * skin_;
    }
    if (!valid) {
      build_candidates(domain, x, grid, kind);
      reference_.assign(x.begin(), x.end());
      version_ = ctx.structure_version();
    }
    filter_candidates<D>(domain, radius_, x, candidates_, out, kept_fraction_);
    out.builds = builds_;
    out.candidate_bytes = candidates_.bytes() + reference_.size() * sizeof(Vec<D>);
  }

  // A Verlet list lives on from its last build, and the driver reorders particles with that
  // build's cell grid: a resumed run must find both as the stopped run left them. The state is
  // whether the list is still valid for the world as it stands, and the positions of the last
  // build, from which the same candidates and grid are rebuilt. (Without a skin the grid is
  // rebuilt every step; the driver keeps its order itself.)
  std::vector<double> checkpoint_state(const World<D>& world, const Resources&) const override {
    std::vector<double> state;
    if (skin_ <= 0 || builds_ == 0) return state;
    state.push_back(world.structure_version() == version_ ? 1.0 : 0.0);
    for (auto& p : reference_) state.insert(state.end(), p.data(), p.data() + D);
    return state;
  }
  void restore_state(const World<D>& world, Resources& res, std::span<const double> state) override {
    if (skin_ <= 0 || state.empty()) return;
    // A structural change after the build (particles removed): the stopped run rebuilds at its
    // next step, and its grid no longer matches the particles, so nothing to restore.
    if (state[0] != 1.0) return;
    reference_.resize((state.size() - 1) / D);
    for (std::size_t i = 0; i < reference_.size(); ++i)
      for (int a = 0; a < D; ++a) reference_[i][a] = state[1 + i * D + a];
    std::span<const std::int32_t> kind;
    if (skip_kind_ >= 0) kind = world.column(components::kind);
    build_candidates(res.get(domain_resource<D>), std::span<const Vec<D>>(reference_),
                     res.ensure(cell_grid_resource<D>), kind);
    version_ = world.structure_version();
  }

 private:
  void build_candidates(const Domain<D>& domain, std::span<const Vec<D>> x, CellGrid<D>& grid,
                        std::span<const std::int32_t> kind) {
    build_candidate_list<D>(domain, radius_ + skin_, x, grid, candidates_, kind, skip_kind_);
    ++builds_;
  }

  double radius_;
  std::int32_t skip_kind_;
  double skin_;
  bool moves_within_step_;
  CandidateList candidates_;
  std::size_t builds_ = 0;
  double kept_fraction_ = 0;  // of the candidates, at the last filter (sizes the list's storage)
  std::uint64_t version_ = 0;
  std::vector<Vec<D>> reference_;
};

}  // namespace ryushi
