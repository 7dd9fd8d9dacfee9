#pragma once
// The Verlet list's candidates, two bytes each instead of four. The candidates are the bulk of
// the neighbour memory (3D WCSPH at the default skin: about 200 per fluid particle, within
// support + skin) and are only ever walked row by row, in order, by the filter. With the
// particles in cell order a row is a few runs of consecutive indices (one per stencil cell), so
// each candidate is stored as its difference from the one before it (the first from the row's
// own index): almost all fit in 16 bits; a jump that does not (to the next plane of cells, a
// periodic image) is an escape slot followed by the index in two halves.
#include <tbb/parallel_for.h>

#include <cstdint>
#include <vector>

namespace ryushi {

struct CandidateList {
  static constexpr std::int16_t kEscape = INT16_MIN;
  std::vector<std::uint32_t> offsets{0};  // row i is slots [offsets[i], offsets[i + 1])
  std::vector<std::int16_t> slots;
  std::size_t count = 0;  // candidates in all rows (each slot holds at most one)
  double radius = 0;

  std::size_t size() const { return offsets.size() - 1; }
  // An upper bound on row i's candidates.
  std::uint32_t row_bound(std::size_t i) const { return offsets[i + 1] - offsets[i]; }
  std::size_t bytes() const {
    return offsets.size() * sizeof(std::uint32_t) + slots.size() * sizeof(std::int16_t);
  }

  // f(j) for the candidates of row i, in the order they were stored.
  template <class F>
  void for_each(std::size_t i, F&& f) const {
    const std::int16_t* s = slots.data() + offsets[i];
    const std::int16_t* const end = slots.data() + offsets[i + 1];
    std::uint32_t j = static_cast<std::uint32_t>(i);
    while (s != end) {
      const std::int16_t d = *s++;
      if (d == kEscape) [[unlikely]] {
        j = static_cast<std::uint16_t>(s[0]) | std::uint32_t{static_cast<std::uint16_t>(s[1])} << 16;
        s += 2;
      } else {
        j += static_cast<std::uint32_t>(static_cast<std::int32_t>(d));  // modulo 2^32: j + d
      }
      f(j);
    }
  }

  // Encodes the rows row_of(i), i < N (each a span of indices), in place of what this held.
  template <class RowOf>
  void assign(std::size_t N, RowOf&& row_of) {
    offsets.assign(N + 1, 0);
    auto slots_of = [&](std::size_t i, std::int16_t* out) {
      std::uint32_t prev = static_cast<std::uint32_t>(i), n = 0;
      for (const std::uint32_t j : row_of(i)) {
        const std::int64_t d = std::int64_t{j} - std::int64_t{prev};
        if (d > kEscape && d <= INT16_MAX) {
          if (out) out[n] = static_cast<std::int16_t>(d);
          n += 1;
        } else {
          if (out) {
            out[n] = kEscape;
            out[n + 1] = static_cast<std::int16_t>(static_cast<std::uint16_t>(j & 0xffffu));
            out[n + 2] = static_cast<std::int16_t>(static_cast<std::uint16_t>(j >> 16));
          }
          n += 3;
        }
        prev = j;
      }
      return n;
    };
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, N, 4096), [&](auto r) {
      for (std::size_t i = r.begin(); i != r.end(); ++i) offsets[i + 1] = slots_of(i, nullptr);
    });
    count = 0;
    for (std::size_t i = 0; i < N; ++i) {
      count += row_of(i).size();
      offsets[i + 1] += offsets[i];
    }
    // The storage is kept from build to build (a fresh array's pages cost about 0.7 ms per MB to
    // fault in on the benchmark VM); one that must grow is replaced, not copied, with 10% spare.
    if (offsets[N] > slots.capacity()) {
      std::vector<std::int16_t>().swap(slots);
      slots.reserve(offsets[N] + offsets[N] / 10);
    }
    slots.resize(offsets[N]);
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, N, 4096), [&](auto r) {
      for (std::size_t i = r.begin(); i != r.end(); ++i) slots_of(i, slots.data() + offsets[i]);
    });
  }
};

}  // namespace ryushi
