// Dynamic particle splitting (Saigo & Koshizuka section 2(3), appendix A): one split conserves
// volume and momentum, the split direction follows the neighbourhood's moment matrix and turns
// with it, and a cap on the particle count holds.
#include <doctest/doctest.h>

#include <cmath>
#include <numbers>

#include "ecs/system.hpp"
#include "systems/neighbour/neighbour_search.hpp"
#include "systems/splitting/particle_splitting.hpp"

using namespace ryushi;

namespace {

// Particles on a lattice with steps (ax, ay), rotated by `angle`, slightly jittered (so that no
// sum is symmetric by accident), with velocities and depths that vary in space; the particle
// nearest the origin has an area past the threshold, every other one stays below it.
struct Patch {
  World<2> world;
  Resources res;
  std::size_t centre = 0;

  Patch(double ax, double ay, double angle, std::size_t max_particles = 0, bool along_gap = true,
        double r_e = 0.16)
      : splitter(params(max_particles, along_gap)) {
    const Eigen::Rotation2Dd R(angle);
    std::vector<Vec<2>> pos;
    for (int i = -4; i <= 4; ++i)
      for (int j = -4; j <= 4; ++j) {
        Vec<2> p(i * ax, j * ay);
        if (i || j) p += 0.01 * Vec<2>(std::sin(3.1 * i + 1.7 * j), std::cos(2.3 * i - 0.9 * j));
        pos.push_back(R * p);
      }
    world.append(pos.size(), kFluid);
    auto& x = world.ensure(components::position);
    auto& v = world.ensure(components::velocity);
    auto& A = world.ensure(components::area);
    auto& h = world.ensure(components::depth);
    auto& V = world.ensure(components::water_volume);
    auto& m = world.ensure(components::mass);
    for (std::size_t k = 0; k < pos.size(); ++k) {
      x[k] = pos[k];
      v[k] = Vec<2>(1.0 + 0.3 * pos[k][0] - 0.2 * pos[k][1], -0.5 + 0.1 * pos[k][0] * pos[k][1]);
      h[k] = 0.2 + 0.05 * pos[k][0];
      A[k] = 0.01;
      V[k] = A[k] * h[k];
      m[k] = 1000 * V[k];
      if (pos[k].norm() < 1e-12) centre = k;
    }
    A[centre] = 0.02;  // 2 A0 > 1.5 A0
    splitter.initialise(world, res);
    res.ensure(swe_influence_radius_resource) = r_e;
    auto& g = res.ensure(ghost_images_resource<2>);
    build_ghost_images<2>(x, {}, true, 0.0, g);
    CellGrid<2> grid;
    Domain<2> domain;
    domain.min = Vec<2>(-10, -10), domain.max = Vec<2>(10, 10);
    build_neighbour_list<2>(domain, 2 * res.get(swe_influence_radius_resource),
                            std::span<const Vec<2>>(g.position), grid, res.ensure(neighbours_resource));
  }
  static SplitParameters params(std::size_t max_particles, bool along_gap) {
    SplitParameters p;
    p.area0 = 0.01;
    p.max_particles = max_particles;
    p.along_gap = along_gap;
    return p;
  }
  void split() {
    Access access = splitter.access();
    SystemContext<2> ctx(world, res, access, splitter.name());
    splitter.run(ctx);
    res.get(structural_changes_resource<2>).apply(world);
  }
  double volume() const {
    double s = 0;
    for (double v : world.column(components::water_volume)) s += v;
    return s;
  }
  Vec<2> momentum() const {  // sum rho0 V u: mass is rho0 V
    Vec<2> s = Vec<2>::Zero();
    auto& V = world.column(components::water_volume);
    auto& v = world.column(components::velocity);
    for (std::size_t i = 0; i < V.size(); ++i) s += V[i] * v[i];
    return s;
  }
  // The two children (parent_id >= 0): their separation x+ - x-.
  Vec<2> children_offset() const {
    auto& parent = world.column(components::parent_id);
    auto& x = world.column(components::position);
    std::vector<Vec<2>> kids;
    for (std::size_t i = 0; i < parent.size(); ++i)
      if (parent[i] >= 0) kids.push_back(x[i]);
    REQUIRE(kids.size() == 2);
    return kids[0] - kids[1];
  }

  ParticleSplitting<2> splitter;
};

}  // namespace

TEST_CASE("splitting: one split conserves volume and momentum to 1e-12 and records the parent") {
  Patch p(0.1, 0.1, 0.3);
  const double V0 = p.volume();
  const Vec<2> P0 = p.momentum();
  const std::size_t n0 = p.world.size();
  const auto parent_id = p.world.column(components::id)[p.centre];
  const double l = std::sqrt(p.world.column(components::area)[p.centre]);
  p.split();
  CHECK(p.world.size() == n0 + 1);
  CHECK(std::abs(p.volume() - V0) <= 1e-12 * V0);
  CHECK((p.momentum() - P0).norm() <= 1e-12 * P0.norm());
  // Both children name the parent, which is gone; they sit alpha_s l apart (eq. 10).
  auto& parent = p.world.column(components::parent_id);
  auto& id = p.world.column(components::id);
  int children = 0;
  for (std::size_t i = 0; i < parent.size(); ++i) {
    if (parent[i] == parent_id) ++children;
    CHECK(id[i] != parent_id);
  }
  CHECK(children == 2);
  CHECK(p.children_offset().norm() == doctest::Approx(0.7 * l).epsilon(1e-12));
  CHECK(p.res.get(splitting_statistics_resource).splits == 1);
}

TEST_CASE(
    "splitting: the direction follows the moment matrix's eigenvectors and turns with the neighbourhood") {
  // Rows along y (particles 0.1 m apart) 0.3 m apart along x, with a support (2 r_e = 0.4 m)
  // that reaches one row on each side: the kernel-weighted moment C_yy > C_xx, so gap splits
  // along x (across the gap between the rows) and spread (eq. 11 as printed) along y, the row.
  for (double angle : {0.0, std::numbers::pi / 6, 1.2}) {
    const Vec<2> sparse(std::cos(angle), std::sin(angle)), dense(-std::sin(angle), std::cos(angle));
    Patch gap(0.3, 0.1, angle, 0, true, 0.2);
    gap.split();
    Vec<2> t = gap.children_offset().normalized();
    CHECK(std::abs(t.dot(sparse)) > 0.995);
    Patch spread(0.3, 0.1, angle, 0, false, 0.2);
    spread.split();
    t = spread.children_offset().normalized();
    CHECK(std::abs(t.dot(dense)) > 0.995);
  }
}

TEST_CASE("splitting: the particle cap stops splitting and the state stays as it was") {
  Patch p(0.1, 0.1, 0.0, 81);  // 81 particles already: no room for a child
  const double V0 = p.volume();
  p.split();
  CHECK(p.world.size() == 81);
  CHECK(p.volume() == V0);
  CHECK(p.res.get(splitting_statistics_resource).capped);
  CHECK(p.res.get(splitting_statistics_resource).splits == 0);
}
