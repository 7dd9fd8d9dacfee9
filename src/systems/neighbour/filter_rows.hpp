#pragma once
// Filters a list's rows to the pairs within a radius, row for row in the same order.
// - filter_rows: a narrowing (the list of a step to the kernel's support at x*): `out` gets the
//   input's slots (`out` may be `in` itself: the narrowing then needs no second list, which in
//   2D ISPH at 255k particles took 125 of 1,054 bytes per particle), a system can run its own
//   per-row work inside (`row_done(i, r2)` right after row i is filtered, in the same task,
//   while the row is in cache; with KeepR2, r2 points at the survivors' squared distances in the
//   row's order, a scratch array of the task's valid during the call; without, it is null). MPS's
//   number density computes its weights there: one pass over the pairs at x* instead of a filter
//   pass and a weight pass that both compute every distance.
// - filter_row: one row, the loop both this and the Verlet filter (filter_candidates in
//   neighbour_search.hpp) run.
#include <tbb/parallel_for.h>

#include <cstdint>
#include <span>
#include <type_traits>
#include <utility>
#include <vector>

#include "systems/neighbour/domain.hpp"
#include "systems/neighbour/neighbour_list.hpp"

namespace ryushi {

// Writes the candidates that `for_each_candidate(f)` gives to dst and keeps those within
// sqrt(reach2) of xi (and their squared distances in r2 with KeepR2); returns how many. Every
// candidate is written before it is known to be kept, and the count advances by the outcome:
// which candidates survive is not predictable, and a branch on it mispredicts.
template <int D, bool KeepR2, bool Periodic, class ForEachCandidate>
inline std::uint32_t filter_row(const Domain<D>& domain, const Vec<D>* pos, const Vec<D>& xi, double reach2,
                                ForEachCandidate&& for_each_candidate, std::uint32_t* dst, double* r2) {
  std::uint32_t c = 0;
  for_each_candidate([&](std::uint32_t j) {
    Vec<D> d;
    if constexpr (Periodic)
      d = domain.displacement(xi, pos[j]);
    else
      d = xi - pos[j];
    const double s = d.squaredNorm();
    dst[c] = j;
    if constexpr (KeepR2) r2[c] = s;
    c += s <= reach2;
  });
  return c;
}

template <int D, bool KeepR2, class RowDone>
void filter_rows(const Domain<D>& domain, double radius, std::span<const Vec<D>> x, const NeighbourList& in,
                 NeighbourList& out, RowDone&& row_done) {
  const std::size_t N = in.size();
  const double radius2 = radius * radius;
  // In place, each row is read before anything is written over it: a row is written at or
  // before where it lies (below), and its bounds are read before they are overwritten. A packed
  // input gets its row ends first, since its offsets are overwritten row by row.
  if (&in == &out && out.ends.empty()) out.ends.assign(out.offsets.begin() + 1, out.offsets.end());
  // One distance pass, no packing copy: each row is written where the input's rows lie, packed
  // one after the other within each run of input rows that follow each other in memory (a
  // parallel block's rows, or a run inside one), so `out` has the input's slots (a system can
  // index per-pair arrays by them, MPS's weights) and gaps only where the input has them
  // (NeighbourList::ends). A row never outgrows its input row, so the packed run never passes
  // the input run's end, and a task writes only where its own rows' input lies.
  if (out.indices.size() != in.indices.size())
    std::vector<std::uint32_t>(in.indices.size()).swap(out.indices);
  out.offsets.resize(N + 1);
  out.offsets[N] = in.offsets[N];
  out.ends.resize(N);  // in place: already N long
  auto pass = [&](auto periodic_axes) {
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, N, 2048), [&](auto r) {
      // Locals, not the captured references: the stores into the list may alias anything the
      // compiler cannot see, and it would reload each reference after every store.
      const double reach2 = radius2;
      const Vec<D>* const pos = x.data();
      std::uint32_t* const indices = out.indices.data();
      // The survivors' squared distances stay in this small array (in L1), not in an array of
      // the candidates' size: writing one double per candidate to memory cost more than the
      // distances (3D MPS at 1M particles).
      std::vector<double> r2;
      std::uint32_t cursor = 0, previous_end = 0;
      for (std::size_t i = r.begin(); i != r.end(); ++i) {
        const std::uint32_t begin = in.offsets[i], end = in.end(i);
        if (i == r.begin() || begin != previous_end) cursor = begin;  // a new run
        previous_end = end;
        const std::span<const std::uint32_t> row(in.indices.data() + begin, end - begin);
        if constexpr (KeepR2)
          if (r2.size() < row.size()) r2.resize(row.size());
        const std::uint32_t c = filter_row<D, KeepR2, decltype(periodic_axes)::value>(
            domain, pos, pos[i], reach2,
            [&](auto&& f) {
              for (auto j : row) f(j);
            },
            indices + cursor, r2.data());
        out.offsets[i] = cursor;
        cursor += c;
        out.ends[i] = cursor;
        row_done(i, KeepR2 ? static_cast<const double*>(r2.data()) : nullptr);
      }
    });
  };
  if (domain.any_periodic())
    pass(std::true_type{});
  else
    pass(std::false_type{});
  out.radius = radius;
}

}  // namespace ryushi
