#include <doctest/doctest.h>

#include <algorithm>
#include <random>
#include <set>

#include "ecs/system.hpp"
#include "systems/neighbour/neighbour_search.hpp"

using namespace ryushi;

namespace {

template <int D>
std::vector<std::set<std::uint32_t>> brute_force(const Domain<D>& dom, double r,
                                                 const std::vector<Vec<D>>& x) {
  std::vector<std::set<std::uint32_t>> out(x.size());
  for (std::size_t i = 0; i < x.size(); ++i)
    for (std::size_t j = 0; j < x.size(); ++j)
      if (i != j && dom.displacement(x[i], x[j]).squaredNorm() <= r * r)
        out[i].insert(static_cast<std::uint32_t>(j));
  return out;
}

template <int D>
void check_against_brute_force(const Domain<D>& dom, double r, const std::vector<Vec<D>>& x) {
  CellGrid<D> grid;
  NeighbourList list;
  build_neighbour_list<D>(dom, r, x, grid, list);
  auto expected = brute_force(dom, r, x);
  REQUIRE(list.size() == x.size());
  std::size_t pairs = 0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    auto got = list.of(i);
    std::set<std::uint32_t> s(got.begin(), got.end());
    CHECK(s.size() == got.size());  // no duplicates
    if (s != expected[i]) {
      FAIL_CHECK("particle " << i << ": " << s.size() << " neighbours, brute force " << expected[i].size());
    }
    pairs += got.size();
  }
  CHECK(pairs > 0);
}

template <int D>
Domain<D> unit_box(double size, bool periodic = false) {
  Domain<D> d;
  d.min.setZero();
  d.max.setConstant(size);
  d.periodic.fill(periodic);
  return d;
}

}  // namespace

TEST_CASE("neighbours: lattice with pairs exactly at the radius and particles on cell faces") {
  // Spacing 0.25 and radius 0.5 are exact in binary: many pairs sit exactly at r, and with a
  // cell edge of ~0.5 particles sit exactly on cell faces (x = 0.5, 1.0, ...).
  std::vector<Vec<2>> x;
  for (int i = 0; i <= 12; ++i)
    for (int j = 0; j <= 12; ++j) x.push_back(Vec<2>(0.25 * i, 0.25 * j));
  check_against_brute_force<2>(unit_box<2>(3.0), 0.5, x);
  std::vector<Vec<3>> y;
  for (int i = 0; i <= 6; ++i)
    for (int j = 0; j <= 6; ++j)
      for (int k = 0; k <= 6; ++k) y.push_back(Vec<3>(0.25 * i, 0.25 * j, 0.25 * k));
  check_against_brute_force<3>(unit_box<3>(1.5), 0.5, y);
}

TEST_CASE("neighbours: uniform random and clustered sets, 2D and 3D") {
  std::mt19937 rng(42);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::normal_distribution<double> n(0.0, 0.03);
  std::vector<Vec<2>> x2;
  for (int i = 0; i < 1500; ++i) x2.push_back(Vec<2>(u(rng), u(rng)));
  for (int c = 0; c < 5; ++c) {  // dense clusters: many particles per cell
    Vec<2> centre(u(rng), u(rng));
    for (int i = 0; i < 200; ++i) x2.push_back((centre + Vec<2>(n(rng), n(rng))).cwiseMax(0.0).cwiseMin(1.0));
  }
  check_against_brute_force<2>(unit_box<2>(1.0), 0.05, x2);
  std::vector<Vec<3>> x3;
  for (int i = 0; i < 2000; ++i) x3.push_back(Vec<3>(u(rng), u(rng), u(rng)));
  check_against_brute_force<3>(unit_box<3>(1.0), 0.1, x3);
}

TEST_CASE("neighbours: periodic axes find pairs across the box") {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<Vec<2>> x;
  for (int i = 0; i < 800; ++i) x.push_back(Vec<2>(u(rng), u(rng)));
  x.push_back(Vec<2>(0.0, 0.5));  // on the periodic seam
  x.push_back(Vec<2>(0.99, 0.5));
  auto dom = unit_box<2>(1.0, true);
  check_against_brute_force<2>(dom, 0.08, x);
  dom.periodic = {true, false};  // one periodic axis only
  check_against_brute_force<2>(dom, 0.08, x);
  std::vector<Vec<3>> y;
  for (int i = 0; i < 1500; ++i) y.push_back(Vec<3>(u(rng), u(rng), u(rng)));
  check_against_brute_force<3>(unit_box<3>(1.0, true), 0.12, y);
  // A periodic axis shorter than three cells would double-count: refused.
  CellGrid<2> grid;
  NeighbourList list;
  CHECK_THROWS_AS(build_neighbour_list<2>(unit_box<2>(1.0, true), 0.4, x, grid, list), std::invalid_argument);
}

TEST_CASE("neighbours: the cell order groups particles by cell") {
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<Vec<2>> x;
  for (int i = 0; i < 500; ++i) x.push_back(Vec<2>(u(rng), u(rng)));
  CellGrid<2> grid;
  NeighbourList list;
  build_neighbour_list<2>(unit_box<2>(1.0), 0.1, x, grid, list);
  auto order = grid.sorted();
  REQUIRE(order.size() == x.size());
  for (std::size_t k = 1; k < order.size(); ++k) CHECK(grid.cell_of(order[k - 1]) <= grid.cell_of(order[k]));
  std::vector<std::uint32_t> perm(order.begin(), order.end());
  std::sort(perm.begin(), perm.end());
  for (std::size_t k = 0; k < perm.size(); ++k) CHECK(perm[k] == k);  // a permutation
}

TEST_CASE("neighbours: skipping pairs of one kind leaves every other pair in place") {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<Vec<2>> x;
  std::vector<std::int32_t> kind;
  for (int i = 0; i < 1200; ++i) {
    x.push_back(Vec<2>(u(rng), u(rng)));
    kind.push_back(x.back()[1] < 0.3 ? kWall : kFluid);
  }
  auto dom = unit_box<2>(1.0);
  auto expected = brute_force<2>(dom, 0.06, x);
  CellGrid<2> grid;
  NeighbourList list;
  build_neighbour_list<2>(dom, 0.06, x, grid, list, kind, kWall);
  for (std::size_t i = 0; i < x.size(); ++i) {
    std::set<std::uint32_t> want;
    for (auto j : expected[i])
      if (!(kind[i] == kWall && kind[j] == kWall)) want.insert(j);
    auto got = list.of(i);
    CHECK(std::set<std::uint32_t>(got.begin(), got.end()) == want);
    CHECK(std::is_sorted(got.begin(), got.end()));
  }
}

// The Verlet list (NeighbourSearch with a skin) against a fresh build at every step of a random
// motion: the filtered list must be the very list a rebuild gives (same pairs, same order), also
// right after a reordering and across steps where particles move up to half the skin; and it must
// actually be reused (fewer builds than steps), or the skin would buy nothing.
TEST_CASE("neighbours: a Verlet list with a skin gives the rebuilt list at every step") {
  for (bool periodic : {false, true}) {
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> u(0.0, 1.0), s(-1.0, 1.0);
    const double radius = 0.06, skin = 0.02, dt = 1e-3;
    Domain<2> dom;
    dom.periodic = {periodic, false};
    World<2> w;
    w.append(1500, kFluid);
    w.append(100, kWall);
    auto& x = w.ensure(components::position);
    auto& v = w.ensure(components::velocity);
    for (std::size_t i = 0; i < w.size(); ++i) {
      x[i] = {u(rng), u(rng)};
      v[i] = {s(rng), s(rng)};  // |v| dt <= 1.4e-3: several steps per rebuild
    }
    Resources res;
    res.ensure(domain_resource<2>) = dom;
    res.ensure(resources::dt) = dt;
    NeighbourSearch<2> search(radius, kWall, skin);
    search.initialise(w, res);
    auto access = search.access();
    std::size_t steps = 60;
    for (std::size_t step = 0; step < steps; ++step) {
      if (step == 30) {  // a reordering between steps: indices change, the list must follow
        std::vector<std::uint32_t> order(w.size());
        for (std::size_t k = 0; k < order.size(); ++k) order[k] = std::uint32_t(order.size() - 1 - k);
        w.permute(order);
      }
      SystemContext<2> ctx(w, res, access, "test");
      search.run(ctx);
      CellGrid<2> grid;
      NeighbourList fresh;
      build_neighbour_list<2>(dom, radius, w.column(components::position), grid, fresh,
                              w.column(components::kind), kWall);
      const auto& list = res.get(neighbours_resource);
      REQUIRE(list.size() == fresh.size());
      bool same_rows = true;  // the Verlet list is strided (NeighbourList::ends): row by row
      for (std::size_t i = 0; i < fresh.size(); ++i) {
        auto a = list.of(i), b = fresh.of(i);
        same_rows = same_rows && std::equal(a.begin(), a.end(), b.begin(), b.end());
      }
      CHECK(same_rows);
      // Move; positions wrap on the periodic axis (the minimum image keeps that a small move).
      auto& xs = w.column(components::position);
      const auto& vs = w.column(components::velocity);
      const auto& kind = w.column(components::kind);
      for (std::size_t i = 0; i < w.size(); ++i) {
        if (kind[i] != kFluid) continue;
        xs[i] += dt * vs[i];
        if (periodic) xs[i][0] -= std::floor(xs[i][0]);
        xs[i][1] = std::clamp(xs[i][1], 0.0, 1.0);
      }
    }
    const auto builds = res.get(neighbours_resource).builds;
    INFO("periodic " << periodic << ": " << builds << " builds in " << steps << " steps");
    CHECK(builds >= 3);          // the motion of 60 steps (up to 0.085) exceeds the skin: rebuilt
    CHECK(builds <= steps / 3);  // and reused in between
  }
}

TEST_CASE("neighbours: the compact candidates give back every index, large jumps and descending rows too") {
  // Rows with steps of every size: within 16 bits, at its edges, beyond it (escapes), backwards
  // (periodic images come out of order), the largest indices, and an empty row.
  NeighbourList list;
  list.offsets = {0};
  std::mt19937 rng(3);
  const std::uint32_t steps[] = {1, 2, 32767, 32768, 32769, 65536, 1u << 20, 4000000000u};
  const std::size_t N = 400;
  for (std::size_t i = 0; i < N; ++i) {
    std::uint32_t j = static_cast<std::uint32_t>(i);
    const std::size_t n = i == 7 ? 0 : rng() % 40;
    for (std::size_t k = 0; k < n; ++k) {
      const std::uint32_t step = steps[rng() % 8];
      j = rng() % 3 == 0 ? j - step : j + step;  // modulo 2^32, as the decoding is
      list.indices.push_back(j);
    }
    if (i != 7) {  // the two extremes end every row but the empty one
      list.indices.push_back(0xffffffffu);
      list.indices.push_back(0);
    }
    list.offsets.push_back(static_cast<std::uint32_t>(list.indices.size()));
  }
  REQUIRE(list.of(7).size() == 0);
  CandidateList compact;
  compact.assign(N, [&](std::size_t i) { return list.of(i); });
  REQUIRE(compact.size() == N);
  CHECK(compact.count == list.indices.size());
  bool same = true;
  for (std::size_t i = 0; i < N; ++i) {
    std::vector<std::uint32_t> row;
    compact.for_each(i, [&](std::uint32_t j) { row.push_back(j); });
    auto expected = list.of(i);
    same = same && std::equal(row.begin(), row.end(), expected.begin(), expected.end());
  }
  CHECK(same);
  std::size_t empty_row = 0;
  compact.for_each(7, [&](std::uint32_t) { ++empty_row; });
  CHECK(empty_row == 0);
  // Consecutive indices (a cell's run) take two bytes each.
  NeighbourList runs;
  runs.offsets = {0, 1000};
  for (std::uint32_t j = 1; j <= 1000; ++j) runs.indices.push_back(j);
  compact.assign(1, [&](std::size_t i) { return runs.of(i); });
  CHECK(compact.slots.size() == 1000);
}
