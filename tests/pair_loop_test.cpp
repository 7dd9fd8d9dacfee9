// The pair loop (src/systems/loops/pair_loop.hpp) on a term that counts each row's neighbours
// and sums its kernel gradients, against a direct sum over every pair: both strategies (gather,
// each pair once), a periodic axis, wall rows that are read and never written, and ghost rows
// (the rows from `owned` on): an owned row gets the same sums whether its neighbours are owned or
// ghosts, and no strategy writes a ghost row. The counts are integers and must match exactly;
// the gradient sums differ by summation order only (~30 terms of either sign, a few ulp each),
// bounded by 1e-12 of the largest single gradient.
#include "systems/loops/pair_loop.hpp"

#include <doctest/doctest.h>

#include <cmath>
#include <limits>
#include <random>

#include "ecs/component.hpp"
#include "systems/neighbour/neighbour_search.hpp"

using namespace ryushi;

namespace {

template <int D>
struct CountAndGradient {
  struct Sum {
    double count = 0;
    Vec<D> grad = Vec<D>::Zero();
    Sum& operator+=(const Sum& o) {
      count += o.count;
      grad += o.grad;
      return *this;
    }
  };
  std::span<double> count;
  std::span<Vec<D>> grad;

  Sum zero() const { return {}; }
  void operator()(const PairGeometry<D>& g, PairSides s, Sum& to_i, Sum& to_j) const {
    if (s.i) {
      to_i.count += 1;
      to_i.grad += g.gradW;
    }
    if (s.j) {
      to_j.count += 1;
      to_j.grad -= g.gradW;  // grad_j W_ji = -grad_i W_ij
    }
  }
  void store(std::size_t i, const Sum& sum) const {
    count[i] = sum.count;
    grad[i] = sum.grad;
  }
};

template <int D>
struct Cloud {
  Domain<D> domain;
  Kernel<D> kernel{KernelType::WendlandC2, 0.015};
  std::vector<Vec<D>> x;
  std::vector<std::int32_t> kind;
  NeighbourList nl;
};

// A jittered lattice with a periodic first axis, every fifth row a wall, in the order the
// neighbour search's cell sort would leave it (the lattice's own order is close enough).
template <int D>
Cloud<D> make_cloud() {
  Cloud<D> c;
  const int n = D == 2 ? 24 : 10;
  const double d = 0.01;
  c.domain.min = Vec<D>::Zero();
  c.domain.max = Vec<D>::Constant(n * d);
  c.domain.periodic[0] = true;
  std::mt19937 rng(11 + D);
  std::uniform_real_distribution<double> jitter(-0.2 * d, 0.2 * d);
  const int total = static_cast<int>(std::pow(n, D));
  for (int k = 0; k < total; ++k) {
    Vec<D> x;
    int rest = k;
    for (int a = D - 1; a >= 0; --a) {
      x[a] = (rest % n + 0.5) * d + jitter(rng);
      rest /= n;
    }
    c.domain.wrap(x);
    c.x.push_back(x);
    c.kind.push_back(k % 5 == 0 ? kWall : kFluid);
  }
  CellGrid<D> grid;
  build_neighbour_list<D>(c.domain, c.kernel.support(), std::span<const Vec<D>>(c.x), grid, c.nl);
  return c;
}

template <int D>
void check_loop(PairsOnce strategy, std::size_t ghosts) {
  auto c = make_cloud<D>();
  const std::size_t N = c.x.size(), owned = N - ghosts;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  std::vector<double> count(N, nan);
  std::vector<Vec<D>> grad(N, Vec<D>::Constant(nan));
  PairLoop<D> loop(c.kernel, c.domain);
  loop.set_strategy(strategy);
  loop.run({c.x, {}, c.kind, kFluid, owned}, c.nl, CountAndGradient<D>{count, grad});

  const double support = c.kernel.support();
  double largest = 0, err = 0;
  std::size_t wrong_counts = 0, written_elsewhere = 0, checked = 0;
  for (std::size_t i = 0; i < N; ++i) {
    if (i >= owned || c.kind[i] != kFluid) {
      if (!std::isnan(count[i]) || !std::isnan(grad[i][0])) ++written_elsewhere;
      continue;
    }
    double n_ref = 0;
    Vec<D> g_ref = Vec<D>::Zero();
    for (std::size_t j = 0; j < N; ++j) {
      const Vec<D> xij = c.domain.displacement(c.x[i], c.x[j]);
      const double r = xij.norm();
      if (j == i || r >= support) continue;
      n_ref += 1;
      const Vec<D> gw = xij * c.kernel.grad_factor(r);
      g_ref += gw;
      largest = std::max(largest, gw.norm());
    }
    ++checked;
    if (count[i] != n_ref) ++wrong_counts;
    err = std::max(err, (grad[i] - g_ref).norm());
  }
  INFO("D = " << D << ", strategy " << int(strategy) << ", ghosts " << ghosts << ": " << checked
              << " rows checked, largest |grad W| " << largest << ", gradient error " << err);
  REQUIRE(checked > 100);
  REQUIRE(largest > 0);
  CHECK(wrong_counts == 0);
  CHECK(written_elsewhere == 0);
  CHECK(err <= 1e-12 * largest);
}

}  // namespace

TEST_CASE("pair loop: gather and pairs once give every owned row its full sums and never write a ghost row") {
  for (PairsOnce strategy : {PairsOnce::Never, PairsOnce::Always})
    for (std::size_t ghosts : {std::size_t{0}, std::size_t{150}}) {
      check_loop<2>(strategy, ghosts);
      check_loop<3>(strategy, ghosts);
    }
}
