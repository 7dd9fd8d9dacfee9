// STREAM-style triad a[i] = b[i] + s c[i] over arrays far larger than the caches, on 1 and 2
// threads (TBB, static blocks so each thread touches the pages it first wrote): the machine's
// sustainable memory bandwidth, the yardstick for the per-system byte counts in
// docs/benchmarks.md ("distance to the limit", issue 13). Counts 24 bytes per element (two reads,
// one write; a write-allocate would add 8 that the hardware may or may not spend).
// Run: build/bench/ryushi_bench_triad [MiB per array, default 256]
#include <tbb/global_control.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <vector>

int main(int argc, char** argv) {
  const std::size_t mib = argc > 1 ? std::strtoul(argv[1], nullptr, 10) : 256;
  const std::size_t n = mib * 1024 * 1024 / sizeof(double);
  std::vector<double> a(n), b(n), c(n);
  for (int threads : {1, 2}) {
    tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads);
    auto blocks = tbb::blocked_range<std::size_t>(0, n, n / (8 * threads) + 1);
    tbb::parallel_for(
        blocks,
        [&](auto r) {
          for (std::size_t i = r.begin(); i != r.end(); ++i) {
            b[i] = 1.0;
            c[i] = 2.0;
          }
        },
        tbb::static_partitioner());
    double best = 1e30;
    for (int rep = 0; rep < 10; ++rep) {
      auto t0 = std::chrono::steady_clock::now();
      tbb::parallel_for(
          blocks,
          [&](auto r) {
            for (std::size_t i = r.begin(); i != r.end(); ++i) a[i] = b[i] + 3.0 * c[i];
          },
          tbb::static_partitioner());
      best = std::min(best, std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
    }
    std::printf("triad, %d thread%s, 3 x %zu MiB: best of 10 %.2f ms, %.2f GB/s (24 bytes per element)\n",
                threads, threads > 1 ? "s" : "", mib, best * 1e3, 24.0 * n / best * 1e-9);
  }
  return a[n / 2] == 7.0 ? 0 : 1;  // uses the result (b + 3 c = 7)
}
