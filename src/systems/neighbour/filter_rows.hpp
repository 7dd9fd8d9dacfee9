#pragma once
// The Verlet filter's pass (filter_neighbour_list in neighbour_search.hpp) as a template that a
// system can run its own per-row work inside: `out` = the pairs of `candidates` within `radius`,
// row for row in the same order, and `row_done(i, r2)` runs right after row i is filtered, in
// the same task, while the row is in cache. With KeepR2, r2 points at the survivors' squared
// distances in the row's order (a scratch array of the task's, valid during the call); without,
// it is null. MPS's number density computes its weights there: one pass over the pairs at x*
// instead of a filter pass and a weight pass that both compute every distance.
#include <tbb/parallel_for.h>

#include <cstdint>
#include <span>
#include <type_traits>
#include <utility>
#include <vector>

#include "systems/neighbour/domain.hpp"
#include "systems/neighbour/neighbour_list.hpp"

namespace ryushi {

template <int D, bool KeepR2, class RowDone>
void filter_rows(const Domain<D>& domain, double radius, std::span<const Vec<D>> x,
                 const NeighbourList& candidates, NeighbourList& out, RowDone&& row_done) {
  const std::size_t N = candidates.size();
  const double radius2 = radius * radius;
  // One distance pass, no packing copy (which was half the filter's time and a second list in
  // memory): each parallel block writes its rows one after the other from the candidates' start
  // of its first row, so the rows are packed within a block and the list has a gap only between
  // blocks (NeighbourList::ends). (Rows left at the candidates' starts, with a gap after each,
  // made WCSPH's pair loops 5-10% slower.) A survivor is written before it is known to be one:
  // the slot is reused by the next candidate or the next row, and stays inside the block.
  out.indices.resize(candidates.indices.size());
  out.offsets.resize(N + 1);
  out.offsets[N] = candidates.offsets[N];
  out.ends.resize(N);
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
      std::uint32_t cursor = candidates.offsets[r.begin()];
      for (std::size_t i = r.begin(); i != r.end(); ++i) {
        const Vec<D> xi = pos[i];
        std::uint32_t* const dst = indices + cursor;
        const auto row = candidates.of(i);
        if constexpr (KeepR2)
          if (r2.size() < row.size()) r2.resize(row.size());
        double* const r2_dst = r2.data();
        std::uint32_t c = 0;
        for (auto j : row) {
          Vec<D> d;
          if constexpr (decltype(periodic_axes)::value)
            d = domain.displacement(xi, pos[j]);
          else
            d = xi - pos[j];
          const double s = d.squaredNorm();
          dst[c] = j;
          if constexpr (KeepR2) r2_dst[c] = s;
          c += s <= reach2;  // branch-free: which candidates survive is not predictable
        }
        out.offsets[i] = cursor;
        cursor += c;
        out.ends[i] = cursor;
        row_done(i, KeepR2 ? static_cast<const double*>(r2_dst) : nullptr);
      }
    });
  };
  if (domain.any_periodic())
    pass(std::true_type{});
  else
    pass(std::false_type{});
  out.radius = radius;
}

// `narrowed` (filtered from `list`) becomes the step's list, and `list`'s storage goes back to
// the filtering system, to be filtered into again next step without an allocation.
inline void adopt_narrowed(NeighbourList& list, NeighbourList& narrowed) {
  narrowed.builds = list.builds;
  narrowed.candidate_bytes = list.bytes();
  std::swap(list, narrowed);
}

}  // namespace ryushi
