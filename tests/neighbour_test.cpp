#include <doctest/doctest.h>

#include <algorithm>
#include <random>
#include <set>

#include "systems/neighbour/neighbour_search.hpp"

using namespace ryushi;

namespace {

template <int D>
std::vector<std::set<std::uint32_t>> brute_force(const Domain<D>& dom, double r, const std::vector<Vec<D>>& x) {
  std::vector<std::set<std::uint32_t>> out(x.size());
  for (std::size_t i = 0; i < x.size(); ++i)
    for (std::size_t j = 0; j < x.size(); ++j)
      if (i != j && dom.displacement(x[i], x[j]).squaredNorm() <= r * r) out[i].insert(static_cast<std::uint32_t>(j));
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
    for (int i = 0; i < 200; ++i)
      x2.push_back((centre + Vec<2>(n(rng), n(rng))).cwiseMax(0.0).cwiseMin(1.0));
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
