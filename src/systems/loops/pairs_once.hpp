#pragma once
// Each pair once: a pair loop that visits (i, j) only from its lower index and accumulates on
// both sides does half the distance and kernel work of one in which every particle gathers all
// its pairs. The writes to j > i make it a scatter; with the particles in cell order, a
// particle's neighbours above it lie within a window W of its index, so blocks of at least W
// consecutive particles run in two phases (even blocks, then odd ones) never write to the same
// particle at once. The sums depend on the block size, never on the thread count.
#include <tbb/parallel_for.h>
#include <tbb/parallel_reduce.h>

#include <algorithm>
#include <cstdint>

#include "systems/neighbour/neighbour_list.hpp"

namespace ryushi {

// -1: use blocks when there are at least four of them; 0: never (gather every pair); 1: always
// (a single block runs serially). Tests force both ways.
enum class PairsOnce : int { Auto = -1, Never = 0, Always = 1 };

// The block size for the first `rows` rows of `nl` (the owned ones; pair_loop.hpp), or 0 to
// gather every pair instead: fewer than four blocks (a periodic axis puts neighbours a box apart
// in index; the scene's first step, before the first reorder, has walls a block apart from the
// fluid beside them) would leave cores idle.
inline std::size_t pairs_once_block_size(const NeighbourList& nl, PairsOnce mode, std::size_t rows) {
  const std::size_t N = std::min(rows, nl.size());
  if (mode == PairsOnce::Never || N == 0) return 0;
  const std::size_t window = tbb::parallel_reduce(
      tbb::blocked_range<std::size_t>(0, N, 4096), std::size_t{0},
      [&](auto r, std::size_t w) {
        for (std::size_t i = r.begin(); i != r.end(); ++i) {
          // Only the scatter to written rows needs the window: ghost rows (from `rows` on) are
          // never written.
          auto nb = nl.of(i);
          auto end = N == nl.size() ? nb.end()
                                    : std::lower_bound(nb.begin(), nb.end(), static_cast<std::uint32_t>(N));
          if (end != nb.begin() && *(end - 1) > i) w = std::max<std::size_t>(w, *(end - 1) - i);
        }
        return w;
      },
      [](std::size_t a, std::size_t b) { return std::max(a, b); });
  const std::size_t block = std::max<std::size_t>(window, 256);
  if (mode == PairsOnce::Always) return std::min(block, N);
  return N / block >= 4 ? block : 0;
}

// Runs body(lo, hi) over [0, N) in blocks of `block`, even blocks in parallel, then odd ones.
template <class Body>
void for_each_block_in_two_phases(std::size_t N, std::size_t block, Body&& body) {
  const std::size_t blocks = (N + block - 1) / block;
  for (std::size_t phase = 0; phase < 2; ++phase) {
    const std::size_t count = (blocks - phase + 1) / 2;
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, count, 1), [&](auto r) {
      for (std::size_t k = r.begin(); k != r.end(); ++k) {
        const std::size_t b = 2 * k + phase;
        body(b * block, std::min(N, (b + 1) * block));
      }
    });
  }
}

// The neighbours of i above it (lists are sorted by index).
inline std::span<const std::uint32_t> neighbours_above(const NeighbourList& nl, std::size_t i) {
  auto nb = nl.of(i);
  auto first = std::upper_bound(nb.begin(), nb.end(), static_cast<std::uint32_t>(i));
  return {first, nb.end()};
}

}  // namespace ryushi
