#pragma once
// Ghost particles of the shallow-water walls (Saigo & Koshizuka section 2(5)): each fluid
// particle within the search radius of a wall has one ghost mirrored across it (and one across
// both walls at a corner). A ghost has its particle's volume, area, depth and surface elevation;
// its velocity has the normal component reversed, the tangential one kept (slip) or reversed
// (no-slip). Ghosts are not particles of the world: this resource holds the particles followed
// by their ghosts (index >= fluid), and the neighbour list is built over that set, so the other
// systems see a ghost as one more neighbour j and read its state through parent[j - fluid]
// (halo particles of a domain decomposition can arrive the same way).
#include <tbb/parallel_for.h>
#include <tbb/parallel_reduce.h>

#include <cmath>
#include <initializer_list>
#include <span>
#include <vector>

#include "ecs/io.hpp"
#include "systems/swe/swe_parameters.hpp"

namespace ryushi {

template <int D>
struct GhostImages {
  std::size_t fluid = 0;              // particles [0, fluid) are the world's, in its order
  std::vector<Vec<D>> position;       // particles then ghosts
  std::vector<std::uint32_t> parent;  // ghost g (index fluid + g): its particle
  std::vector<Vec<D>> velocity_sign;  // ghost velocity = velocity_sign .* parent velocity
  std::vector<Vec<D>> reflection;     // ghost position = reflection .* parent position + shift
  std::vector<Vec<D>> shift;

  std::size_t size() const { return position.size(); }
  // The world index whose state particle-or-ghost j carries.
  std::uint32_t owner(std::uint32_t j) const { return j < fluid ? j : parent[j - fluid]; }
  // Where j is when the particles are at x (a ghost follows its particle's mirror image).
  Vec<D> where(std::uint32_t j, std::span<const Vec<D>> x) const {
    if (j < fluid) return x[j];
    const std::size_t g = j - fluid;
    return reflection[g].cwiseProduct(x[parent[g]]) + shift[g];
  }
};

template <int D>
inline constexpr Resource<GhostImages<D>> ghost_images_resource{"swe_ghosts"};

// r_e = alpha_e sqrt(max_i A_i) (eq. 9), one radius for every pair so that the interaction is
// symmetric, recomputed each step from the areas of the last depth sum.
template <int D>
class SweInfluenceRadius final : public System<D> {
 public:
  explicit SweInfluenceRadius(double alpha_e) : alpha_e_(alpha_e) {}
  std::string name() const override { return "swe_influence_radius"; }
  static constexpr auto io = Io{reads(components::area), writes(swe_influence_radius_resource)};
  Access access() const override { return io.access(); }
  void initialise(World<D>&, Resources& res) override { res.ensure(swe_influence_radius_resource); }
  void run(SystemContext<D>& ctx) override {
    auto [A, radius] = io.fetch(ctx);
    double amax = tbb::parallel_reduce(
        tbb::blocked_range<std::size_t>(0, A.size(), 4096), 0.0,
        [&](auto r, double m) {
          for (std::size_t i = r.begin(); i != r.end(); ++i) m = std::max(m, A[i]);
          return m;
        },
        [](double a, double b) { return std::max(a, b); });
    radius = alpha_e_ * std::sqrt(amax);
  }

 private:
  double alpha_e_;
};

// The ghost images of the particles at x within `reach` of the walls (one per wall, and one
// across both walls of a corner).
template <int D>
void build_ghost_images(std::span<const Vec<D>> x, const std::vector<MirrorWall>& walls, bool slip,
                        double reach, GhostImages<D>& g) {
  static_assert(D == 2, "shallow-water walls are lines in the plan view");
  g.fluid = x.size();
  g.position.assign(x.begin(), x.end());
  g.parent.clear();
  g.velocity_sign.clear();
  g.reflection.clear();
  g.shift.clear();
  // The image across the walls ws: x_a -> 2 at - x_a on each wall's axis.
  auto add = [&](std::uint32_t i, std::initializer_list<const MirrorWall*> ws) {
    Vec<D> reflection = Vec<D>::Ones(), shift = Vec<D>::Zero();
    for (auto* w : ws) reflection[w->axis] = -1, shift[w->axis] = 2 * w->at;
    g.position.push_back(reflection.cwiseProduct(x[i]) + shift);
    g.parent.push_back(i);
    g.reflection.push_back(reflection);
    g.shift.push_back(shift);
    // Slip: the normal components reversed; no-slip: the whole velocity.
    g.velocity_sign.push_back(slip ? reflection : Vec<D>(-Vec<D>::Ones()));
  };
  // Serial: a few per cent of the particles touch a wall, and the order stays reproducible.
  std::vector<const MirrorWall*> near;
  for (std::uint32_t i = 0; i < x.size(); ++i) {
    near.clear();
    for (auto& w : walls) {
      const double along = x[i][1 - w.axis];
      const double dist = w.inward * (x[i][w.axis] - w.at);
      if (dist >= 0 && dist < reach && along >= w.lo - reach && along <= w.hi + reach) near.push_back(&w);
    }
    for (std::size_t a = 0; a < near.size(); ++a) {
      add(i, {near[a]});
      for (std::size_t b = a + 1; b < near.size(); ++b)
        if (near[b]->axis != near[a]->axis) add(i, {near[a], near[b]});  // a corner
    }
  }
}

template <int D>
class SweGhostWalls final : public System<D> {
 public:
  // support_factor: the kernel's support in units of r_e (spiky: 2).
  SweGhostWalls(std::vector<MirrorWall> walls, bool slip, double support_factor)
      : walls_(std::move(walls)), slip_(slip), support_factor_(support_factor) {}
  std::string name() const override { return "swe_ghost_walls"; }
  static constexpr auto io =
      Io{reads(components::position, swe_influence_radius_resource), writes(ghost_images_resource<D>)};
  Access access() const override { return io.access(); }
  void initialise(World<D>&, Resources& res) override { res.ensure(ghost_images_resource<D>); }
  void run(SystemContext<D>& ctx) override {
    auto [x, radius, ghosts] = io.fetch(ctx);
    build_ghost_images<D>(x, walls_, slip_, support_factor_ * radius, ghosts);
  }

 private:
  std::vector<MirrorWall> walls_;
  bool slip_;
  double support_factor_;
};

}  // namespace ryushi
