// Neighbour-list build time in ns per particle, 2D and 3D, 1e5 and 1e6 particles, 1 and 2
// threads. Run: build/bench/ryushi_bench_neighbours (see docs/benchmarks.md).
#include <benchmark/benchmark.h>
#include <tbb/global_control.h>

#include <random>

#include "systems/neighbour/neighbour_search.hpp"

using namespace ryushi;

template <int D>
static void BM_NeighbourBuild(benchmark::State& state) {
  const std::size_t n = state.range(0);
  const int threads = static_cast<int>(state.range(1));
  tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads);
  // A jittered lattice with spacing d and support radius 2h = 3 d (h = 1.5 d, the default).
  const double d = 1.0;
  const long side = std::lround(std::pow(double(n), 1.0 / D));
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> jitter(-0.1 * d, 0.1 * d);
  std::vector<Vec<D>> x;
  Domain<D> domain;
  domain.min.setConstant(-1.0);
  domain.max.setConstant(side * d + 1.0);
  std::array<long, D> k{};
  for (std::size_t i = 0; i < std::pow(side, D); ++i) {
    long rest = i;
    Vec<D> p;
    for (int a = 0; a < D; ++a) {
      k[a] = rest % side;
      rest /= side;
      p[a] = (k[a] + 0.5) * d + jitter(rng);
    }
    x.push_back(p);
  }
  CellGrid<D> grid;
  NeighbourList list;
  build_neighbour_list<D>(domain, 3.0 * d, x, grid, list);  // warm-up allocates
  // Cell-ordered particles, as the simulation keeps them.
  std::vector<Vec<D>> sorted;
  for (auto i : grid.sorted()) sorted.push_back(x[i]);
  for (auto _ : state) {
    build_neighbour_list<D>(domain, 3.0 * d, sorted, grid, list);
    benchmark::DoNotOptimize(list.indices.data());
  }
  state.counters["ns_per_particle"] =
      benchmark::Counter(double(sorted.size()) * state.iterations() * 1e-9, benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
  state.counters["neighbours"] = double(list.indices.size()) / sorted.size();
  state.counters["bytes_per_particle"] = double(list.bytes()) / sorted.size();
}

BENCHMARK(BM_NeighbourBuild<2>)->ArgsProduct({{100000, 1000000}, {1, 2}})->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_NeighbourBuild<3>)->ArgsProduct({{100000, 1000000}, {1, 2}})->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_MAIN();
