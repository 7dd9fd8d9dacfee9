#pragma once
// The ISPH pressure rows' neighbour list: the full list without dry walls (kind wall, no
// unknown), which drop out of every stencil (isph_pressure_equation.hpp).
#include <tbb/parallel_for.h>

#include <cstdint>
#include <span>
#include <vector>

#include "ecs/component.hpp"
#include "systems/neighbour/neighbour_list.hpp"

namespace ryushi {

inline const NeighbourList& restrict_to_wetted(std::span<const std::int32_t> kind,
                                               std::span<const std::uint8_t> unknown,
                                               const NeighbourList& full, NeighbourList& out) {
  const std::size_t n = full.size();
  auto keeps = [&](std::size_t j) { return kind[j] != kWall || unknown[j]; };
  out.radius = full.radius;
  out.offsets.assign(n + 1, 0);
  out.ends.clear();  // packed
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n, 1024), [&](auto range) {
    for (std::size_t i = range.begin(); i != range.end(); ++i) {
      std::uint32_t c = 0;
      if (keeps(i))
        for (auto j : full.of(i)) c += keeps(j);
      out.offsets[i + 1] = c;
    }
  });
  for (std::size_t i = 0; i < n; ++i) out.offsets[i + 1] += out.offsets[i];
  out.indices.resize(out.offsets[n]);
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n, 1024), [&](auto range) {
    for (std::size_t i = range.begin(); i != range.end(); ++i) {
      if (!keeps(i)) continue;
      auto k = out.offsets[i];
      for (auto j : full.of(i))
        if (keeps(j)) out.indices[k++] = j;
    }
  });
  return out;
}

}  // namespace ryushi
